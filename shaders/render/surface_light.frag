// Surface light: G-buffer -> the radiance leaving each surface point towards the camera,
// with no air in it (the sky pass adds what lies between the camera and the point).
//
//   R_G = albedo / pi * (sun through the atmosphere * visibility + sky irradiance)
//                                                          (Elek Eq. 17, 20; Sperlhofer Eq. 2-13)
// Below the sea surface both are first dimmed by the water above the point (ocean/water.glsl),
// how deep from the height field's height (the G-buffer normal's w), not from the mesh's
// point: from afar the mesh's chords sag hundreds of metres below the sphere between its
// vertices, and coastal land lit as sea floor that deep showed as blue-grey combs and dashes
// along every coast.
// The ground's detail normals, filtered by the pixel's footprint, come with the spread of
// slopes the filter removed (the G-buffer material's b): the sun lights them with the
// expected clamped cosine over that spread (terrain/rough_cosine.glsl), so a far pixel gets
// the mean of what a close view of its facets shows (LEAN / Toksvig in spirit, issue 13).
// Also writes the distance along the view ray to the point, which the sky pass and the
// ocean read. Pixels where nothing was drawn keep the cleared 0 (no surface).
#include "common/frame_uniforms.glsl"
#include "common/gbuffer.glsl"
#define SUN_VISIBILITY_TERRAIN 1  // the terrain's shadows in the sun (terrain/terrain_shadow.glsl)
#include "atmosphere/interface.glsl"
#include "ocean/water.glsl"
#include "terrain/rough_cosine.glsl"
#include "render/sample_spacing.glsl"
#include "render/block_samples.glsl"
// 1: the terrain's shadow from the sparse samples where they agree (render/terrain_shadow.frag);
// 0: marched at every pixel (tests compare the two).
#define TERRAIN_SHADOW_FROM_SAMPLES 1
// 1: the program for the sea floor's dark depths alone (the pixels render/surface_marks.frag
// marked in the stencil, src/render/renderer.cpp): their distance and no light, what this
// program's test gives them below, while the lighting program runs only on the rest, kept off
// them by the stencil before it runs, where its `if` would not (a software renderer runs the body
// for every pixel, masked: at `orbit` the sea floor is half of the ground, at `sea` nearly all).
#ifndef SEA_FLOOR_DARK
#define SEA_FLOOR_DARK 0
#endif
// 1: the program for the pixels render/surface_marks.frag marked, whose way to the sun surely
// meets no cloud: the clouds' shadow is 1 there, and its code is left out.
#ifndef SUN_CLEAR_OF_CLOUDS
#define SUN_CLEAR_OF_CLOUDS 0
#endif

layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_GBUFFER_ALBEDO) uniform sampler2D gAlbedo;
layout(binding = UNIT_GBUFFER_MATERIAL) uniform sampler2D gMaterial;
layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(binding = UNIT_TERRAIN_SHADOW) uniform sampler2D terrainShadowSamples;
#include "render/terrain_shadow_samples.glsl"
#include "render/surface_point.glsl"
#include "render/land_on_screen.glsl"
#include "render/terrain_shadow_list.glsl"

// The stencil's test before the shader runs (it writes no depth; the stencil it tests is kept):
// without this a shader that writes memory, as the mark of land on screen does, is tested after
// it ran, and a software renderer then lights the dark depths' pixels too.
layout(early_fragment_tests) in;

layout(location = 0) out vec4 outSurfaceRadiance;
layout(location = 1) out float outSurfaceDistance;

// A normal whose clamped cosine with the sun is the expected one over facets whose slopes
// spread by `slopeSpread` (per component) about `normal`: turned towards or away from the sun
// in the plane of the two. The spread of n.l is the slopes' projected on the sun's direction
// within the surface, slopeSpread * sqrt(1 - mu^2).
vec3 shadingNormal(vec3 normal, vec3 sun, float slopeSpread) {
    float mu = dot(normal, sun);
    vec3 across = normal - mu * sun;
    float acrossLength = length(across);
    if (slopeSpread <= 0.0 || acrossLength < 1.0e-4) return normal;
    float cosine = expectedClampedCosine(mu, slopeSpread * sqrt(max(1.0 - mu * mu, 0.0)));
    return cosine * sun + sqrt(max(1.0 - cosine * cosine, 0.0)) * (across / acrossLength);
}

// The share of the sun's disc the terrain leaves visible at the pixel's `point`: from the
// samples (render/terrain_shadow.frag) around the pixel where they agree
// (terrainClearanceFromSamples); where they do not, `marchLater` and 1 (lit): the pixel is
// listed and marched after this pass (render/terrain_shadow_list.glsl), not here, since a
// software renderer runs a march's first turn for every pixel, marched or not (README
// "Programs, not branches"); `meanVisibility`, the samples' mean, stands in where the list is
// full. A `facesSun` false pixel needs no visibility (the sun does not light it) and marches none.
// Built with TERRAIN_SHADOW_FROM_SAMPLES 0 (tests), every such pixel marches here.
float terrainVisibility(ivec2 pixel, vec3 point, bool facesSun, out bool marchLater, out float meanVisibility) {
    marchLater = false;
    meanVisibility = 1.0;
    if (terrainShadows == 0) return 1.0;
    float radius = atmosphereUniforms.sunAngularRadius;
    float clearance = 1.0;  // rad: lit
#if TERRAIN_SHADOW_FROM_SAMPLES
    float meanClearance;
    bool agree = terrainClearanceFromSamples(terrainShadowSamples, pixel, 0, radius, clearance, meanClearance);
    marchLater = facesSun && !agree;
    meanVisibility = terrainShadowDiscShare(meanClearance, radius);
    if (!agree) clearance = 1.0;
#else
    for (int i = 0; i < (facesSun ? 1 : 0); ++i) clearance = TerrainShadowClearance(point, frame.sunDirection);
#endif
    return terrainShadowDiscShare(clearance, radius);
}

// The light leaving the surface point of `pixel` (no air in it), `depthBelowSea` m under the sea;
// where the terrain's shadow is marched later, listed with the share of it the sun's light carries.
vec3 surfaceRadiance(ivec2 pixel, SurfacePoint surface, float depthBelowSea) {
    vec3 point = surface.point;
    vec3 normal = normalize(surface.normalAndHeight.xyz);
    vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
    vec3 up = normalize(point);
    vec3 shading = shadingNormal(normal, frame.sunDirection, texelFetch(gMaterial, pixel, 0).b);
    vec3 skyIrradiance;
    vec3 sunIrradiance = SunAndSkyIrradianceUnshadowed(point, shading, frame.sunDirection, skyIrradiance);
    // The visibility only where the sun lights the surface at all (as SunAndSkyIrradiance).
    bool facesSun = dot(shading, frame.sunDirection) > 0.0;
    bool marchLater;
    float meanVisibility;
    float visibility = (SUN_CLEAR_OF_CLOUDS != 0 ? 1.0 : CloudSunTransmittance(point, frame.sunDirection, CLOUD_SHADOW_MAX_KM)) *
                       terrainVisibility(pixel, point, facesSun, marchLater, meanVisibility);
    if (facesSun) sunIrradiance *= visibility;
    // The sky's share is linear in the normal's rise, (1 + n.up) / 2 (Bruneton's
    // GetSunAndSkyIrradiance): the mean normal's, not the shading normal's.
    skyIrradiance *= (1.0 + dot(normal, up)) / max(1.0 + dot(shading, up), 1.0e-3);
    lightUnderWater(depthBelowSea, dot(up, frame.sunDirection), sunIrradiance, skyIrradiance);
    vec3 radiance = albedo / PI * (sunIrradiance + skyIrradiance);
    if (marchLater) {
        // The sun's share, lit; kept, or where it is most of the radiance (a half-float target
        // would swamp what stays in full shadow) the rest, as the sea's light does.
        vec3 sunShare = albedo / PI * sunIrradiance;
        bool keepRest = dot(sunShare, vec3(1.0)) > 0.5 * dot(radiance, vec3(1.0));
        bool listed = listTerrainShadow(pixel, surface.rayDistance, sunShare, keepRest);
        if (!listed)
            radiance -= sunShare * (1.0 - meanVisibility);
        else if (keepRest)
            radiance = max(radiance - sunShare, vec3(0.0));
    }
    return radiance;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    SurfacePoint surface;
    // Nothing drawn: the sky pass shows the sky here (in the SEA_FLOOR_DARK program too: the pixels
    // with no ground are marked with the dark depths, render/surface_marks.frag).
    if (!surfacePointAt(pixel, surface)) discard;
    outSurfaceDistance = surface.rayDistance;
    outSurfaceRadiance = vec4(0.0, 0.0, 0.0, 1.0);
    float underSea = depthBelowSea(surface);
    // The sea floor's dark depths are not lit (ocean/water.glsl): there the terrain shadow's and
    // the clouds' marches take no step (a software renderer still runs the rest of the body for
    // every pixel of a group, masked: on the `sea` view this pass went from 114 to 75 ms).
#if !SEA_FLOOR_DARK
    if (underSea < 0.0) markLandOnScreen();
    if (underSea < SEA_FLOOR_DARK_DEPTH_M) outSurfaceRadiance = vec4(surfaceRadiance(pixel, surface, underSea), 1.0);
#endif
}
