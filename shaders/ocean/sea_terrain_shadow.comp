// The terrain's shadow on the sea at the pixels the ocean listed (ocean/sea_terrain_shadow.glsl):
// the march from the sea's point towards the sun (as ocean/sea_light.frag would march it), and
// the share of the radiance the sun's light carries set for the part of its disc the terrain leaves. One
// invocation per listed pixel, dispatched indirectly with as many groups as the list needs:
// nothing where none is listed.
#include "common/frame_uniforms.glsl"
#define SUN_VISIBILITY_TERRAIN 1
#include "atmosphere/interface.glsl"
#include "terrain/grid.glsl"
#include "ocean/ocean_block.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/terrain_block.glsl"
#include "ocean/sea_terrain_shadow.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;  // SEA_TERRAIN_SHADOW_GROUP_SIZE
layout(binding = IMAGE_SURFACE_RADIANCE, rgba16f) uniform image2D surfaceRadiance;
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= min(seaTerrainShadowList.count, seaTerrainShadowList.capacity)) return;
    uvec4 entry = seaTerrainShadowList.entries[i];
    ivec2 pixel = ivec2(entry.x & 0xffffu, entry.x >> 16);
    float seaDistance = uintBitsToFloat(entry.y);
    if (texelFetch(surfaceDistance, pixel, 0).r != seaDistance) return;  // (a safeguard: the sea's light lists each pixel once)
    vec3 sunShare = unpackSunShare(entry.zw);
    vec3 point = cameraFromPlanetCentreKm() + pixelRay(pixel) * (seaDistance / M_PER_KM);  // as ocean/sea_light.frag's
    float clearance = TerrainShadowClearanceAbove(point, ocean.seaLevel, frame.sunDirection);
    float visibility = terrainShadowDiscShare(clearance, atmosphereUniforms.sunAngularRadius);
    vec4 radiance = imageLoad(surfaceRadiance, pixel);
    bool keptRest = (entry.w & 0x80000000u) != 0u;
    vec3 updated = keptRest ? radiance.rgb + sunShare * visibility : radiance.rgb - sunShare * (1.0 - visibility);
    imageStore(surfaceRadiance, pixel, vec4(clamp(updated, vec3(0.0), vec3(MAX_HDR_RADIANCE)), radiance.a));
}
