// The atmosphere model's shared GLSL compiled as C++ in double precision.
//
// shaders/atmosphere/{definitions,functions,rendering,elek_table}.glsl are written in the
// subset of GLSL that is also C++. Here they are included into a class whose
// members stand in for the GLSL globals (the table sizes) and whose member
// functions are then exactly the GPU's functions, evaluated in double. This is
// the CPU reference every GPU table and render lookup is tested against
// (STYLE habit 1; Bruneton's reference/functions.cc does the same).
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include "atmosphere/tables.h"

namespace planet::atmosphere {

// GLSL names for the shared files, in double precision.
namespace glsl {
using Number = double;
using Length = double;
using Area = double;
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using ivec2 = glm::ivec2;
using Spectrum = glm::dvec3;
using glm::clamp;
using glm::cos;
using glm::dot;
using glm::exp;
using glm::floor;
using glm::length;
using glm::log;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::pow;
using glm::sin;
using glm::smoothstep;
using glm::sqrt;
using std::abs;
using planet::atmosphere::texelFetch;
using planet::atmosphere::texture;
#define IN(x) const x&
#define OUT(x) x&
#include "shaders/atmosphere/definitions.glsl"

class Model {
public:
    // precompute: read the transmittance table as the precomputation does
    // (TRANSMITTANCE_LOG_LOOKUP in functions.glsl); false: as the frame does.
    explicit Model(const TableSizes& sizes, bool precompute = false)
        : TRANSMITTANCE_LOG_LOOKUP(precompute),
          TRANSMITTANCE_TEXTURE_WIDTH(sizes.transmittance_width),
          TRANSMITTANCE_TEXTURE_HEIGHT(sizes.transmittance_height),
          SCATTERING_TEXTURE_R_SIZE(sizes.scattering_r),
          SCATTERING_TEXTURE_MU_SIZE(sizes.scattering_mu),
          SCATTERING_TEXTURE_MU_S_SIZE(sizes.scattering_mu_s),
          SCATTERING_TEXTURE_NU_SIZE(sizes.scattering_nu),
          IRRADIANCE_TEXTURE_WIDTH(sizes.irradiance_width),
          IRRADIANCE_TEXTURE_HEIGHT(sizes.irradiance_height),
          ELEK_TEXTURE_R_SIZE(sizes.elek_r),
          ELEK_TEXTURE_MU_SIZE(sizes.elek_mu),
          ELEK_TEXTURE_MU_S_SIZE(sizes.elek_mu_s) {}

    using TransmittanceTexture = Table2D;
    using ScatteringTexture = Table3D;
    using IrradianceTexture = Table2D;

    const bool TRANSMITTANCE_LOG_LOOKUP;
    const int TRANSMITTANCE_TEXTURE_WIDTH;
    const int TRANSMITTANCE_TEXTURE_HEIGHT;
    const int SCATTERING_TEXTURE_R_SIZE;
    const int SCATTERING_TEXTURE_MU_SIZE;
    const int SCATTERING_TEXTURE_MU_S_SIZE;
    const int SCATTERING_TEXTURE_NU_SIZE;
    const int IRRADIANCE_TEXTURE_WIDTH;
    const int IRRADIANCE_TEXTURE_HEIGHT;
    const int ELEK_TEXTURE_R_SIZE;
    const int ELEK_TEXTURE_MU_SIZE;
    const int ELEK_TEXTURE_MU_S_SIZE;

    // The shared functions, as members (`const Number PI` becomes a constant member).
#include "shaders/atmosphere/functions.glsl"
#include "shaders/atmosphere/elek_table.glsl"
#include "shaders/atmosphere/rendering.glsl"
};

#undef IN
#undef OUT
}  // namespace glsl

using glsl::AtmosphereParameters;
using glsl::DensityProfile;
using glsl::DensityProfileLayer;
using glsl::Model;

}  // namespace planet::atmosphere
