// The temporal march's fallback (pass "sky refine"): the pixels that render/sky_temporal.frag
// listed as beyond what its samples and history can rebuild (in a moving frame: nothing to
// reproject, an edge, a history read across a line, or a nearest sample whose history was off
// by more than render.temporal_refine_error; the list is at the end of its main) are marched
// again here, exactly as the full-rate sky pass marches them (render/sky.frag: the same ray
// through the pixel's centre, the same start), over the reconstruction's radiance and T, S.
// In a still frame (STILL_FRAME, with the reconstruction's still-frame program) the listed
// pixels are those whose surface changed (an edge the anti-aliasing's jitter moved): each takes
// its new sample or its samples' spatial estimate instead, as the general reconstruction would.
// One invocation per listed pixel (render/pixel_list.glsl), dispatched indirectly with as
// many groups as the list needs: no work for a pixel not listed.
#include "common/frame_uniforms.glsl"
// LIGHT_SHAFTS_TERRAIN (the terrain's shadows in the air) comes from the program builder, 1 only
// when the preset asks for light shafts (src/render/atmosphere_program.h).
vec2 refinedPixelCentre;  // the light shafts' jitter seed, as gl_FragCoord.xy in the sky pass
#define SHAFT_PIXEL refinedPixelCentre
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/water.glsl"
#include "render/sky_air.glsl"
#include "render/sky_medium.glsl"
#ifdef STILL_FRAME
#include "render/sparse_pattern.glsl"
#include "render/sky_history.glsl"
#include "render/sky_spatial.glsl"
#endif
#define PIXEL_LIST_BINDING BUFFER_SKY_REFINE
#include "render/pixel_list.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;  // PIXEL_LIST_GROUP_SIZE
layout(binding = UNIT_SURFACE_RADIANCE) uniform sampler2D surfaceRadiance;
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;
layout(binding = IMAGE_HDR_RADIANCE, rgba16f) uniform writeonly image2D hdrRadiance;
layout(binding = IMAGE_SKY_MEDIUM, rgba32ui) uniform writeonly uimage2D skyMedium;  // T, S, samples (1: this one)

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pixelList.count) return;
    ivec2 pixel = listedPixel(i);
    refinedPixelCentre = vec2(pixel) + 0.5;
    vec3 dir = worldRayFromNdc(pixelCentreNdc(refinedPixelCentre));
    vec3 surface = texelFetch(surfaceRadiance, pixel, 0).rgb;
    float distance = texelFetch(surfaceDistance, pixel, 0).r;
#ifdef STILL_FRAME
    float samples;
    SkySample estimate = surfaceChangedEstimate(pixel, distance, samples);
    imageStore(hdrRadiance, pixel, vec4(min(throughAir(dir, surface, distance, estimate.transmittance, estimate.inscatter),
                                             vec3(MAX_HDR_RADIANCE)), 1.0));
    imageStore(skyMedium, pixel, packSkyMedium(estimate, samples));
#else
    AirMarch a = marchPixelAtFullRate(pixel, dir, distance);
    vec3 radiance = min(throughAir(dir, surface, distance, a.transmittance, a.inscatter), vec3(MAX_HDR_RADIANCE));
    imageStore(hdrRadiance, pixel, vec4(radiance, 1.0));
    imageStore(skyMedium, pixel, packSkyMedium(SkySample(min(a.inscatter, vec3(MAX_HDR_RADIANCE)), a.transmittance), 1.0));
#endif
}
