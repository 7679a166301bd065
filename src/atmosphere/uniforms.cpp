#include "atmosphere/uniforms.h"

#include "render/bindings.h"

namespace planet::atmosphere {

static_assert(kAtmosphereUniformBinding == binding::BLOCK_ATMOSPHERE);

namespace {

void packProfile(const DensityProfile& profile, glm::vec4 (&out)[2][2]) {
    for (int i = 0; i < 2; ++i) {
        const DensityProfileLayer& l = profile.layers[i];
        out[i][0] = glm::vec4(l.width, l.exp_term, l.exp_scale, l.linear_term);
        out[i][1] = glm::vec4(l.constant_term, 0.0f, 0.0f, 0.0f);
    }
}

}  // namespace

AtmosphereUniforms makeAtmosphereUniforms(const AtmosphereParameters& p) {
    AtmosphereUniforms u{};
    u.solarIrradiance = glm::vec3(p.solar_irradiance);
    u.sunAngularRadius = static_cast<float>(p.sun_angular_radius);
    u.bottomRadius = static_cast<float>(p.bottom_radius);
    u.topRadius = static_cast<float>(p.top_radius);
    u.miePhaseG = static_cast<float>(p.mie_phase_function_g);
    u.muSMin = static_cast<float>(p.mu_s_min);
    u.rayleighScattering = glm::vec3(p.rayleigh_scattering);
    u.elekRayleighPhase = static_cast<float>(p.elek_rayleigh_phase);
    u.mieScattering = glm::vec3(p.mie_scattering);
    u.mieExtinction = glm::vec3(p.mie_extinction);
    u.absorptionExtinction = glm::vec3(p.absorption_extinction);
    u.groundAlbedo = glm::vec3(p.ground_albedo);
    packProfile(p.rayleigh_density, u.profiles[0]);
    packProfile(p.mie_density, u.profiles[1]);
    packProfile(p.absorption_density, u.profiles[2]);
    return u;
}

std::string atmosphereShaderDefines(const TableSizes& s) {
    auto define = [](const char* name, int value) { return "#define " + std::string(name) + " " + std::to_string(value) + "\n"; };
    return define("TRANSMITTANCE_TEXTURE_WIDTH", s.transmittance_width) +
           define("TRANSMITTANCE_TEXTURE_HEIGHT", s.transmittance_height) +
           define("SCATTERING_TEXTURE_R_SIZE", s.scattering_r) + define("SCATTERING_TEXTURE_MU_SIZE", s.scattering_mu) +
           define("SCATTERING_TEXTURE_MU_S_SIZE", s.scattering_mu_s) +
           define("SCATTERING_TEXTURE_NU_SIZE", s.scattering_nu) +
           define("IRRADIANCE_TEXTURE_WIDTH", s.irradiance_width) +
           define("IRRADIANCE_TEXTURE_HEIGHT", s.irradiance_height) +
           define("ELEK_TEXTURE_R_SIZE", s.elek_r) + define("ELEK_TEXTURE_MU_SIZE", s.elek_mu) +
           define("ELEK_TEXTURE_MU_S_SIZE", s.elek_mu_s) +
           "#define TransmittanceTexture sampler2D\n#define ScatteringTexture sampler3D\n"
           "#define IrradianceTexture sampler2D\n";
}

}  // namespace planet::atmosphere
