// Elek's 3D scattering table: the second, smaller parametrization, shared by GLSL and C++.
//
// Elek (2009) §4.1.1 drops the sun-view azimuth omega from Bruneton's 4D table
// (r, mu, mu_s, nu) and keeps a 3D texture over altitude, view zenith and sun
// zenith, remapped as
//   U = sqrt((r^2 - Rp^2) / (Ra^2 - Rp^2))                    (= rho / H)
//   V = (1 + mu) / 2
//   W = (1 - exp(-2.8 mu_s - 0.8)) / (1 - exp(-3.6))          (clamped to [0, 1]: mu_s >= -0.286)
// Every view direction then implicitly has omega = 0 (the sun in the view's
// vertical half-plane). The phase functions stay out of the table and are
// applied per fragment with the real nu (Elek §4.1.2), which restores most of
// the azimuthal variation: what is lost is the azimuth dependence of the
// phase-free radiance (mainly the planet's shadow at dusk, and multiple
// scattering's own azimuth dependence).
//
// Here the table is not integrated anew: each texel is Bruneton's 4D table
// looked up at omega = 0, i.e. nu = mu mu_s + sqrt((1 - mu^2)(1 - mu_s^2)), so
// the two parametrizations share one model and differ only by the dropped axis
// and the sampling (compareElekWith4D in src/atmosphere/elek_table.cpp measures
// the difference). Layout, like the 4D tables: the scattering table's rgb is
// Rayleigh + multiple orders (phase-free), the single Mie table's rgb single
// Mie (phase-free); x = mu_s, y = mu, z = r.
//
// One deviation from Elek's V: mu is split at the horizon like the 4D table,
// V in [0, 1/2) for rays that hit the ground, [1/2, 1] for the others, each
// half linear in mu between its ends (-1 .. mu_horizon, mu_horizon .. 1). The
// radiance is discontinuous at the horizon; with a single linear V a texel
// would straddle it and blend ground and sky rays. At the ground mu_horizon = 0
// and the split V equals Elek's (1 + mu) / 2 up to the texel-centre mapping.
//
// Needs definitions.glsl, functions.glsl (GetScattering, phase functions,
// GetTransmittance...), the sizes ELEK_TEXTURE_R_SIZE, ELEK_TEXTURE_MU_SIZE,
// ELEK_TEXTURE_MU_S_SIZE and the ScatteringTexture type.

const Number ELEK_W_SLOPE = 2.8;   // Elek's W: exp(-2.8 mu_s - 0.8)
const Number ELEK_W_OFFSET = 0.8;

// Cosine of the horizon's zenith angle seen from radius r (<= 0).
Number ElekHorizonMu(IN(AtmosphereParameters) atmosphere, Length r) {
    return -SafeSqrt((r - atmosphere.bottom_radius) * (r + atmosphere.bottom_radius)) / r;
}

// The largest nu the directions allow: sun in the view's vertical half-plane, omega = 0.
Number ElekNuAtZeroAzimuth(Number mu, Number mu_s) {
    return ClampCosine(mu * mu_s + SafeSqrt((1.0 - mu * mu) * (1.0 - mu_s * mu_s)));
}

// Texture coordinates (x: mu_s, y: mu, z: r) of Elek's table.
vec3 GetElekTextureUvwFromRMuMuS(IN(AtmosphereParameters) atmosphere, Length r, Number mu, Number mu_s,
                                 bool ray_r_mu_intersects_ground) {
    Length H = sqrt((atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius));
    Length rho = SafeSqrt((r - atmosphere.bottom_radius) * (r + atmosphere.bottom_radius));
    Number u_r = GetTextureCoordFromUnitRange(clamp(rho / H, Number(0.0), Number(1.0)), ELEK_TEXTURE_R_SIZE);

    Number mu_horizon = ElekHorizonMu(atmosphere, r);
    Number u_mu;
    if (ray_r_mu_intersects_ground) {
        Number x = clamp((mu + 1.0) / (mu_horizon + 1.0), Number(0.0), Number(1.0));
        u_mu = 0.5 * GetTextureCoordFromUnitRange(x, ELEK_TEXTURE_MU_SIZE / 2);
    } else {
        Number x = clamp((mu - mu_horizon) / (1.0 - mu_horizon), Number(0.0), Number(1.0));
        u_mu = 0.5 + 0.5 * GetTextureCoordFromUnitRange(x, ELEK_TEXTURE_MU_SIZE / 2);
    }

    Number w = (1.0 - exp(-ELEK_W_SLOPE * mu_s - ELEK_W_OFFSET)) / (1.0 - exp(-ELEK_W_SLOPE - ELEK_W_OFFSET));
    Number u_mu_s = GetTextureCoordFromUnitRange(clamp(w, Number(0.0), Number(1.0)), ELEK_TEXTURE_MU_S_SIZE);
    return vec3(u_mu_s, u_mu, u_r);
}

// The inverse, for texture coordinates in the table's range.
void GetRMuMuSFromElekTextureUvw(IN(AtmosphereParameters) atmosphere, IN(vec3) uvw, OUT(Length) r, OUT(Number) mu,
                                 OUT(Number) mu_s, OUT(bool) ray_r_mu_intersects_ground) {
    Length H = sqrt((atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius));
    Length rho = H * GetUnitRangeFromTextureCoord(uvw.z, ELEK_TEXTURE_R_SIZE);
    r = sqrt(rho * rho + atmosphere.bottom_radius * atmosphere.bottom_radius);

    Number mu_horizon = ElekHorizonMu(atmosphere, r);
    if (uvw.y < 0.5) {
        Number x = GetUnitRangeFromTextureCoord(2.0 * uvw.y, ELEK_TEXTURE_MU_SIZE / 2);
        mu = ClampCosine(-1.0 + x * (mu_horizon + 1.0));
        ray_r_mu_intersects_ground = true;
    } else {
        Number x = GetUnitRangeFromTextureCoord(2.0 * uvw.y - 1.0, ELEK_TEXTURE_MU_SIZE / 2);
        mu = ClampCosine(mu_horizon + x * (1.0 - mu_horizon));
        ray_r_mu_intersects_ground = false;
    }

    Number w = GetUnitRangeFromTextureCoord(uvw.x, ELEK_TEXTURE_MU_S_SIZE);
    mu_s = ClampCosine(-(log(1.0 - w * (1.0 - exp(-ELEK_W_SLOPE - ELEK_W_OFFSET))) + ELEK_W_OFFSET) / ELEK_W_SLOPE);
}

// One texel of Elek's table from the 4D tables at omega = 0: returns the
// Rayleigh + multiple part, the single Mie part in `single_mie_scattering`,
// both phase-free.
Spectrum ComputeElekTableTexture(IN(AtmosphereParameters) atmosphere, IN(ScatteringTexture) scattering_texture,
                                 IN(ScatteringTexture) single_mie_scattering_texture, IN(vec3) frag_coord,
                                 OUT(Spectrum) single_mie_scattering) {
    const vec3 ELEK_TEXTURE_SIZE = vec3(ELEK_TEXTURE_MU_S_SIZE, ELEK_TEXTURE_MU_SIZE, ELEK_TEXTURE_R_SIZE);
    Length r;
    Number mu;
    Number mu_s;
    bool ray_r_mu_intersects_ground;
    GetRMuMuSFromElekTextureUvw(atmosphere, frag_coord / ELEK_TEXTURE_SIZE, r, mu, mu_s, ray_r_mu_intersects_ground);
    Number nu = ElekNuAtZeroAzimuth(mu, mu_s);
    single_mie_scattering =
        GetScattering(atmosphere, single_mie_scattering_texture, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
    return GetScattering(atmosphere, scattering_texture, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
}

// Elek table lookup: Rayleigh + multiple part returned, single Mie in
// `single_mie_scattering`, both phase-free (nu is not an argument: omega = 0).
Spectrum GetCombinedScatteringElek(IN(AtmosphereParameters) atmosphere, IN(ScatteringTexture) elek_scattering_texture,
                                   IN(ScatteringTexture) elek_single_mie_scattering_texture, Length r, Number mu,
                                   Number mu_s, bool ray_r_mu_intersects_ground,
                                   OUT(Spectrum) single_mie_scattering) {
    vec3 uvw = GetElekTextureUvwFromRMuMuS(atmosphere, r, mu, mu_s, ray_r_mu_intersects_ground);
    single_mie_scattering = Spectrum(texture(elek_single_mie_scattering_texture, uvw));
    return Spectrum(texture(elek_scattering_texture, uvw));
}

// Phase functions at the real nu (Elek §4.1.2); as ApplyPhaseFunctions in rendering.glsl.
Spectrum ApplyPhaseFunctionsElek(IN(AtmosphereParameters) atmosphere, IN(Spectrum) scattering,
                                 IN(Spectrum) single_mie_scattering, Number nu) {
    return scattering * RenderRayleighPhaseFunction(atmosphere, nu) +
           single_mie_scattering * MiePhaseFunction(atmosphere.mie_phase_function_g, nu);
}

// GetSkyRadiance (rendering.glsl) with Elek's table.
Spectrum GetSkyRadianceElek(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                            IN(ScatteringTexture) elek_scattering_texture,
                            IN(ScatteringTexture) elek_single_mie_scattering_texture, IN(vec3) camera_position,
                            IN(vec3) view_ray, IN(vec3) sun_direction, OUT(Spectrum) transmittance) {
    ViewRay ray = ViewRayInAtmosphere(atmosphere, camera_position, view_ray, sun_direction);
    if (!ray.inside) {
        transmittance = Spectrum(1.0);
        return Spectrum(0.0);
    }
    Length r = ray.r;
    Number mu = ray.mu;
    Number mu_s = ray.mu_s;
    Number nu = ray.nu;
    bool ray_r_mu_intersects_ground = RayIntersectsGround(atmosphere, r, mu);

    transmittance = ray_r_mu_intersects_ground
                        ? Spectrum(0.0)
                        : GetTransmittanceToTopAtmosphereBoundary(atmosphere, transmittance_texture, r, mu);
    Spectrum single_mie_scattering;
    Spectrum scattering =
        GetCombinedScatteringElek(atmosphere, elek_scattering_texture, elek_single_mie_scattering_texture, r, mu,
                                  mu_s, ray_r_mu_intersects_ground, single_mie_scattering);
    return ApplyPhaseFunctionsElek(atmosphere, scattering, single_mie_scattering, nu) * NightFade(atmosphere, mu_s);
}

// ScatteringBetween (rendering.glsl) with Elek's table: phase-free in-scattering
// between (r, mu) and the point at distance d, L(a->b) = L(a->inf) - T(a->b) L(b->inf).
Spectrum ScatteringBetweenElek(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                               IN(ScatteringTexture) elek_scattering_texture,
                               IN(ScatteringTexture) elek_single_mie_scattering_texture, Length r, Number mu,
                               Number mu_s, Number nu, Length d, OUT(Spectrum) transmittance,
                               OUT(Spectrum) single_mie_scattering) {
    bool ray_r_mu_intersects_ground = RayIntersectsGround(atmosphere, r, mu);
    transmittance = GetTransmittance(atmosphere, transmittance_texture, r, mu, d, ray_r_mu_intersects_ground);
    Spectrum scattering =
        GetCombinedScatteringElek(atmosphere, elek_scattering_texture, elek_single_mie_scattering_texture, r, mu,
                                  mu_s, ray_r_mu_intersects_ground, single_mie_scattering);
    Length r_p = ClampRadius(atmosphere, sqrt(d * d + 2.0 * r * mu * d + r * r));
    Number mu_p = ClampCosine((r * mu + d) / r_p);
    Number mu_s_p = ClampCosine((r * mu_s + d * nu) / r_p);
    Spectrum single_mie_scattering_p;
    Spectrum scattering_p =
        GetCombinedScatteringElek(atmosphere, elek_scattering_texture, elek_single_mie_scattering_texture, r_p, mu_p,
                                  mu_s_p, ray_r_mu_intersects_ground, single_mie_scattering_p);
    single_mie_scattering = max(single_mie_scattering - transmittance * single_mie_scattering_p, Spectrum(0.0));
    return max(scattering - transmittance * scattering_p, Spectrum(0.0));
}

// GetSkyRadianceToPointAlongRay (rendering.glsl) with Elek's table, with the
// same Sperlhofer 5.1.2 horizon blend and 5.1.3 Mie fade.
Spectrum GetSkyRadianceToPointAlongRayElek(IN(AtmosphereParameters) atmosphere,
                                           IN(TransmittanceTexture) transmittance_texture,
                                           IN(ScatteringTexture) elek_scattering_texture,
                                           IN(ScatteringTexture) elek_single_mie_scattering_texture,
                                           IN(vec3) camera_position, IN(vec3) view_ray, Length distance,
                                           IN(vec3) sun_direction, OUT(Spectrum) transmittance) {
    ViewRay ray = ViewRayInAtmosphere(atmosphere, camera_position, view_ray, sun_direction);
    if (!ray.inside) {
        transmittance = Spectrum(1.0);
        return Spectrum(0.0);
    }
    Length r = ray.r;
    Number mu = ray.mu;
    Number mu_s = ray.mu_s;
    Number nu = ray.nu;
    Length d = max(distance - ray.skipped, Length(0.0));

    const Number EPS = 0.004;
    Number mu_horizon = ElekHorizonMu(atmosphere, r);
    Spectrum single_mie_scattering;
    Spectrum scattering;
    if (abs(mu - mu_horizon) < EPS) {
        Number a = (mu - mu_horizon + EPS) / (2.0 * EPS);
        Spectrum transmittance_below;
        Spectrum mie_below;
        Spectrum below = ScatteringBetweenElek(atmosphere, transmittance_texture, elek_scattering_texture,
                                               elek_single_mie_scattering_texture, r, mu_horizon - EPS, mu_s, nu, d,
                                               transmittance_below, mie_below);
        Spectrum transmittance_above;
        Spectrum mie_above;
        Spectrum above = ScatteringBetweenElek(atmosphere, transmittance_texture, elek_scattering_texture,
                                               elek_single_mie_scattering_texture, r, mu_horizon + EPS, mu_s, nu, d,
                                               transmittance_above, mie_above);
        scattering = mix(below, above, a);
        single_mie_scattering = mix(mie_below, mie_above, a);
        transmittance = mix(transmittance_below, transmittance_above, a);
    } else {
        scattering = ScatteringBetweenElek(atmosphere, transmittance_texture, elek_scattering_texture,
                                           elek_single_mie_scattering_texture, r, mu, mu_s, nu, d, transmittance,
                                           single_mie_scattering);
    }
    single_mie_scattering = single_mie_scattering * smoothstep(Number(0.0), Number(0.01), mu_s);
    return ApplyPhaseFunctionsElek(atmosphere, scattering, single_mie_scattering, nu) * NightFade(atmosphere, mu_s);
}
