// The terrain shadow's samples on the sea (render/terrain_shadow.frag's g channel) that the
// sampling pass listed, land being within the sun ray's reach there: the march from sea level
// where the sample's ray meets the sea's mean surface, as the sampling pass found that point.
// One invocation per listed sample, dispatched indirectly (render/pixel_list.glsl): in the
// sampling pass the march's first turn ran at every sample, marched or not (a software
// renderer runs a loop's first turn for every group of pixels; README "Programs, not branches").
#include "common/frame_uniforms.glsl"
#define SUN_VISIBILITY_TERRAIN 1
#include "atmosphere/interface.glsl"
#include "ocean/ocean_block.glsl"
#include "ocean/sea_sphere.glsl"
#include "render/sample_spacing.glsl"
#define PIXEL_LIST_BINDING BUFFER_TERRAIN_SHADOW_SEA_SAMPLES
#include "render/pixel_list.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;  // PIXEL_LIST_GROUP_SIZE
layout(binding = IMAGE_TERRAIN_SHADOW_SAMPLES, rg32f) uniform image2D samples;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pixelList.count) return;
    ivec2 texel = listedPixel(i);
    vec3 dir = pixelRay(texel * TERRAIN_SHADOW_SPACING);  // as render/terrain_shadow.frag's ray and sea point
    vec3 seaPoint = cameraFromPlanetCentreKm() + dir * (seaSphereDistance(dir) / M_PER_KM);
    vec4 clearance = imageLoad(samples, texel);
    clearance.g = TerrainShadowClearanceAbove(seaPoint, ocean.seaLevel, frame.sunDirection);
    imageStore(samples, texel, clearance);
}
