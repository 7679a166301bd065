// The sky pass at full rate: everything between the camera and the surface point, or space,
// for every pixel. It reads the surface radiance R_G and the distance to its point (surface
// light and ocean passes) and applies the medium in between:
//
//   in air       L = T(camera, point) R_G + S(camera, point)        (Elek Eq. 19-20; Sperlhofer Eq. 4-18)
//   no surface   L = S(camera, space) + T * sun disc                (Sperlhofer Eq. 2-16; Elek §4.2.2)
//   under water  L = T_w(d) R_G + (1 - T_w(d)) L_deep               (ocean/water.glsl)
//
// In air the ray is walked by the unified march of clouds and atmosphere (clouds/
// cloud_march.glsl, Michelic Eq. 15-20): without clouds it is one atmosphere lookup, T R_G + S.
// This and the reduced-rate march (sky_sparse.frag, reconstructed by sky_temporal.frag) are
// the places where aerial perspective is computed. It also writes T and S as the first
// sample of the temporal march's history (render/sky_temporal.frag).
#include "common/frame_uniforms.glsl"
// LIGHT_SHAFTS_TERRAIN (the terrain's shadows in the air) comes from the program builder, 1 only
// when the preset asks for light shafts (src/render/atmosphere_program.h).
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/water.glsl"
#include "render/sky_air.glsl"
#include "render/sky_medium.glsl"

// A camera under the sea (frame.cameraDepthBelowSea > 0) gets this file built with UNDER_WATER 1
// (src/render/renderer.cpp): a program rather than an if, because a software renderer runs
// both sides of an if for every pixel, and the water's side (its light through the sea above
// the camera) cost the air's pass a tenth more where no pixel took it.
#ifndef UNDER_WATER
#define UNDER_WATER 0
#endif

layout(binding = UNIT_SURFACE_RADIANCE) uniform sampler2D surfaceRadiance;
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;

layout(location = 0) out vec4 outRadiance;
layout(location = 1) out uvec4 outSkyMedium;  // T, S, samples in the history (1: this one)

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 dir = worldRayFromNdc(pixelCentreNdc(gl_FragCoord.xy));  // as render/sky_refine.comp
    vec3 surface = texelFetch(surfaceRadiance, pixel, 0).rgb;
    float distance = texelFetch(surfaceDistance, pixel, 0).r;
    vec3 radiance;
#if UNDER_WATER
    radiance = throughWater(surface, distance);
    outSkyMedium = packSkyMedium(SkySample(vec3(0.0), vec3(0.0)), 0.0);
#else
    AirMarch a = marchPixelAtFullRate(pixel, dir, distance);
    radiance = throughAir(dir, surface, distance, a.transmittance, a.inscatter);
    outSkyMedium = packSkyMedium(SkySample(min(a.inscatter, vec3(MAX_HDR_RADIANCE)), a.transmittance), 1.0);
#endif
    outRadiance = vec4(min(radiance, vec3(MAX_HDR_RADIANCE)), 1.0);
}
