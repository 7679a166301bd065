// The sky pass: everything between the camera and the surface point, or space, for every
// pixel. It reads the surface radiance R_G and the distance to its point (surface light
// and ocean passes) and applies the medium in between:
//
//   in air       L = T(camera, point) R_G + S(camera, point)        (Elek Eq. 19-20; Sperlhofer Eq. 4-18)
//   no surface   L = S(camera, space) + T * sun disc                (Sperlhofer Eq. 2-16; Elek §4.2.2)
//   under water  L = T_w(d) R_G + (1 - T_w(d)) L_deep               (ocean/water.glsl)
//
// In air the ray is walked by the unified march of clouds and atmosphere (clouds/
// cloud_march.glsl, Michelic Eq. 15-20): without clouds it is one atmosphere lookup, T R_G + S.
// This is the one place where aerial perspective is computed.
#include "common/frame_uniforms.glsl"
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/water.glsl"

in vec2 vNdc;
layout(binding = UNIT_SURFACE_RADIANCE) uniform sampler2D surfaceRadiance;
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;

layout(location = 0) out vec4 outRadiance;

// The march's step counts over the frame, when clouds.statistics asks (planet bench).
layout(std430, binding = BUFFER_CLOUD_STATISTICS) buffer CloudStatistics {
    uint marchSteps;    // small steps (in or near clouds)
    uint skippedSteps;  // large steps through empty space (the zero-density border's)
    uint pixels;        // pixels marched through air
} statistics;

// Under water: the water body between the camera and the first surface (the sea floor, or
// the sea surface seen from below), lit by the sun and sky through the water above the
// camera. Nothing drawn: water all the way.
vec3 throughWater(vec3 surface, float distance) {
    vec3 up = frame.cameraUp;
    vec3 seaSurface = cameraFromPlanetCentreKm() + up * (frame.cameraDepthBelowSea / M_PER_KM);
    vec3 skyIrradiance;
    vec3 sunIrradiance = SunAndSkyIrradiance(seaSurface, up, frame.sunDirection, skyIrradiance);
    vec3 light = (sunIrradiance + skyIrradiance) * waterTransmittanceAlong(frame.cameraDepthBelowSea);
    vec3 transmittance = waterTransmittanceAlong(distance > 0.0 ? distance : 1.0e30);
    return transmittance * surface + (1.0 - transmittance) * deepWaterRadiance(light);
}

// In air: clouds and aerial perspective to the surface point, or to space and the sun's disc.
vec3 throughAir(vec3 dir, vec3 surface, float distance) {
    vec3 sun = frame.sunDirection;
    // Interleaved gradient noise (Jimenez 2014): a different start in each pixel of a 3x3 block.
    float jitter = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    ViewMarch m = MarchView(cameraFromPlanetCentreKm(), dir, distance / M_PER_KM, sun, MarchQualityOf(jitter));
    if (clouds.statistics != 0) {
        atomicAdd(statistics.marchSteps, uint(m.steps));
        atomicAdd(statistics.skippedSteps, uint(m.skipped));
        atomicAdd(statistics.pixels, 1u);
    }
    if (distance <= 0.0) return m.inscatter + m.transmittance * SunDiscRadiance(dir, sun);
    return m.transmittance * surface + m.inscatter;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 dir = worldRayFromNdc(vNdc);
    vec3 surface = texelFetch(surfaceRadiance, pixel, 0).rgb;
    float distance = texelFetch(surfaceDistance, pixel, 0).r;
    vec3 radiance = frame.cameraDepthBelowSea > 0.0 ? throughWater(surface, distance) : throughAir(dir, surface, distance);
    outRadiance = vec4(min(radiance, vec3(MAX_HDR_RADIANCE)), 1.0);
}
