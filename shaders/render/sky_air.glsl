// What the sky passes share (render/sky.frag, sky_sparse.frag, sky_temporal.frag,
// sky_refine.comp): the march
// of one view ray through the air and the clouds, the water body under the sea, and the
// composite of the surface behind. Include after common/frame_uniforms.glsl,
// atmosphere/interface.glsl, clouds/cloud_march.glsl and ocean/water.glsl.

// The march's step counts over the frame, when clouds.statistics asks (planet bench).
layout(std430, binding = BUFFER_CLOUD_STATISTICS) buffer CloudStatistics {
    uint marchSteps;    // small steps (in or near clouds)
    uint skippedSteps;  // large steps through empty space (the zero-density border's)
    uint pixels;        // pixels marched through air
} statistics;

#include "render/gradient_noise.glsl"

// Where the clouds' opacity along a ray passes this, they are what the pixel shows: it is
// reprojected from their distance and moves with the wind.
const float CLOUDY_OPACITY = 0.3;

// What lies between the camera and the surface point `distanceM` along `dir` (or space, when
// 0): T and S of Elek Eq. 19-20, and where to reproject it from.
struct AirMarch {
    vec3 transmittance;
    vec3 inscatter;
    float reprojectionKm;  // the clouds' opacity-weighted distance where they dominate, else the
                           // surface's; 0: nothing but air to space (reproject as a direction)
    float cloudOpacity;    // 1 - the clouds' transmittance along the ray
};

AirMarch marchAir(vec3 dir, float distanceM, float jitter) {
    // The camera by its up and altitude, both formed in double (not its float position, whose
    // radius is rounded to half a metre: the air below the horizon from a few metres up).
    ViewMarch m = MarchViewAt(frame.cameraUp, frame.cameraAltitude / M_PER_KM, dir, distanceM / M_PER_KM,
                              frame.sunDirection, MarchQualityOf(jitter));
    if (clouds.statistics != 0) {
        atomicAdd(statistics.marchSteps, uint(m.steps));
        atomicAdd(statistics.skippedSteps, uint(m.skipped));
        atomicAdd(statistics.pixels, 1u);
    }
    AirMarch a;
    a.transmittance = m.transmittance;
    a.inscatter = m.inscatter;
    a.reprojectionKm = m.cloudOpacity > CLOUDY_OPACITY ? m.cloudDistance : distanceM / M_PER_KM;
    a.cloudOpacity = m.cloudOpacity;
    return a;
}

// A pixel marched at full rate: render/sky.frag's, and render/sky_refine.comp's for the pixels
// the temporal reconstruction could not trust; the same start in both, so a refined pixel is
// the full-rate frame's.
AirMarch marchPixelAtFullRate(ivec2 pixel, vec3 dir, float distanceM) {
    return marchAir(dir, distanceM, interleavedGradientNoise(pixel));
}

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

// Whether the ray `dir` from the camera never enters the air: the camera above the atmosphere's
// top and the ray leaving it or passing it by. Then T = 1 and S = 0 exactly, as the march gives.
// CAMERA_IN_AIR (src/render/atmosphere_program.h): the camera a kilometre or more under the top, where
// no ray misses it; a program, not a branch: a software renderer runs the space's side too.
bool rayMissesTheAir(vec3 dir) {
#if CAMERA_IN_AIR
    return false;
#else
    AtmosphereParameters atmosphere = atmosphereParameters();
    float r = atmosphere.bottom_radius + frame.cameraAltitude / M_PER_KM;
    if (r < atmosphere.top_radius) return false;
    float mu = dot(frame.cameraUp, dir);
    return mu >= 0.0 || r * r * (mu * mu - 1.0) + atmosphere.top_radius * atmosphere.top_radius < 0.0;
#endif
}

// What the air's T dims along `dir`: the surface's radiance R_G where there is a surface
// (`distance` > 0), else the sun's disc. NO_SUN_DISC (src/render/atmosphere_program.h): the
// program's pixels lie off the disc's rectangle on screen (Renderer::drawSkyPasses), where it is 0.
vec3 behindTheAir(vec3 dir, vec3 surface, float distance) {
#if NO_SUN_DISC
    return distance > 0.0 ? surface : vec3(0.0);
#else
    return distance > 0.0 ? surface : SunDiscRadiance(dir, frame.sunDirection);
#endif
}

// In air: L = T R_G + S at a surface point, S + T x the sun's disc where the ray goes to
// space (Elek Eq. 19-20; Sperlhofer Eq. 2-16).
vec3 throughAir(vec3 dir, vec3 surface, float distance, vec3 transmittance, vec3 inscatter) {
    return transmittance * behindTheAir(dir, surface, distance) + inscatter;
}
