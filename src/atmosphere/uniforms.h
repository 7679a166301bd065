// AtmosphereUniforms: the model's parameters as a std140 uniform block
// (BLOCK_ATMOSPHERE in shaders/common/bindings.glsl), mirror of
// shaders/atmosphere/uniforms.glsl, which rebuilds the AtmosphereParameters struct
// from it. Each vec3 is followed by the float that fills its 16 bytes (std140), and
// the offsets are static_asserted. Changing a parameter updates this buffer; no
// shader is recompiled.
#pragma once

#include <cstddef>
#include <string>

#include <glm/glm.hpp>

#include "atmosphere/model.h"
#include "atmosphere/tables.h"

namespace planet::atmosphere {

constexpr unsigned kAtmosphereUniformBinding = 1;  // BLOCK_ATMOSPHERE (static_asserted in uniforms.cpp)

struct AtmosphereUniforms {
    glm::vec3 solarIrradiance;        // W m^-2 nm^-1 at 680, 550, 440 nm
    float sunAngularRadius;           // rad
    float bottomRadius;               // km
    float topRadius;                  // km
    float miePhaseG;                  // Cornette-Shanks asymmetry
    float muSMin;                     // cosine of the lowest sun the tables cover
    glm::vec3 rayleighScattering;     // 1/km
    float elekRayleighPhase;          // 1: Elek's Rayleigh phase (Eq. 15) at render time, else 0
    glm::vec3 mieScattering;          // 1/km
    float padding0;
    glm::vec3 mieExtinction;          // 1/km
    float padding1;
    glm::vec3 absorptionExtinction;   // 1/km
    float padding2;
    glm::vec3 groundAlbedo;
    float padding3;
    glm::vec4 profiles[3][2][2];      // [rayleigh, mie, absorption][layer][(width, exp_term, exp_scale, linear), (constant)]
};
static_assert(sizeof(AtmosphereUniforms) == 7 * 16 + 12 * 16, "AtmosphereUniforms must match std140");
static_assert(offsetof(AtmosphereUniforms, bottomRadius) == 16 && offsetof(AtmosphereUniforms, rayleighScattering) == 32 &&
                  offsetof(AtmosphereUniforms, mieScattering) == 48 && offsetof(AtmosphereUniforms, mieExtinction) == 64 &&
                  offsetof(AtmosphereUniforms, absorptionExtinction) == 80 &&
                  offsetof(AtmosphereUniforms, groundAlbedo) == 96 && offsetof(AtmosphereUniforms, profiles) == 112,
              "AtmosphereUniforms offsets must match std140 (shaders/atmosphere/uniforms.glsl)");

AtmosphereUniforms makeAtmosphereUniforms(const AtmosphereParameters& p);

// #defines the shared model code needs in GLSL: table sizes and texture types.
std::string atmosphereShaderDefines(const TableSizes& sizes);

}  // namespace planet::atmosphere
