// The terrain's shadow at the pixels a pass listed (render/terrain_shadow_list.glsl): the march
// from the pixel's point towards the sun, from the ground (TERRAIN_SHADOW_LIST_GROUND 1, the
// surface light's pixels, as render/surface_light.frag would march it) or from sea level (the
// sea's light's, as ocean/sea_light.frag would), and the share of the radiance the sun's light
// carries set for the part of its disc the terrain leaves. One invocation per listed pixel,
// dispatched indirectly with as many groups as the list needs: nothing where none is listed.
#ifndef TERRAIN_SHADOW_LIST_GROUND
#define TERRAIN_SHADOW_LIST_GROUND 0
#endif
#include "common/frame_uniforms.glsl"
#define SUN_VISIBILITY_TERRAIN 1
#include "atmosphere/interface.glsl"
#include "terrain/grid.glsl"
#include "ocean/ocean_block.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/terrain_block.glsl"
#include "render/terrain_shadow_list.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;  // TERRAIN_SHADOW_LIST_GROUP_SIZE
layout(binding = IMAGE_SURFACE_RADIANCE, rgba16f) uniform image2D surfaceRadiance;
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= min(terrainShadowList.count, terrainShadowList.capacity)) return;
    uvec4 entry = terrainShadowList.entries[i];
    ivec2 pixel = ivec2(entry.x & 0xffffu, entry.x >> 16);
    float rayDistance = uintBitsToFloat(entry.y);
    if (texelFetch(surfaceDistance, pixel, 0).r != rayDistance) return;  // (a safeguard: a pass lists each pixel once)
    vec3 sunShare = unpackSunShare(entry.zw);
    vec3 point = cameraFromPlanetCentreKm() + pixelRay(pixel) * (rayDistance / M_PER_KM);  // as the listing pass's
    float startM = TERRAIN_SHADOW_LIST_GROUND != 0 ? -1.0e9 : ocean.seaLevel;  // the ground's, or the sea's level
    float clearance = TerrainShadowClearanceAbove(point, startM, frame.sunDirection);
    float visibility = terrainShadowDiscShare(clearance, atmosphereUniforms.sunAngularRadius);
    vec4 radiance = imageLoad(surfaceRadiance, pixel);
    bool keptRest = (entry.w & 0x80000000u) != 0u;
    vec3 updated = keptRest ? radiance.rgb + sunShare * visibility : radiance.rgb - sunShare * (1.0 - visibility);
    imageStore(surfaceRadiance, pixel, vec4(clamp(updated, vec3(0.0), vec3(MAX_HDR_RADIANCE)), radiance.a));
}
