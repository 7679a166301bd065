// The terrain shadow's samples that the sampling pass (render/terrain_shadow.frag) listed, with what
// to march at each (the entry's flags, render/pixel_list.glsl): 1, the ground's march (r) from the
// G-buffer's surface point, found as the sampling pass found it; 2, the sea's (g) from sea level
// where the sample's ray meets the sea's mean surface in front of its ground. One invocation per
// listed sample, dispatched indirectly: in the sampling pass a march's first turn ran at every
// sample, marched or not (a software renderer runs a loop's first turn for every group of pixels;
// README "Programs, not branches"). The sample's one or two marches are turns of one loop, so that a
// group runs the march's code once a turn.
#include "common/frame_uniforms.glsl"
#include "common/gbuffer.glsl"
#define SUN_VISIBILITY_TERRAIN 1
#include "atmosphere/interface.glsl"
#include "ocean/ocean_block.glsl"
#include "ocean/sea_sphere.glsl"
#include "render/sample_spacing.glsl"
#define PIXEL_LIST_BINDING BUFFER_TERRAIN_SHADOW_SAMPLE_MARCHES
#include "render/pixel_list.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;  // PIXEL_LIST_GROUP_SIZE
layout(binding = IMAGE_TERRAIN_SHADOW_SAMPLES, rg32f) uniform image2D samples;
layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gDepth;
#include "render/surface_point.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pixelList.count) return;
    ivec2 texel = listedPixel(i);
    uint flags = listedFlags(i);  // 1: the ground's march, 2: the sea's
    SurfacePoint ground;
    surfacePointAt(texel * terrainShadowSpacing(frameHeightPixels()), ground);  // as render/terrain_shadow.frag's point and ray
    vec3 seaPoint = cameraFromPlanetCentreKm() + ground.dir * (seaSphereDistance(ground.dir) / M_PER_KM);
    vec4 clearance = imageLoad(samples, texel);
    for (int k = (flags & 1u) != 0u ? 0 : 1; k <= ((flags & 2u) != 0u ? 1 : 0); ++k) {
        bool onGround = k == 0;
        float c = TerrainShadowClearanceAbove(onGround ? ground.point : seaPoint, onGround ? -1.0e9 : ocean.seaLevel,
                                              frame.sunDirection);
        if (onGround) clearance.r = c;
        else clearance.g = c;
    }
    imageStore(samples, texel, clearance);
}
