// Spherical Gerstner waves (Michelic §4, Eq. 7-11): the CPU reference, in double.
//
// A wave i starts at the point o_i of the sphere (unit vector) and travels along
// great circles to the antipode -o_i. At a point with unit direction v from the
// centre, on the sea sphere of radius r:
//   l_i = r * angle(v, o_i)                          distance from the origin (Eq. 7)
//   d_i = normalize(v (v . o_i) - o_i)               unit tangent pointing away from o_i
//                                                    (Eq. 7's v x ((v - o_i) x v), normalised)
//   theta_i = k_i l_i - w_i t + phase_i              phase; k_i = 2 pi / wavelength,
//                                                    w_i = k_i * speed (deep water: sqrt(g k))
//   Q'_i = Q_i smoothstep(e0, e1, 1 - |v . o_i|)     Eq. 11: no loops at o_i and -o_i
//   P = v r + v sum A_i sin(theta_i) + sum Q'_i A_i cos(theta_i) d_i        (Eq. 8)
//   n = normalize(v - v sum Q'_i A_i k_i sin(theta_i) - sum d_i A_i k_i cos(theta_i))  (Eq. 10)
// Deviations from the paper, and why:
//  - the paper writes + phi_i t, which moves crests towards the origin; we write - w_i t so
//    that waves travel from o_i to -o_i as its text says;
//  - d_i is normalised (Eq. 7's vector has length sin(angle)): the paper uses d_i as the unit
//    direction of Eq. 5, and unnormalised it would shrink the horizontal displacement and the
//    normal's tilt towards the origin and antipode;
//  - at v = +-o_i, where d_i is undefined, the wave's horizontal displacement is zero (its Q' is
//    0 there anyway when e0 > 0); the angle is atan2(|v x o|, v . o), accurate at 0 and pi;
//  - Eq. 10 is the paper's first-order normal (Eq. 9 on the sphere): it drops products of
//    different waves' slopes, so it is exact for one wave (up to curvature, A / r) and for many
//    off by at most m G / (1 - m)^2 rad, m = sum Q'_i A_i k_i |sin theta_i| (<= sum Q A k),
//    G = |sum A_i k_i cos theta_i d_i| (the slope): 1.4 deg at worst for the default sea at
//    choppiness 0.9 (tests/test_ocean_waves.cpp derives and checks the bound).
//
// The GPU evaluates the same sum relative to the camera (shaders/ocean/gerstner.glsl) because a
// float l_i of planet size cannot hold the phase of a 1 m wave; ocean/ocean_gpu.h packs the
// per-wave, per-frame data it needs.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace planet::ocean {

inline constexpr double kGravity = 9.81;  // m s^-2

struct GerstnerWave {
    glm::dvec3 origin{0.0, 0.0, 1.0};  // o_i, unit vector (world frame, +Z north)
    double amplitude_m = 0.5;          // A_i, m, >= 0
    double wavelength_m = 20.0;        // 2 pi / k_i, m, > 0
    double steepness = 0.5;            // Q_i, [0, 1]
    double speed_mps = 5.59;           // phase speed, m/s (deep water: sqrt(g / k))
    double phase_rad = 0.0;            // phase_i at t = 0

    double wavenumber() const;         // k_i = 2 pi / wavelength, rad/m
    double angularFrequency() const;   // w_i = k_i * speed, rad/s
};

// Deep-water dispersion: phase speed sqrt(g / k) of a wave of this wavelength, m/s.
double deepWaterSpeed(double wavelength_m);

// Eq. 11's fade of Q near each wave's origin and antipode. With e1 <= e0 the smoothstep
// becomes a step at e0 (GLSL leaves it undefined), so e0 = e1 = 0 turns the fade off.
// Without it a wave loops within about Q A of o_i and -o_i (Michelic Fig. 8b); on an Earth-sized
// planet the default fade acts some 90 to 290 km out, far wider than needed but harmless.
struct WaveFade {
    double e0 = 1.0e-4;
    double e1 = 1.0e-3;
};

// The displaced sea surface at direction `unitDirection` (need not be exactly unit;
// it is normalised), sea radius r (m), time t (s): world position, m (Eq. 8).
glm::dvec3 gerstnerPosition(const std::vector<GerstnerWave>& waves, glm::dvec3 unitDirection, double seaRadius,
                            double time, const WaveFade& fade);

// Eq. 10's unit normal at the same point.
glm::dvec3 gerstnerNormal(const std::vector<GerstnerWave>& waves, glm::dvec3 unitDirection, double seaRadius,
                          double time, const WaveFade& fade);

// Radial displacement of the surface point over the sea sphere (|P| - r), m.
double gerstnerHeight(const std::vector<GerstnerWave>& waves, glm::dvec3 unitDirection, double seaRadius,
                      double time, const WaveFade& fade);

// "" when every wave is valid and sum Q_i A_i k_i <= 1 (no looping crests; a message
// naming the sum otherwise); else (unit origin within 1e-6, amplitude >= 0 and finite,
// wavelength > 0, steepness in [0, 1], finite speed and phase), else a message naming
// the first bad wave by index and field.
std::string validateWaves(const std::vector<GerstnerWave>& waves);

// Waves at the shore (shaders/ocean/ocean_waves.glsl is the GPU's copy of both).
// A wave breaks when its height 2A reaches 0.78 times the water depth d below the mean
// surface (McCowan's breaker index): the share of its amplitude the depth lets it keep,
// min(0.39 d / A, 1).
double shoalingKept(double amplitude_m, double waterDepth_m);

// The sea foam's mean cover at depth d from waves the pixel does not resolve: shoreward of its
// breaking depth a wave keeps the energy (0.39 d)^2, so it spends 2 x 0.39^2 d per metre of
// depth, most at its breaking line and none at the waterline; per unit of its energy A^2 that
// is its kept share s. The cover is sum A_i^2 s_i over the breaking waves (s_i < 1) over
// sum A_i^2, times the mean of the crest pattern ((1 + sin)/2)^4 the foam lies on, 35/128.
inline constexpr double kFoamCrestMean = 35.0 / 128.0;
double foamCover(const std::vector<GerstnerWave>& waves, double waterDepth_m);

}  // namespace planet::ocean
