// The reduced-rate march (pass "sky march"): drawn over a target a quarter of the frame's
// size on each side, it traces one pixel of each 4x4 block (render/sparse_pattern.glsl)
// through air and clouds exactly as the full-rate sky pass does (render/sky.frag), with a
// start jitter that moves at every visit; render/sky_temporal.frag builds the full frame
// from these samples and the history.
#include "common/frame_uniforms.glsl"
// LIGHT_SHAFTS_TERRAIN (the terrain's shadows in the air) comes from the program builder, 1 only
// when the preset asks for light shafts (src/render/atmosphere_program.h).
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/water.glsl"
#include "render/sky_air.glsl"
#include "render/sparse_pattern.glsl"

layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;

layout(location = 0) out vec4 outInscatter;      // S, reprojection distance km
layout(location = 1) out vec4 outTransmittance;  // T, the clouds' opacity

void main() {
    ivec2 block = ivec2(gl_FragCoord.xy);
    ivec2 pixel = sparseTracedPixel(block);
    vec2 ndc = (vec2(pixel) + 0.5) * frame.inverseViewportSize * 2.0 - 1.0;
    float distance = texelFetch(surfaceDistance, pixel, 0).r;
    AirMarch a = marchAir(worldRayFromNdc(ndc), distance, sparseJitter(block));
    outInscatter = vec4(min(a.inscatter, vec3(MAX_HDR_RADIANCE)), a.reprojectionKm);
    outTransmittance = vec4(a.transmittance, a.cloudOpacity);
}
