// The atmosphere's parameters as a uniform block; mirror of src/atmosphere/uniforms.h.
// Include after definitions.glsl; atmosphereParameters() rebuilds the struct the
// model functions take.
#include "common/bindings.glsl"

layout(std140, binding = BLOCK_ATMOSPHERE) uniform AtmosphereBlock {
    vec3 solarIrradiance;        // W m^-2 nm^-1
    float sunAngularRadius;      // rad
    float bottomRadius;          // km
    float topRadius;             // km
    float miePhaseG;
    float muSMin;
    vec3 rayleighScattering;     // 1/km
    float elekRayleighPhase;     // 1: Elek's Rayleigh phase (Eq. 15)
    vec3 mieScattering;
    float padding0;
    vec3 mieExtinction;
    float padding1;
    vec3 absorptionExtinction;
    float padding2;
    vec3 groundAlbedo;
    float padding3;
    vec4 profiles[12];           // [profile][layer][2]: (width, exp_term, exp_scale, linear), (constant)
} atmosphereUniforms;

DensityProfile densityProfile(int index) {
    DensityProfile p;
    for (int layer = 0; layer < 2; ++layer) {
        vec4 a = atmosphereUniforms.profiles[index * 4 + layer * 2];
        vec4 b = atmosphereUniforms.profiles[index * 4 + layer * 2 + 1];
        p.layers[layer] = DensityProfileLayer(a.x, a.y, a.z, a.w, b.x);
    }
    return p;
}

AtmosphereParameters atmosphereParameters() {
    AtmosphereParameters a;
    a.solar_irradiance = atmosphereUniforms.solarIrradiance;
    a.sun_angular_radius = atmosphereUniforms.sunAngularRadius;
    a.bottom_radius = atmosphereUniforms.bottomRadius;
    a.top_radius = atmosphereUniforms.topRadius;
    a.rayleigh_density = densityProfile(0);
    a.rayleigh_scattering = atmosphereUniforms.rayleighScattering;
    a.mie_density = densityProfile(1);
    a.mie_scattering = atmosphereUniforms.mieScattering;
    a.mie_extinction = atmosphereUniforms.mieExtinction;
    a.mie_phase_function_g = atmosphereUniforms.miePhaseG;
    a.absorption_density = densityProfile(2);
    a.absorption_extinction = atmosphereUniforms.absorptionExtinction;
    a.ground_albedo = atmosphereUniforms.groundAlbedo;
    a.mu_s_min = atmosphereUniforms.muSMin;
    a.elek_rayleigh_phase = atmosphereUniforms.elekRayleighPhase;
    return a;
}
