// Atmosphere model: types and parameters, shared by GLSL and C++.
//
// This file and functions.glsl are written in the subset of GLSL that is also
// C++ (STYLE habit 1, after Bruneton's atmosphere/definitions.glsl): the GPU
// precomputation and rendering compile them as GLSL in single precision, and
// src/atmosphere/model.h compiles the very same text as C++ in
// double precision for the CPU reference. Differences are hidden behind the
// names below, defined for each language.
//
// Units: lengths in km (float precision at planet scale: r^2 - R^2 terms in m
// would lose everything to rounding), scattering coefficients in 1/km,
// irradiance in W m^-2 nm^-1, radiance in W m^-2 sr^-1 nm^-1.

#ifndef __cplusplus
#define IN(x) const in x
#define OUT(x) out x
#define Length float
#define Area float
#define Number float
#define Spectrum vec3
#endif

// One layer of a density profile: density(h) = exp_term * exp(exp_scale * h)
// + linear_term * h + constant_term, clamped to [0, 1] (h: altitude in km).
// Exponential profiles (Elek Eq. 8) use the exp terms, ozone's tent the linear ones.
struct DensityProfileLayer {
    Length width;          // km; the layer applies below this altitude (layer 0 only)
    Number exp_term;
    Number exp_scale;      // 1/km
    Number linear_term;    // 1/km
    Number constant_term;
};

struct DensityProfile {
    DensityProfileLayer layers[2];  // layer 0 below layers[0].width, layer 1 above
};

struct AtmosphereParameters {
    Spectrum solar_irradiance;           // at the top of the atmosphere
    Number sun_angular_radius;           // rad
    Length bottom_radius;                // km (the planet's radius)
    Length top_radius;                   // km
    DensityProfile rayleigh_density;
    Spectrum rayleigh_scattering;        // 1/km at density 1
    DensityProfile mie_density;
    Spectrum mie_scattering;             // 1/km
    Spectrum mie_extinction;             // 1/km
    Number mie_phase_function_g;
    DensityProfile absorption_density;   // ozone
    Spectrum absorption_extinction;      // 1/km
    Spectrum ground_albedo;
    Number mu_s_min;                     // cosine of the largest sun zenith angle the tables cover
    Number elek_rayleigh_phase;          // 1: Elek Eq. 15 instead of Eq. 2
};
