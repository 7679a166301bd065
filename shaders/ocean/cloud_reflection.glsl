// The sky and the clouds along the sea's reflected rays (ocean/sea_light.frag), and the clouds' share of
// it formed once per point of the sea's projected grid where the sea is a flat mirror to every
// pixel (ocean.vert; issue 15: marched in every pixel, the reflection was most of the ocean
// pass from orbit).
//
// Per pixel the sea reflects along the mirror ray of its footprint-filtered normal
// (ocean_waves.glsl): the waves a pixel resolves tilt it, the rest only roughen the glitter.
// Seen from so high that no pixel resolves a wave whose tilt would move its ray's crossing of
// the cloud layer by a sizeable part of the pixel's footprint (src/ocean/flat_mirror.h decides,
// on the CPU, per frame), the pixels' rays are those of the mean sea surface, which vary
// smoothly over the sea. Then the program is built with OCEAN_FLAT_MIRROR 1: what the clouds
// change in the reflection,
//   dL_C = MarchView(p, r) - L_sky(p, r)          (the march: clouds/cloud_march.glsl),
// is formed at the grid's points and interpolated by the patches, and each fragment adds it
// to the clear sky along its own ray: L_sky(p, r) + dL_C. Where no cloud is crossed dL_C = 0
// and the sky's reflection is exactly the per-pixel one. Otherwise (OCEAN_FLAT_MIRROR 0) each
// fragment marches its own reflected ray.
//
// Seen from higher still, where no pixel resolves any wave (src/ocean/flat_mirror.h,
// seaIsASmoothMirror), every fragment's normal is the sphere's own, so its mirror ray is the
// mean surface's, as at the grid's points: then (OCEAN_SMOOTH_MIRROR 1, a flat mirror too) the
// grid's points form the whole reflection, L_sky + dL_C = MarchView(p, r), and the fragments
// take it interpolated, with no sky lookup of their own (from space the lookup was a third of
// the sea's fragment work; the reflected sky varies over the disc, not within a patch).
#include "ocean/mirror_modes.glsl"

// The reflected ray's march: one slice, a 32nd of the steps, two sun samples and the far field
// (its few steps would alias the volume; waves and Fresnel blur the reflection anyway).
vec3 ReflectedMarch(vec3 point, vec3 reflected, vec3 sun) {
    MarchQuality quality = MarchQualityOf(0.5);
    quality.slicesPerCrossing = 1;
    quality.stepBudget = max(clouds.maxSteps / 32, 4);
    quality.sunSamples = min(clouds.sunSamples, 2);
    quality.minFootprintKm = CloudFarFieldFootprint();
    return MarchView(point, reflected, 0.0, sun, quality).inscatter;
}

// dL_C above: the clouds' change to what the sea reflects along `reflected` from `point` (km
// from the planet centre).
vec3 CloudReflectionChange(vec3 point, vec3 reflected, vec3 sun) {
    vec3 clearTransmittance;
    return ReflectedMarch(point, reflected, sun) - SkyRadiance(point, reflected, sun, clearTransmittance);
}

// The mirror ray of the surface with unit normal `normal` seen along `view`, kept above the
// horizon (the sea never reflects the ground below it).
vec3 SeaReflectedRay(vec3 view, vec3 normal, vec3 up) {
    vec3 reflected = reflect(view, normal);
    return normalize(reflected + up * max(0.0, 0.01 - dot(reflected, up)));
}

