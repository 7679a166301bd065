// The temporal reconstruction (pass "sky temporal"): the full frame's T and S (what lies
// between the camera and the surface, render/sky.frag) from this frame's reduced-rate samples
// (render/sky_sparse.frag: one pixel of each 4x4 block) and the previous frame's result,
// then the composite L = T R_G + S (or S + T x sun disc) at every pixel.
//
// For each pixel:
//  - this frame's samples of the 3x3 blocks around it, each weighted by its distance in the
//    image (a tent four pixels wide: bilinear between samples) and by how alike its surface
//    distance is (sky only from sky, a near hill only from that hill: no halo of sky around a
//    mountain, no clouds bleeding over a hill): the spatial estimate, and the range (box) of
//    the samples that see the same surface, widened by its own size (the samples are four
//    pixels apart: what lies between them may reach past their range);
//  - the history: the pixel's point (the clouds' opacity-weighted distance where they
//    dominate, moved back by the wind; else the surface point; else the direction) projected
//    into the previous frame (its camera relative to this one formed in double:
//    frame.cameraFromPrevious), read with Catmull-Rom where the 4x4 texels around show the
//    same surface, bilinear over those that do elsewhere, and rejected where none does (a
//    disocclusion);
//  - when anything moved (the camera, the clock: frame.stillSincePrevious 0), the history is
//    first scaled by how much brighter the nearest samples found the scene than their history
//    (the light that changed: a camera climbing out of the clouds' shade), then clamped to
//    the box where the point moved or the samples around changed (a cloud cannot be dragged where
//    this frame's samples say there is none, a sky cannot stay blue where they say it is black),
//    a moving pixel takes half of the spatial estimate, and the traced pixel takes its new
//    sample; when nothing moved, nothing is clamped and the traced pixel adds its sample to a
//    running mean of up to 16 (each visit with another jitter), so a still frame converges.
//  - the other pixels keep the history, or the spatial estimate where there is none;
//  - in a frame where anything moved, the pixels none of this can rebuild are listed (the end
//    of main; render/pixel_list.glsl) and marched again at full rate by
//    render/sky_refine.comp.
// The history is the frame's only state; it is dropped on a jump, a resize or a parameter
// change (frame.historyValid 0), and then this frame is the spatial estimate alone.
// STILL_FRAME_UNJITTERED (src/render/renderer.cpp's mode 2): the still-frame program for a frame
// whose sub-pixel jitter stood too (below).
#ifdef STILL_FRAME_UNJITTERED
#define STILL_FRAME 1
#endif
#include "common/frame_uniforms.glsl"
// LIGHT_SHAFTS_TERRAIN (the terrain's shadows in the air) comes from the program builder, 1 only
// when the preset asks for light shafts (src/render/atmosphere_program.h).
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/water.glsl"
#include "render/sky_air.glsl"
#include "render/sparse_pattern.glsl"
#include "render/sky_history.glsl"
#include "render/sky_spatial.glsl"
#define PIXEL_LIST_BINDING BUFFER_SKY_REFINE
#include "render/pixel_list.glsl"

in vec2 vNdc;
// The stencil's test before the shader, where the pass splits its pixels by it
// (src/render/renderer.cpp, drawSkyTemporalSplit): the pixel list's writes would otherwise hold
// it back. (No depth is written, and nothing is discarded.)
layout(early_fragment_tests) in;
layout(binding = UNIT_SURFACE_RADIANCE) uniform sampler2D surfaceRadiance;
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;

layout(location = 0) out vec4 outRadiance;
layout(location = 1) out uvec4 outSkyMedium;  // T, S, samples in the history

// The history's gain in a moving frame: the nearest samples' ratios of their radiance to the
// history at their pixel (render/sky_sparse.frag), averaged in the logarithm, where the ratio is
// within this relative change (larger ones are a cloud's edge or parallax, not light that
// changed: those pixels are marched again). Along takeoff at 160x90 the cloud-filled frames
// brighten by a few per cent a frame as the camera climbs through the deck, and the history
// between the samples lagged behind (frames 6-21 s: mean error 0.84 % on average without it,
// 0.39 % with it; worst frame 2.35 % and 0.93 %).
const float GAIN_LIMIT = 0.3;
const float BOX_MARGIN = 0.25;           // the box widened by this share of its size on each side
// Where the point moved by more than half a pixel, half of the spatial estimate goes into the
// history each frame: a moving pixel's history has been resampled and clamped many times over
// until its next visit, and a cloud's edge left behind by a box that spans cloud and sky fades
// in a few frames instead of sixteen (measured along the twilight path, frames 200-250 at
// 320x180: mean error 15.5 % without, 9.9 % with; a quarter: 10.7 %, three quarters: 9.8 %).
const float SPATIAL_SHARE_MOVING = 0.5;
// A pixel whose history reads across a line or an edge (the 2x2 it is read from spans more than
// this share of its radiance) is marched again in a moving frame: the line moves with the scene
// only where the scene moved rigidly (along takeoff at 160x90, with the history checked at 0.1 on
// all 3x3 samples: 15 frames with the error's 99th percentile over 15 % against 138 without it,
// for 3 % more pixels marched again). Lowered from 0.25 with the gain above: over 6-21 s of the
// path, the frames with a 99th percentile of 15 % or more (the deck's textured tops from just
// above, read from a history resampled every frame) went from 9 to none, 29 % to 31 % marched
// again.
const float REFINE_HISTORY_CONTRAST = 0.15;
// Where only the clock ran, a sample marks the pixels around it for the full-rate march at this
// times render.temporal_refine_error (above). `cumulus_wind` (the camera still under the cumulus
// for 4 s, 121 frames) at 480x270: before (x1, the gain below applied there too) / now (x3, no
// gain there): 7.7 % / 0.7 % of the pixels marched again a frame, the sky passes 0.40 / 0.16 of
// the full rate, the mean error 0.51 / 0.64 % on average, its 99th percentile 3.6 / 6.9 %
// (median frame); the worst frame's difference is noise at the jitter's scale in the clouds, no
// trail (a pixel marched again is the reference's own march, noise and all, so marking more
// lowers the error against it). A running mean of up to 4, 8 or 16 samples there instead of the
// single sample lagged behind the drifting clouds (mean 0.84-0.89 %).
const float CLOCK_REFINE_SCALE = 3.0;

// The traced pixel's new sample added to its history's running mean (of `samples` so far).
void addSample(inout SkySample result, inout float samples, SkySample fresh) {
    float alpha = 1.0 / (samples + 1.0);
    result.inscatter = mix(result.inscatter, fresh.inscatter, alpha);
    result.transmittance = mix(result.transmittance, fresh.transmittance, alpha);
    samples += 1.0;
}

// The pixel's radiance through the air from its T and S, and T, S and samples for the history.
void writeSky(vec3 dir, vec3 surface, float distance, SkySample result, float samples) {
    outRadiance = vec4(min(throughAir(dir, surface, distance, result.transmittance, result.inscatter),
                           vec3(MAX_HDR_RADIANCE)), 1.0);
    outSkyMedium = packSkyMedium(result, min(samples, MAX_HISTORY_SAMPLES));
}

#ifdef STILL_FRAME
// A frame where the camera and the sun stood and nothing else moved at the pixels' scale (the
// clock stopped, or it moved the clouds far under a pixel, from high above them:
// frame.stillSincePrevious and viewStillSincePrevious, with a history, src/render/frame_uniforms.h;
// src/render/renderer.cpp picks this variant), the anti-aliasing's sub-pixel jitter moving or not.
// Then every pixel's history is its own texel (render/sky_history.glsl, historyJitterShift) and
// nothing is clamped or marched again, so the general reconstruction below comes down to the history,
// and at the traced pixel its running mean with the new sample; and where a pixel's surface
// changed (an edge that moved with the jitter), to its own new sample or its samples' spatial
// estimate, which render/sky_refine.comp's STILL_FRAME program forms for the pixels listed here
// (render/sky_spatial.glsl, surfaceChangedEstimate): this variant and that are the general
// program alone, to the bit. Programs, not branches: a software renderer runs every side of
// every branch, and the samples' loop and the history's filters were four fifths of the pass
// (orbit, 480x270, llvmpipe: 12.6 -> 2.7 ms); the samples' loop for the pixels whose surface
// changed, behind an if here, still cost half of this program (1280x720: orbit 41 -> 20 ms,
// space 26 -> 15 ms without it; docs/PERFORMANCE.md, fifteenth session).
void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 dir = worldRayFromNdc(vNdc);
    vec3 surface = texelFetch(surfaceRadiance, pixel, 0).rgb;
    float distance = texelFetch(surfaceDistance, pixel, 0).r;
    if (distance <= 0.0 && rayMissesTheAir(dir)) {  // space: nothing to march or rebuild
        outRadiance = vec4(spaceRadiance(gl_FragCoord.xy), 1.0);
        outSkyMedium = spaceSkyMedium();
        return;
    }
    float samples;
    SkySample result = unpackSkyMedium(texelFetch(historySkyMedium, pixel, 0), samples);
    samples = floor(samples + 0.5);
    ivec2 block = pixel / SPARSE_BLOCK;
#ifdef STILL_FRAME_UNJITTERED
    // The jitter stood as well (no anti-aliasing, or a still): every pixel's ray is its
    // history's, so its surface is too and none is listed (the general program lists none
    // either); the test left out, the program is the same to the bit (orbit, 1280x720: 20 -> 17 ms).
    const bool surfaceChanged = false;
#else
    float expected = previousSurfaceDistance(dir, distance);  // as readHistory is asked (the camera stood, to a millimetre)
    // Another surface than the history's at this pixel (under the anti-aliasing's jitter, an edge
    // moved across it): no history, as in the general program; render/sky_refine.comp writes it
    // over what this leaves.
    bool surfaceChanged = distanceSimilarity(expected, texelFetch(historySurfaceDistance, pixel, 0).r) <= 0.05;
    if (surfaceChanged) listPixel(pixel);
#endif
    if (!surfaceChanged && sparseTracedPixel(block) == pixel)
        addSample(result, samples,
                  SkySample(texelFetch(sparseInscatter, block, 0).rgb, texelFetch(sparseTransmittance, block, 0).rgb));
    writeSky(dir, surface, distance, result, samples);
}
#else
void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 dir = worldRayFromNdc(vNdc);
    vec3 surface = texelFetch(surfaceRadiance, pixel, 0).rgb;
    float distance = texelFetch(surfaceDistance, pixel, 0).r;
    if (distance <= 0.0 && rayMissesTheAir(dir)) {  // space: nothing to march or rebuild
        outRadiance = vec4(spaceRadiance(gl_FragCoord.xy), 1.0);
        outSkyMedium = spaceSkyMedium();
        return;
    }

    vec3 behind = behindTheAir(dir, surface, distance);
    // This frame's samples around the pixel.
    ivec2 block = pixel / SPARSE_BLOCK;
    SpatialSum around = noSamples();
    float reprojectionKm = 0.0;
    bool cloudy = false;  // the clouds dominate the pixel: it moves with the wind
    bool traced = false;
    SkySample fresh;
    float boxSamples = 0.0;  // samples in the box
    float disagreement = 0.0;  // their summed relative error of the history
    vec3 loS = vec3(1.0e30), hiS = vec3(-1.0e30), loT = vec3(1.0e30), hiT = vec3(-1.0e30);
    float historyError = 0.0;  // the largest error the history had at the nearest samples
    float gainLog = 0.0, gainWeight = 0.0;  // the nearest samples' log(now / history), weighted
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            BlockSample a = blockSample(block, ivec2(dx, dy), pixel);
            vec4 s = a.inscatter, t = a.transmittance;
            SkySample here = SkySample(s.rgb, t.rgb);
            float e = a.distanceError.y;  // (now - then) / max(now, then)
            float alike = distanceSimilarity(distance, a.distanceError.x);
            vec2 offset = a.offset;
            float tent = sampleTent(offset);
            if (addSpatialSample(around, here, alike, offset)) {  // the best match's point
                reprojectionKm = s.a;
                cloudy = t.a > CLOUDY_OPACITY;
            }
            if (offset == vec2(0.0)) {  // the traced pixel itself
                traced = true;
                fresh = here;
            }
            if (alike > 0.1) {
                boxSamples += 1.0;
                disagreement += abs(e);  // how far the sample is from what the history foresaw
                loS = min(loS, here.inscatter);
                hiS = max(hiS, here.inscatter);
                loT = min(loT, here.transmittance);
                hiT = max(hiT, here.transmittance);
                if (tent > 0.0) {
                    historyError = max(historyError, abs(e));
                    if (abs(e) < GAIN_LIMIT) {
                        gainLog += tent * alike * log(e >= 0.0 ? 1.0 / (1.0 - e) : 1.0 + e);
                        gainWeight += tent * alike;
                    }
                }
            }
        }
    }
    SkySample spatial = spatialEstimate(around);
    // The samples are four pixels apart: what lies between them may reach past their range.
    vec3 marginS = BOX_MARGIN * (hiS - loS) + 0.01 * hiS, marginT = BOX_MARGIN * (hiT - loT) + 0.01 * hiT;
    loS -= marginS;
    hiS += marginS;
    loT -= marginT;
    hiT += marginT;

    // The history at this pixel's point in the previous frame: a cloud moved with the wind.
    SkySample history = SkySample(vec3(0.0), vec3(0.0));
    float samples = 0.0;
    float historyWeight = 0.0;
    float motion = 0.0;  // pixels the point moved since the previous frame
    float historyContrast = 0.0;
    if (frame.historyValid > 0.5) {
        vec2 position = previousPixel(dir, reprojectionKm, cloudy);
        // Where the history's texels lie off the pixels by the anti-aliasing's sub-pixel jitter (a
        // moving camera: render/sky_history.glsl), that is no motion of the scene, which clamps the
        // history and mixes in the spatial estimate (counted as motion, every pixel took half of
        // the spatial estimate each frame in the explorer).
        motion = length(position - (vec2(pixel) + 0.5) - historyJitterShift());
        readHistory(position, previousSurfaceDistance(dir, distance), behind, history, samples, historyWeight,
                    historyContrast);
    }
    bool reprojected = historyWeight > 0.05;
    float moving = 1.0 - frame.stillSincePrevious;
    // Only the clock ran (the camera and the sun stayed: the explorer with its clock on, its
    // anti-aliasing's jitter moving or not).
    bool clockOnly = frame.viewStillSincePrevious > 0.5;
    SkySample result;
    if (reprojected) {
        // Clamped where the point moved by more than a fraction of a pixel, or where the samples
        // around changed by more than their noise (the sky brightening as the camera climbs, a
        // cloud's light as the sun moves: what a reprojection cannot follow); not where neither
        // happened (a thin feature the samples miss, the limb's glow from orbit, would be clamped
        // away), and only by a box of three samples or more (one or two say little).
        float changed = smoothstep(0.03, 0.1, disagreement / max(boxSamples, 1.0));
        float clampAmount = moving * max(smoothstep(0.05, 0.5, motion), changed) * smoothstep(1.5, 3.5, boxSamples);
        // Not where only the clock ran: the sun stayed, so the light did not change, and the
        // nearest samples' ratios are their own jitter's noise, which the gain put into every
        // pixel between them, the clear sky between the clouds too (cumulus_wind at 160x90:
        // mean error 0.62 % with it, 0.41 % without, the same pixels marched again).
        if (moving > 0.0 && gainWeight > 0.0 && !clockOnly) {  // L = T R_G + S scaled by the gain, through S
            // Not T x the sun's disc: a per cent of the disc added to S would stay in the history
            // as a glare after the disc moved on.
            float gain = exp(gainLog / gainWeight);
            vec3 radiance = history.transmittance * (distance > 0.0 ? surface : vec3(0.0)) + history.inscatter;
            history.inscatter = max(history.inscatter + (gain - 1.0) * radiance, vec3(0.0));
        }
        history.inscatter = mix(history.inscatter, clamp(history.inscatter, loS, hiS), clampAmount);
        history.transmittance = mix(history.transmittance, clamp(history.transmittance, loT, hiT), clampAmount);
        samples = min(floor(samples + 0.5), mix(MAX_HISTORY_SAMPLES, 0.0, moving));
        result = history;
        float toSpatial = SPATIAL_SHARE_MOVING * moving * smoothstep(0.05, 0.5, motion);
        result.inscatter = mix(result.inscatter, spatial.inscatter, toSpatial);
        result.transmittance = mix(result.transmittance, spatial.transmittance, toSpatial);
        if (traced) addSample(result, samples, fresh);
    } else if (traced) {
        result = fresh;
        samples = 1.0;
    } else {
        result = spatial;
        samples = 0.0;
    }

    writeSky(dir, surface, distance, result, samples);

    // Where anything moved, the pixels this cannot rebuild are marched again at full rate
    // (render/sky_refine.comp): nothing to reproject, or too few samples of its own surface
    // around; an edge between surfaces, or surface and sky, at the pixel (what lies along it
    // changes as it moves: the sky just above the horizon, a grazing ray past a ridge; a band
    // one pixel tall that samples four apart cannot see); a history read across a line or an
    // edge; or a nearest sample where the history was off by more than
    // render.temporal_refine_error (render/sky_sparse.frag checks it: parallax between layers of
    // cloud, a grazing ray's point sample, light that changed).
    // Where only the clock ran (the camera and the sun stayed: the explorer with its clock on),
    // nothing moved but the clouds, with the wind, a small fraction of a pixel a frame from most
    // views: an edge or a line stays where it was, and only the samples' errors decide. Marked as
    // in any moving frame, the edges and lines of a cumulus field were 35 % of the pixels (a still
    // camera under the cumulus at 160x90 over 4 s: the sky passes cost 1.01 of the full rate,
    // and 0.37 with this; the mean error 0.29 % and 0.62 %, as a still camera's converges to).
    // Under the anti-aliasing's moving jitter an edge between surfaces moves by a fraction of a
    // pixel, and a pixel that sees another surface than before finds no history of it (not
    // reprojected: marched again).
    // And there a sample's error is mostly the march's jitter's noise (its pixel's history is that
    // pixel's own single sample of 16 frames before, marched with another start; nothing else
    // changed but a fraction of a pixel of cloud, and under the anti-aliasing the sample's place
    // in the pixel), so it marks at CLOCK_REFINE_SCALE times the error (tuned without the
    // anti-aliasing; with it, see tests/test_temporal.cpp, WithTheExplorersAntiAliasing...).
    bool edge = false;
    if (!clockOnly) {
        for (int i = 0; i < 4; ++i) {
            ivec2 n = clamp(pixel + ivec2(i == 0 ? 1 : i == 1 ? -1 : 0, i == 2 ? 1 : i == 3 ? -1 : 0), ivec2(0),
                            ivec2(frame.viewportSize) - 1);
            edge = edge || distanceSimilarity(distance, texelFetch(surfaceDistance, n, 0).r) < 0.5;
        }
    }
    float refineError = frame.temporalRefineError * (clockOnly ? CLOCK_REFINE_SCALE : 1.0);
    bool refine = frame.historyValid > 0.5 && moving > 0.0 &&
                  (!reprojected || boxSamples < 2.0 || historyError > refineError ||
                   (!clockOnly && (edge || historyContrast > REFINE_HISTORY_CONTRAST)));
    if (refine) listPixel(pixel);
}
#endif
