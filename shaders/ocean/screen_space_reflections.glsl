// Screen-space reflections of the terrain in the sea (Michelic §6: "either atmosphere
// reflections or screen-space reflections of the terrain"; here both): the reflected ray is
// followed across the image against the copy of the G-buffer depth taken before the ocean
// pass; where it passes behind the terrain the terrain's surface radiance there (the copy of
// the surface light's target: no air in it) is what the sea reflects. Only what is on screen
// can be found, so the result comes with a confidence in [0, 1] that the terrain reflection
// pass blends the sky-and-cloud reflection under: it fades out towards the image's edges, where the ray may
// pass behind a ridge rather than into it (the depth buffer has no thickness), and for rays
// that turn towards the camera. Rays that leave the screen, or climb above the highest
// mountain, find nothing (confidence 0): the sky's reflection alone, as before.
//
// Rays from the open sea, where the continents map's slope bound keeps all ground within their
// reach below sea level (terrainMayBeReflected), are not searched at all: the ocean pass lists
// the others (it leaves the sky it reflected there), and the terrain reflection pass (ocean/
// terrain_reflection.comp) searches those alone. A search in the ocean's own program cost every
// pixel, searched or not, on a software renderer, which runs an if's code for every pixel,
// masked (from orbit: a third of the ocean's cost).
//
// The march is in screen space: a ray P(t) = origin + t dir projects onto the segment from
// the origin's image (u = 0) to the vanishing point of dir (u = 1), and with w the depth
// along the camera's forward axis (w0 at the origin, wd of dir)
//     t(u) = (w0 / wd) u / (1 - u),   depth(u) = w0 / (1 - u),
// so equal steps in u are equal steps on screen (no pixel is skipped near the origin and
// none sampled twice far away) and each step's depth is exact. SSR_STEPS steps (jittered
// per pixel so that a missed thin feature is noise, not bands; the last one always at the
// segment's end: a mountain seen across water lies near the vanishing point, all of it in
// the last step, and a jittered last step fell short of it in most pixels, which left its
// reflection as speckle), then SSR_REFINEMENTS
// bisections of the step where the ray went behind the depth buffer: bounded cost on
// llvmpipe whatever the scene.
//
// Needs common/frame_uniforms.glsl, ocean/ocean_block.glsl, terrain/terrain_block.glsl and
// terrain/terrain_shadow.glsl (with the continents map, uContinents).

#include "ocean/terrain_reflection_reach.glsl"

const int SSR_STEPS = 20;
const int SSR_REFINEMENTS = 5;
const float SSR_EDGE_FADE_NDC = 0.15;    // hits this close to the image's edge fade out (NDC units)
const float SSR_MIN_THICKNESS = 0.02;    // relative depth behind the depth buffer still taken as inside
const float SSR_MIN_FORWARD = 0.02;      // cos(dir, forward) below which the search fades out...
const float SSR_FULL_FORWARD = 0.1;      // ...and above which it is fully on

struct ScreenReflection {
    vec3 radiance;     // the terrain's surface radiance where the ray met it (no air)
    float distance;    // m along the ray to there
    float confidence;  // [0, 1]: how far to trust it over the sky's reflection
};

vec4 clipFromWorldPoint(vec3 pointFromCamera) {
    return frame.clipFromView * vec4(mat3(frame.viewFromWorld) * pointFromCamera, 1.0);
}
vec4 clipFromWorldDirection(vec3 dir) { return frame.clipFromView * vec4(mat3(frame.viewFromWorld) * dir, 0.0); }

// How far the reflected ray from the sea at `up`, `heightM` above sea level, can still meet the
// land near it, m (terrain/terrain_shadow.glsl's terrainReachBelowLandKm: below the highest the
// land within the continents' slope bound may rise, not the highest mountain; 0 where no land
// lies within it).
float reachBelowLand(vec3 up, float heightM, float sinRise) {
    return M_PER_KM * terrainReachBelowLandKm(up, heightM, sinRise, 1.0e30, frame.planetRadius / M_PER_KM,
                                              ocean.continentLipschitz, ocean.continentSampleSlackRad,
                                              terrainShape, uContinents);
}

// The fraction u of the segment where it leaves the image ([-1, 1]^2 in NDC).
float screenExit(vec2 ndcStart, vec2 ndcEnd) {
    vec2 delta = ndcEnd - ndcStart;
    vec2 safe = mix(vec2(1e-9), delta, greaterThan(abs(delta), vec2(1e-9)));  // still: exits far away
    vec2 exits = (sign(safe) - ndcStart) / safe;
    return clamp(min(exits.x, exits.y), 0.0, 1.0);
}

// A per-pixel offset in [0, 1) (interleaved gradient noise, Jimenez 2014): spreads the
// steps' positions so that features thinner than a step are found by some pixels, not lost
// in bands.
float stepJitter(ivec2 pixel) { return fract(52.9829189 * fract(dot(vec2(pixel), vec2(0.06711056, 0.00583715)))); }

ivec2 pixelAt(vec2 ndc) {
    return clamp(ivec2((ndc * 0.5 + 0.5) * frame.viewportSize), ivec2(0), ivec2(frame.viewportSize) - 1);
}

// How far the ray at u stands behind what the depth copy holds there, relative to its own
// depth (> 0: behind; the sky, depth 0, is never in front of it). Reversed-Z: depth = near / w,
// which is affine on screen over a plane, so the copy is read filtered at the ray's own point,
// not at the centre of its pixel: at grazing views one pixel spans hundreds of metres of
// depth, and against its centre a ray rising from shallow water was found "behind" the sea
// floor under it or not by where in the pixel its step fell (a checker of dark dots along
// the shore).
float behindDepthBuffer(sampler2D depthCopy, vec2 ndc0, vec2 ndcEnd, float w0, float u) {
    vec2 uv = clamp(mix(ndc0, ndcEnd, u) * 0.5 + 0.5, 0.5 * frame.inverseViewportSize,
                    1.0 - 0.5 * frame.inverseViewportSize);
    float sceneDepth = textureLod(depthCopy, uv, 0.0).r;
    float rayDepth = frame.nearPlane * (1.0 - u) / w0;
    return sceneDepth / max(rayDepth, 1e-30) - 1.0;  // w_ray / w_scene - 1
}

// The search along the reflected ray from `origin` (m from the camera, world axes), which stays
// below the highest mountain for `reach` m: the terrain it meets on screen, or confidence 0.
ScreenReflection searchScreenReflection(vec3 origin, vec3 dir, float reach, ivec2 pixel, sampler2D depthCopy,
                                        sampler2D radianceCopy) {
    ScreenReflection none = ScreenReflection(vec3(0.0), 0.0, 0.0);
    vec4 clip0 = clipFromWorldPoint(origin);
    vec4 clipDir = clipFromWorldDirection(dir);
    float w0 = clip0.w, wd = clipDir.w;
    // A ray turning towards the camera runs off the image's bottom or behind it at once.
    float forwardFade = smoothstep(SSR_MIN_FORWARD, SSR_FULL_FORWARD, wd);
    if (forwardFade <= 0.0 || w0 <= 0.0) return none;
    float scale = w0 / wd;  // t(u) = scale u / (1 - u)
    vec2 ndc0 = clip0.xy / w0, ndcEnd = clipDir.xy / wd;
    float uEnd = min(reach / (reach + scale), screenExit(ndc0, ndcEnd));
    if (uEnd <= 0.0) return none;

    // (As many steps as the segment spans pixels, at least one, saved 2 ms at `orbit` but lost the
    // land's reflection in pixels along the horizon at `sunset`: the reference image's mean moved by
    // 1.6 %, some of its pixels by 100x. Not kept.)
    float jitter = stepJitter(pixel);
    float uFront = 0.0, uBehind = -1.0;
    for (int i = 0; i < SSR_STEPS; ++i) {
        float u = i + 1 < SSR_STEPS ? uEnd * (float(i) + 1.0 - jitter) / float(SSR_STEPS) : uEnd;
        if (behindDepthBuffer(depthCopy, ndc0, ndcEnd, w0, u) > 0.0) {
            uBehind = u;
            break;
        }
        uFront = u;
    }
    if (uBehind < 0.0) return none;
    for (int i = 0; i < (uBehind >= 0.0 ? SSR_REFINEMENTS : 0); ++i) {
        float u = 0.5 * (uFront + uBehind);
        if (behindDepthBuffer(depthCopy, ndc0, ndcEnd, w0, u) > 0.0) uBehind = u;
        else uFront = u;
    }
    // Into the terrain, the ray ends up just behind the surface: by no more than the last
    // interval's own depth change (or a pixel's worth of a steep face). Far behind, it went
    // behind a ridge and may come out again: the depth buffer cannot say, so it fades.
    ScreenReflection hit = none;
    for (int i = 0; i < (uBehind >= 0.0 ? 1 : 0); ++i) {  // a loop, not an if: skipped where no pixel hit
        float behind = behindDepthBuffer(depthCopy, ndc0, ndcEnd, w0, uBehind);
        float thickness = max(2.0 * (uBehind - uFront) / (1.0 - uBehind), SSR_MIN_THICKNESS);
        float inside = 1.0 - smoothstep(thickness, 2.0 * thickness, behind);
        vec2 ndcHit = mix(ndc0, ndcEnd, uBehind);
        float edge = smoothstep(0.0, SSR_EDGE_FADE_NDC, 1.0 - max(abs(ndcHit.x), abs(ndcHit.y)));
        hit.radiance = texelFetch(radianceCopy, pixelAt(ndcHit), 0).rgb;
        hit.distance = scale * uBehind / (1.0 - uBehind);
        hit.confidence = forwardFade * inside * edge;
    }
    return hit;
}

// The reflected terrain as seen from the sea: its radiance through the air between (the
// reflected path crosses it as the camera's own view does: transmittance and in-scattering
// over the hit distance, Elek Eq. 19-20; clouds in between are not marched).
vec3 reflectedTerrainRadiance(ScreenReflection hit, vec3 pointKm, vec3 dir, vec3 sun) {
    vec3 transmittance;
    vec3 inscatter = SkyRadianceToPoint(pointKm, dir, hit.distance / M_PER_KM, sun, transmittance);
    return transmittance * hit.radiance + inscatter;
}
