// The clouds in the sea's reflection at the pixels the spread could not serve (ocean/
// sea_reflection.glsl): each listed pixel's own dL_C, times its weight, added to its surface
// radiance. One invocation per listed pixel, dispatched indirectly (render/pixel_list.glsl).
#include "ocean/sea_reflection.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;  // PIXEL_LIST_GROUP_SIZE
layout(binding = IMAGE_SURFACE_RADIANCE, rgba16f) uniform image2D surfaceRadiance;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pixelList.count) return;
    ivec2 pixel = listedPixel(i);
    float weight = texelFetch(seaReflection, pixel, 0).w;
    vec4 radiance = imageLoad(surfaceRadiance, pixel);
    imageStore(surfaceRadiance, pixel, vec4(radiance.rgb + weight * cloudChangeAt(pixel).rgb, radiance.a));
}
