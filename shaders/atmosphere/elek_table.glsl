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
// ELEK_TEXTURE_MU_S_SIZE and the ScatteringTexture type. Include before
// rendering.glsl: the render-time lookups there take either table
// (GetCombinedScatteringFrom), so sky and aerial perspective are written once.

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
// r, with r^2 - R^2 given apart (rho2: exact for a camera metres above the ground, where
// the horizon's cosine -rho / r from a float r would be off).
vec3 GetElekTextureUvwFromRRho2MuMuS(IN(AtmosphereParameters) atmosphere, Length r, Area rho2, Number mu, Number mu_s,
                                     bool ray_r_mu_intersects_ground) {
    Length H = sqrt((atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius));
    Length rho = SafeSqrt(rho2);
    Number u_r = GetTextureCoordFromUnitRange(clamp(rho / H, Number(0.0), Number(1.0)), ELEK_TEXTURE_R_SIZE);

    Number mu_horizon = -rho / r;
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

vec3 GetElekTextureUvwFromRMuMuS(IN(AtmosphereParameters) atmosphere, Length r, Number mu, Number mu_s,
                                 bool ray_r_mu_intersects_ground) {
    return GetElekTextureUvwFromRRho2MuMuS(atmosphere, r, (r - atmosphere.bottom_radius) * (r + atmosphere.bottom_radius),
                                           mu, mu_s, ray_r_mu_intersects_ground);
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

// The same with r^2 - R^2 given apart (see GetElekTextureUvwFromRRho2MuMuS).
Spectrum GetCombinedScatteringElekRho2(IN(AtmosphereParameters) atmosphere,
                                       IN(ScatteringTexture) elek_scattering_texture,
                                       IN(ScatteringTexture) elek_single_mie_scattering_texture, Length r, Area rho2,
                                       Number mu, Number mu_s, bool ray_r_mu_intersects_ground,
                                       OUT(Spectrum) single_mie_scattering) {
    vec3 uvw = GetElekTextureUvwFromRRho2MuMuS(atmosphere, r, rho2, mu, mu_s, ray_r_mu_intersects_ground);
    single_mie_scattering = Spectrum(texture(elek_single_mie_scattering_texture, uvw));
    return Spectrum(texture(elek_scattering_texture, uvw));
}
