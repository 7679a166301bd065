// The waves as the GPU takes them: one OceanWave record per wave (shaders/ocean/
// gerstner.glsl), refreshed every frame because each carries its phase and great-circle
// frame at the camera (see that file for why), computed here in double.
//
// Also the CPU twin of the GPU's camera-relative evaluation, in float through the very
// GLSL of gerstner.glsl: tests compare it (and the GPU) with the double reference of
// ocean/waves.h.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "ocean/waves.h"

namespace planet::ocean {

// Mirror of the GLSL struct OceanWave (std430, 64 bytes).
struct OceanWaveGpu {
    glm::vec4 originKr;  // o_i, k_i r
    glm::vec4 frameE;    // e (unit tangent at o_i towards the camera), sin(tc)
    glm::vec4 shape;     // A_i, Q_i, cos(tc), phase at the camera in [-pi, pi)
    glm::vec4 scale;     // k_i, wavelength, slope variance of this and all shorter waves, 0
};

// The records for a camera at `cameraPosition` (world, m) over a sea of radius
// seaRadius (m) at time t (s), longest wave first.
std::vector<OceanWaveGpu> packWaves(const std::vector<GerstnerWave>& waves, const glm::dvec3& cameraPosition,
                                    double seaRadius, double time);

// What the tessellation evaluation shader computes for the unit direction `direction`:
// the displacement from the sea sphere (m, world axes; Eq. 8 without v r) using the
// packed records, with every wave at full level of detail. In float via gerstner.glsl.
glm::vec3 gpuPathDisplacement(const std::vector<OceanWaveGpu>& records, const glm::dvec3& direction,
                              const glm::dvec3& cameraPosition, const WaveFade& fade);

// Slope variance (mean square slope, both axes) of a clean sea under a wind of this speed,
// Cox & Munk 1954: 0.003 + 5.12e-3 U (their wind was measured 12.5 m up; we pass the 10 m
// wind, about 2 % slower over the sea).
double coxMunkSlopeVariance(double windSpeedMps);

// The slope variance the shading adds for ripples shorter than any wave of the set: Cox &
// Munk's total less what the waves carry (sum (A k)^2 / 2), at least a tenth of the total
// (ripples under the shortest wave are always there).
double subgridSlopeVariance(const std::vector<GerstnerWave>& waves, double windSpeedMps);

// Largest possible radial displacement of the surface: sum of amplitudes, m.
double maxWaveHeight(const std::vector<GerstnerWave>& waves);

}  // namespace planet::ocean
