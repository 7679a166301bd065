// The terrain's shadow at a sparse set of pixels, one of each terrainShadowSpacing-square
// block, the block's corner: the march's clearance angle (rad; the sun's disc is whole at its
// angular radius and above, hidden at minus that: terrain/terrain_shadow.glsl), both channels
// marched after this pass at the samples it lists (render/terrain_shadow_sample_marches.comp)
//   r  at the G-buffer's surface point (the ground, the sea floor); TERRAIN_SHADOW_NO_SURFACE
//      where the pixel shows none;
//   g  where the pixel's ray meets the sea's mean surface in front of that ground (from sea
//      level, as the ocean marches: TerrainShadowClearanceAbove, by render/terrain_shadow_sample_marches.comp
//      after this pass at the samples it lists); 1 where no land lies within the shadow's reach
//      (terrainShadowMayReachSea) or the sun is down; TERRAIN_SHADOW_NO_SURFACE where the ray
//      meets no sea in front of the ground.
// The surface light (r) and the ocean (g) read these at the pixels around their own and march
// only where they do not all say the same, clearly lit or fully shadowed
// (render/terrain_shadow_samples.glsl): the march is the surface light's main cost at a low sun
// or at ground level, and the ocean's beside land (a beach), and most of a frame is wholly lit
// or wholly in shadow.
// The sea floor's dark depths (ocean/water.glsl's SEA_FLOOR_DARK_DEPTH_M), which the surface
// light does not light, are not marched either: TERRAIN_SHADOW_NO_SURFACE there in r, so that a
// shallower pixel beside them marches its own.
#include "common/frame_uniforms.glsl"
#include "common/gbuffer.glsl"
#define SUN_VISIBILITY_TERRAIN 1
#include "atmosphere/interface.glsl"
#include "render/sample_spacing.glsl"
#include "ocean/water.glsl"
#include "ocean/ocean_block.glsl"
#include "ocean/sea_sphere.glsl"
#define PIXEL_LIST_BINDING BUFFER_TERRAIN_SHADOW_SAMPLE_MARCHES
#include "render/pixel_list.glsl"

layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gDepth;
#include "render/surface_point.glsl"

layout(location = 0) out vec2 outClearance;

// Where the view ray `dir` (unit, world axes) meets the sea's mean surface (a sphere
// ocean.seaLevel above the planet radius) in front of the pixel's ground (`ground`, if
// `hasGround`): true, with the point in km from the planet centre. The waves move the sea's
// points by metres, which do not move a terrain's shadow. False on a dry world, from under the sea (the ocean shades no sunlight
// there) and where the ground is in front (the shore, land).
bool seaSurfaceAt(vec3 dir, SurfacePoint ground, bool hasGround, out vec3 point) {
    point = vec3(0.0);
    if (terrainHasOcean == 0) return false;
    float t = seaSphereDistance(dir);  // m; -1: no sea in front, or the camera under it
    if (t < 0.0 || (hasGround && t >= ground.rayDistance)) return false;
    point = cameraFromPlanetCentreKm() + dir * (t / M_PER_KM);
    return true;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy) * terrainShadowSpacing(frameHeightPixels());
    vec3 sun = frame.sunDirection;
    SurfacePoint s;
    outClearance = vec2(TERRAIN_SHADOW_NO_SURFACE);
    // The marches after this pass, at the samples listed with what to march (render/
    // terrain_shadow_sample_marches.comp): here a march's first turn ran at every sample, marched or
    // not (a software renderer runs a loop's first turn for every group of pixels; the ground's:
    // 3 ms at `orbit`, 4.5 at `space`, 1280x720).
    bool surface = surfacePointAt(pixel, s);
    bool groundMarch = surface && depthBelowSea(s) < SEA_FLOOR_DARK_DEPTH_M;
    if (groundMarch) outClearance.r = 1.0;  // (the march's, after this pass)
    vec3 seaPoint;
    bool sea = seaSurfaceAt(s.dir, s, surface, seaPoint);
    bool mayReach = false;  // land within the shadow's reach of the sea's point, the sun up
    for (int i = 0; i < (sea ? 1 : 0); ++i) {
        vec3 up = normalize(seaPoint);
        mayReach = dot(up, sun) > 0.0 &&
                   terrainShadowMayReachSea(up, sun, ocean.seaLevel, frame.planetRadius / M_PER_KM,
                                            ocean.continentLipschitz, ocean.continentSampleSlackRad, terrainShape,
                                            uContinents);
        outClearance.g = 1.0;  // lit where no land is within reach, or the sun is down (no sunlight to shade)
    }
    // (The sea's march there cost 4.5 ms at `orbit`.) The entry's flags: 1 the ground's march (r), 2 the sea's (g).
    uint marches = (groundMarch ? 1u : 0u) | (mayReach ? 2u : 0u);
    if (marches != 0u) listPixelWithFlags(ivec2(gl_FragCoord.xy), marches);
}
