// AtmosphereUniforms: the model's parameters as a std140 uniform block
// (binding 1), mirror of shaders/atmosphere/uniforms.glsl, which rebuilds the
// AtmosphereParameters struct from it. Only vec4 members, so the C++ layout
// matches std140 without padding rules. Changing a parameter updates this
// buffer; no shader is recompiled.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "atmosphere/model.h"
#include "atmosphere/tables.h"

namespace planet::atmosphere {

constexpr unsigned kAtmosphereUniformBinding = 1;

struct AtmosphereUniforms {
    glm::vec4 solarIrradiance;        // rgb; w: sun angular radius (rad)
    glm::vec4 radii;                  // x: bottom, y: top (km); z: Mie g; w: mu_s_min
    glm::vec4 rayleighScattering;     // rgb (1/km); w: 1 for Elek's Rayleigh phase (Eq. 15)
    glm::vec4 mieScattering;          // rgb (1/km); w: 1 to render with Elek's 3D table (render-time choice)
    glm::vec4 mieExtinction;          // rgb (1/km)
    glm::vec4 absorptionExtinction;   // rgb (1/km)
    glm::vec4 groundAlbedo;           // rgb
    glm::vec4 profiles[3][2][2];      // [rayleigh, mie, absorption][layer][(width, exp_term, exp_scale, linear), (constant)]
};
static_assert(sizeof(AtmosphereUniforms) == 7 * 16 + 12 * 16, "AtmosphereUniforms must match std140");

AtmosphereUniforms makeAtmosphereUniforms(const AtmosphereParameters& p);

// #defines the shared model code needs in GLSL: table sizes and texture types.
std::string atmosphereShaderDefines(const TableSizes& sizes);

}  // namespace planet::atmosphere
