// The temporal march's fallback (pass "sky refine"): the pixels that render/sky_temporal.frag
// marked as beyond what its samples and history can rebuild (in a moving frame: nothing to
// reproject, an edge, a history read across a line, or a nearest sample whose history was off
// by more than render.temporal_refine_error; the list is at the end of its main) are marched again here,
// exactly as the full-rate sky pass marches them (render/sky.frag), over the reconstruction's
// T, S and radiance. Every other pixel is dropped before this shader runs: the marks are the
// depth the pass draws over, and its triangle passes the depth test only where one was made
// (src/render/renderer.cpp).
#include "common/frame_uniforms.glsl"
// LIGHT_SHAFTS_TERRAIN (the terrain's shadows in the air) comes from the program builder, 1 only
// when the preset asks for light shafts (src/render/atmosphere_program.h).
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/water.glsl"
#include "render/sky_air.glsl"
#include "render/sky_medium.glsl"

layout(early_fragment_tests) in;  // the depth test, before the shader: see above
in vec2 vNdc;
layout(binding = UNIT_SURFACE_RADIANCE) uniform sampler2D surfaceRadiance;
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;

layout(location = 0) out vec4 outRadiance;
layout(location = 1) out uvec4 outSkyMedium;  // T, S, samples in the history (1: this one)

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 dir = worldRayFromNdc(vNdc);
    vec3 surface = texelFetch(surfaceRadiance, pixel, 0).rgb;
    float distance = texelFetch(surfaceDistance, pixel, 0).r;
    AirMarch a = marchPixelAtFullRate(pixel, dir, distance);
    outRadiance = vec4(min(throughAir(dir, surface, distance, a.transmittance, a.inscatter), vec3(MAX_HDR_RADIANCE)), 1.0);
    outSkyMedium = packSkyMedium(SkySample(min(a.inscatter, vec3(MAX_HDR_RADIANCE)), a.transmittance), 1.0);
}
