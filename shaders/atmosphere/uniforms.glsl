// The atmosphere's parameters as a uniform block; mirror of src/atmosphere/uniforms.h.
// Include after definitions.glsl; atmosphereParameters() rebuilds the struct the
// model functions take.
layout(std140, binding = 1) uniform AtmosphereUniforms {
    vec4 solarIrradiance;       // rgb; w: sun angular radius
    vec4 radii;                 // bottom, top (km), Mie g, mu_s_min
    vec4 rayleighScattering;    // rgb; w: Elek phase flag
    vec4 mieScattering;         // rgb; w: 1 = render with Elek's 3D table (lighting.frag)
    vec4 mieExtinction;
    vec4 absorptionExtinction;
    vec4 groundAlbedo;
    vec4 profiles[12];          // [profile][layer][2]: (width, exp_term, exp_scale, linear), (constant)
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
    a.solar_irradiance = atmosphereUniforms.solarIrradiance.rgb;
    a.sun_angular_radius = atmosphereUniforms.solarIrradiance.w;
    a.bottom_radius = atmosphereUniforms.radii.x;
    a.top_radius = atmosphereUniforms.radii.y;
    a.rayleigh_density = densityProfile(0);
    a.rayleigh_scattering = atmosphereUniforms.rayleighScattering.rgb;
    a.mie_density = densityProfile(1);
    a.mie_scattering = atmosphereUniforms.mieScattering.rgb;
    a.mie_extinction = atmosphereUniforms.mieExtinction.rgb;
    a.mie_phase_function_g = atmosphereUniforms.radii.z;
    a.absorption_density = densityProfile(2);
    a.absorption_extinction = atmosphereUniforms.absorptionExtinction.rgb;
    a.ground_albedo = atmosphereUniforms.groundAlbedo.rgb;
    a.mu_s_min = atmosphereUniforms.radii.w;
    a.elek_rayleigh_phase = atmosphereUniforms.rayleighScattering.w;
    return a;
}
