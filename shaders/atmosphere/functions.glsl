// Atmospheric scattering: the model's functions, shared by GLSL and C++.
//
// A port of Bruneton's 2017 reformulation of "Precomputed Atmospheric
// Scattering" (Bruneton & Neyret 2008), the model Sperlhofer ch. 2 and 4.6
// describe and Elek builds on: Rayleigh and Mie scattering with exponential
// density (Elek Eq. 8), ozone absorption, transmittance (Elek Eq. 9, Sperlhofer
// Eq. 2-6/2-7), single scattering (Elek Eq. 10), scattering density and
// multiple scattering order by order (Elek Eq. 12-14, Sperlhofer Eq. 2-10/2-11),
// ground irradiance (Elek Eq. 16, Sperlhofer Eq. 2-12), and the lookups used
// at render time (sky radiance, aerial perspective, sun and sky irradiance).
//
// Organisation: geometry -> transmittance -> single scattering -> table
// coordinates -> multiple scattering -> irradiance -> rendering. Needs
// definitions.glsl, the table sizes (TRANSMITTANCE_TEXTURE_WIDTH, ...) and the
// texture types (TransmittanceTexture, ...), which the including code provides.
// Written in the GLSL subset that is also C++: no swizzles, explicit Number().

const Number PI = 3.14159265358979323846;

// ---------------------------------------------------------------- geometry

Number ClampCosine(Number mu) { return clamp(mu, Number(-1.0), Number(1.0)); }
Length ClampDistance(Length d) { return max(d, Length(0.0)); }
Length ClampRadius(IN(AtmosphereParameters) atmosphere, Length r) {
    return clamp(r, atmosphere.bottom_radius, atmosphere.top_radius);
}
Length SafeSqrt(Area a) { return sqrt(max(a, Area(0.0))); }

// Discriminant of the ray-sphere quadratic, r^2 (mu^2 - 1) + R^2, written as
// (r mu)^2 - (r - R)(r + R): near the ground r - R is small and exact, where
// the textbook form subtracts numbers of size 4e7 km^2 (horizon precision).
Area RaySphereDiscriminant(Length r, Number mu, Length sphere_radius) {
    return (r * mu) * (r * mu) - (r - sphere_radius) * (r + sphere_radius);
}

// Distance along a ray from radius r with view zenith cosine mu to the top
// boundary (the ray is inside the atmosphere).
Length DistanceToTopAtmosphereBoundary(IN(AtmosphereParameters) atmosphere, Length r, Number mu) {
    return ClampDistance(-r * mu + SafeSqrt(RaySphereDiscriminant(r, mu, atmosphere.top_radius)));
}

Length DistanceToBottomAtmosphereBoundary(IN(AtmosphereParameters) atmosphere, Length r, Number mu) {
    return ClampDistance(-r * mu - SafeSqrt(RaySphereDiscriminant(r, mu, atmosphere.bottom_radius)));
}

bool RayIntersectsGround(IN(AtmosphereParameters) atmosphere, Length r, Number mu) {
    return mu < 0.0 && RaySphereDiscriminant(r, mu, atmosphere.bottom_radius) >= 0.0;
}

// ----------------------------------------------------------- transmittance

Number GetLayerDensity(IN(DensityProfileLayer) layer, Length altitude) {
    Number density = layer.exp_term * exp(layer.exp_scale * altitude) + layer.linear_term * altitude +
                     layer.constant_term;
    return clamp(density, Number(0.0), Number(1.0));
}

Number GetProfileDensity(IN(DensityProfile) profile, Length altitude) {
    return altitude < profile.layers[0].width ? GetLayerDensity(profile.layers[0], altitude)
                                              : GetLayerDensity(profile.layers[1], altitude);
}

// Integral of the density along the ray to the top boundary (trapezoidal rule).
Length ComputeOpticalLengthToTopAtmosphereBoundary(IN(AtmosphereParameters) atmosphere,
                                                   IN(DensityProfile) profile, Length r, Number mu) {
    const int SAMPLE_COUNT = 500;
    Length dx = DistanceToTopAtmosphereBoundary(atmosphere, r, mu) / Number(SAMPLE_COUNT);
    Length result = 0.0;
    for (int i = 0; i <= SAMPLE_COUNT; ++i) {
        Length d_i = Number(i) * dx;
        Length r_i = sqrt(d_i * d_i + 2.0 * r * mu * d_i + r * r);
        Number y_i = GetProfileDensity(profile, r_i - atmosphere.bottom_radius);
        Number weight_i = i == 0 || i == SAMPLE_COUNT ? 0.5 : 1.0;
        result += y_i * weight_i * dx;
    }
    return result;
}

// Transmittance to the top boundary: exp(-optical depth) (Elek Eq. 9, Sperlhofer Eq. 2-6, 2-7).
Spectrum ComputeTransmittanceToTopAtmosphereBoundary(IN(AtmosphereParameters) atmosphere, Length r, Number mu) {
    return exp(-(atmosphere.rayleigh_scattering *
                     ComputeOpticalLengthToTopAtmosphereBoundary(atmosphere, atmosphere.rayleigh_density, r, mu) +
                 atmosphere.mie_extinction *
                     ComputeOpticalLengthToTopAtmosphereBoundary(atmosphere, atmosphere.mie_density, r, mu) +
                 atmosphere.absorption_extinction *
                     ComputeOpticalLengthToTopAtmosphereBoundary(atmosphere, atmosphere.absorption_density, r, mu)));
}

// Texel centres map to the ends of [0, 1], so a function is sampled exactly at its domain's ends.
Number GetTextureCoordFromUnitRange(Number x, int texture_size) {
    return 0.5 / Number(texture_size) + x * (1.0 - 1.0 / Number(texture_size));
}
Number GetUnitRangeFromTextureCoord(Number u, int texture_size) {
    return (u - 0.5 / Number(texture_size)) / (1.0 - 1.0 / Number(texture_size));
}

// Transmittance table coordinates: r through rho (distance to the horizon),
// mu through the distance to the top boundary, both mapped linearly, which puts
// samples where the function changes fastest (near the horizon).
vec2 GetTransmittanceTextureUvFromRMu(IN(AtmosphereParameters) atmosphere, Length r, Number mu) {
    Length H = sqrt((atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius));
    Length rho = SafeSqrt(r * r - atmosphere.bottom_radius * atmosphere.bottom_radius);
    Length d = DistanceToTopAtmosphereBoundary(atmosphere, r, mu);
    Length d_min = atmosphere.top_radius - r;
    Length d_max = rho + H;
    Number x_mu = (d - d_min) / (d_max - d_min);
    Number x_r = rho / H;
    return vec2(GetTextureCoordFromUnitRange(x_mu, TRANSMITTANCE_TEXTURE_WIDTH),
                GetTextureCoordFromUnitRange(x_r, TRANSMITTANCE_TEXTURE_HEIGHT));
}

void GetRMuFromTransmittanceTextureUv(IN(AtmosphereParameters) atmosphere, IN(vec2) uv, OUT(Length) r,
                                      OUT(Number) mu) {
    Number x_mu = GetUnitRangeFromTextureCoord(uv.x, TRANSMITTANCE_TEXTURE_WIDTH);
    Number x_r = GetUnitRangeFromTextureCoord(uv.y, TRANSMITTANCE_TEXTURE_HEIGHT);
    Length H = sqrt((atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius));
    Length rho = H * x_r;
    r = sqrt(rho * rho + atmosphere.bottom_radius * atmosphere.bottom_radius);
    Length d_min = atmosphere.top_radius - r;
    Length d_max = rho + H;
    Length d = d_min + x_mu * (d_max - d_min);
    mu = d == 0.0 ? Number(1.0) : (H * H - rho * rho - d * d) / (2.0 * r * d);
    mu = ClampCosine(mu);
}

Spectrum ComputeTransmittanceToTopAtmosphereBoundaryTexture(IN(AtmosphereParameters) atmosphere,
                                                            IN(vec2) frag_coord) {
    const vec2 TRANSMITTANCE_TEXTURE_SIZE = vec2(TRANSMITTANCE_TEXTURE_WIDTH, TRANSMITTANCE_TEXTURE_HEIGHT);
    Length r;
    Number mu;
    GetRMuFromTransmittanceTextureUv(atmosphere, frag_coord / TRANSMITTANCE_TEXTURE_SIZE, r, mu);
    return ComputeTransmittanceToTopAtmosphereBoundary(atmosphere, r, mu);
}

Spectrum GetTransmittanceToTopAtmosphereBoundary(IN(AtmosphereParameters) atmosphere,
                                                 IN(TransmittanceTexture) transmittance_texture, Length r,
                                                 Number mu) {
    vec2 uv = GetTransmittanceTextureUvFromRMu(atmosphere, r, mu);
    return Spectrum(texture(transmittance_texture, uv));
}

// Transmittance between the point at (r, mu) and the point at distance d along
// the ray: a ratio of two table lookups (Elek Eq. 19, Sperlhofer Eq. 4-16),
// taken on the side of the ray that does not cross the ground.
Spectrum GetTransmittance(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                          Length r, Number mu, Length d, bool ray_r_mu_intersects_ground) {
    Length r_d = ClampRadius(atmosphere, sqrt(d * d + 2.0 * r * mu * d + r * r));
    Number mu_d = ClampCosine((r * mu + d) / r_d);
    if (ray_r_mu_intersects_ground) {
        return min(GetTransmittanceToTopAtmosphereBoundary(atmosphere, transmittance_texture, r_d, -mu_d) /
                       GetTransmittanceToTopAtmosphereBoundary(atmosphere, transmittance_texture, r, -mu),
                   Spectrum(1.0));
    } else {
        return min(GetTransmittanceToTopAtmosphereBoundary(atmosphere, transmittance_texture, r, mu) /
                       GetTransmittanceToTopAtmosphereBoundary(atmosphere, transmittance_texture, r_d, mu_d),
                   Spectrum(1.0));
    }
}

// Transmittance to the sun, times the visible fraction of the sun disc above
// the horizon (Elek Eq. 17).
Spectrum GetTransmittanceToSun(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                               Length r, Number mu_s) {
    Number sin_theta_h = atmosphere.bottom_radius / r;
    Number cos_theta_h = -sqrt(max(1.0 - sin_theta_h * sin_theta_h, 0.0));
    return GetTransmittanceToTopAtmosphereBoundary(atmosphere, transmittance_texture, r, mu_s) *
           smoothstep(-sin_theta_h * atmosphere.sun_angular_radius, sin_theta_h * atmosphere.sun_angular_radius,
                      mu_s - cos_theta_h);
}

// ------------------------------------------------------- single scattering

// Phase functions per steradian. Rayleigh: Elek Eq. 2 / Sperlhofer Eq. 2-2.
// Mie: Cornette-Shanks, Elek Eq. 3 / Sperlhofer Eq. 2-4.
Number RayleighPhaseFunction(Number nu) {
    Number k = 3.0 / (16.0 * PI);
    return k * (1.0 + nu * nu);
}

Number MiePhaseFunction(Number g, Number nu) {
    Number k = 3.0 / (8.0 * PI) * (1.0 - g * g) / (2.0 + g * g);
    return k * (1.0 + nu * nu) / pow(1.0 + g * g - 2.0 * g * nu, 1.5);
}

// Elek's ad hoc Rayleigh phase (Eq. 15), per steradian, applied only when the
// scattered light is rendered (deferred phase, Elek §4.1.2), never in the tables.
Number RenderRayleighPhaseFunction(IN(AtmosphereParameters) atmosphere, Number nu) {
    return atmosphere.elek_rayleigh_phase > 0.5 ? 0.8 * (1.4 + 0.5 * nu) / (4.0 * PI) : RayleighPhaseFunction(nu);
}

void ComputeSingleScatteringIntegrand(IN(AtmosphereParameters) atmosphere,
                                      IN(TransmittanceTexture) transmittance_texture, Length r, Number mu,
                                      Number mu_s, Number nu, Length d, bool ray_r_mu_intersects_ground,
                                      OUT(Spectrum) rayleigh, OUT(Spectrum) mie) {
    Length r_d = ClampRadius(atmosphere, sqrt(d * d + 2.0 * r * mu * d + r * r));
    Number mu_s_d = ClampCosine((r * mu_s + d * nu) / r_d);
    Spectrum transmittance =
        GetTransmittance(atmosphere, transmittance_texture, r, mu, d, ray_r_mu_intersects_ground) *
        GetTransmittanceToSun(atmosphere, transmittance_texture, r_d, mu_s_d);
    rayleigh = transmittance * GetProfileDensity(atmosphere.rayleigh_density, r_d - atmosphere.bottom_radius);
    mie = transmittance * GetProfileDensity(atmosphere.mie_density, r_d - atmosphere.bottom_radius);
}

Length DistanceToNearestAtmosphereBoundary(IN(AtmosphereParameters) atmosphere, Length r, Number mu,
                                           bool ray_r_mu_intersects_ground) {
    if (ray_r_mu_intersects_ground) {
        return DistanceToBottomAtmosphereBoundary(atmosphere, r, mu);
    } else {
        return DistanceToTopAtmosphereBoundary(atmosphere, r, mu);
    }
}

// Single scattering (Elek Eq. 10) without the phase function, which is applied
// at lookup time (deferred phase, Elek §4.1.2).
void ComputeSingleScattering(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                             Length r, Number mu, Number mu_s, Number nu, bool ray_r_mu_intersects_ground,
                             OUT(Spectrum) rayleigh, OUT(Spectrum) mie) {
    const int SAMPLE_COUNT = 50;
    Length dx =
        DistanceToNearestAtmosphereBoundary(atmosphere, r, mu, ray_r_mu_intersects_ground) / Number(SAMPLE_COUNT);
    Spectrum rayleigh_sum = Spectrum(0.0);
    Spectrum mie_sum = Spectrum(0.0);
    for (int i = 0; i <= SAMPLE_COUNT; ++i) {
        Length d_i = Number(i) * dx;
        Spectrum rayleigh_i;
        Spectrum mie_i;
        ComputeSingleScatteringIntegrand(atmosphere, transmittance_texture, r, mu, mu_s, nu, d_i,
                                         ray_r_mu_intersects_ground, rayleigh_i, mie_i);
        Number weight_i = (i == 0 || i == SAMPLE_COUNT) ? 0.5 : 1.0;
        rayleigh_sum += rayleigh_i * weight_i;
        mie_sum += mie_i * weight_i;
    }
    rayleigh = rayleigh_sum * dx * atmosphere.solar_irradiance * atmosphere.rayleigh_scattering;
    mie = mie_sum * dx * atmosphere.solar_irradiance * atmosphere.mie_scattering;
}

// ------------------------------------------- scattering table coordinates
//
// 4D (r, mu, mu_s, nu) packed into a 3D texture: x = nu slice * MU_S_SIZE + mu_s,
// y = mu, z = r. mu is split in two halves, rays that hit the ground (u < 0.5)
// and rays that do not, so the discontinuity at the horizon falls between
// texels rather than inside one.

vec4 GetScatteringTextureUvwzFromRMuMuSNu(IN(AtmosphereParameters) atmosphere, Length r, Number mu, Number mu_s,
                                          Number nu, bool ray_r_mu_intersects_ground) {
    Length H = sqrt((atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius));
    Length rho = SafeSqrt(r * r - atmosphere.bottom_radius * atmosphere.bottom_radius);
    Number u_r = GetTextureCoordFromUnitRange(rho / H, SCATTERING_TEXTURE_R_SIZE);

    Length r_mu = r * mu;
    Area discriminant = RaySphereDiscriminant(r, mu, atmosphere.bottom_radius);
    Number u_mu;
    if (ray_r_mu_intersects_ground) {
        Length d = -r_mu - SafeSqrt(discriminant);
        Length d_min = r - atmosphere.bottom_radius;
        Length d_max = rho;
        u_mu = 0.5 - 0.5 * GetTextureCoordFromUnitRange(d_max == d_min ? 0.0 : (d - d_min) / (d_max - d_min),
                                                        SCATTERING_TEXTURE_MU_SIZE / 2);
    } else {
        Length d = -r_mu + SafeSqrt(discriminant + H * H);
        Length d_min = atmosphere.top_radius - r;
        Length d_max = rho + H;
        u_mu = 0.5 + 0.5 * GetTextureCoordFromUnitRange((d - d_min) / (d_max - d_min), SCATTERING_TEXTURE_MU_SIZE / 2);
    }

    Length d = DistanceToTopAtmosphereBoundary(atmosphere, atmosphere.bottom_radius, mu_s);
    Length d_min = atmosphere.top_radius - atmosphere.bottom_radius;
    Length d_max = H;
    Number a = (d - d_min) / (d_max - d_min);
    Length D = DistanceToTopAtmosphereBoundary(atmosphere, atmosphere.bottom_radius, atmosphere.mu_s_min);
    Number A = (D - d_min) / (d_max - d_min);
    Number u_mu_s = GetTextureCoordFromUnitRange(max(1.0 - a / A, 0.0) / (1.0 + a), SCATTERING_TEXTURE_MU_S_SIZE);

    Number u_nu = (nu + 1.0) / 2.0;
    return vec4(u_nu, u_mu_s, u_mu, u_r);
}

void GetRMuMuSNuFromScatteringTextureUvwz(IN(AtmosphereParameters) atmosphere, IN(vec4) uvwz, OUT(Length) r,
                                          OUT(Number) mu, OUT(Number) mu_s, OUT(Number) nu,
                                          OUT(bool) ray_r_mu_intersects_ground) {
    Length H = sqrt((atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius));
    Length rho = H * GetUnitRangeFromTextureCoord(uvwz.w, SCATTERING_TEXTURE_R_SIZE);
    r = sqrt(rho * rho + atmosphere.bottom_radius * atmosphere.bottom_radius);

    if (uvwz.z < 0.5) {
        Length d_min = r - atmosphere.bottom_radius;
        Length d_max = rho;
        Length d = d_min + (d_max - d_min) *
                               GetUnitRangeFromTextureCoord(1.0 - 2.0 * uvwz.z, SCATTERING_TEXTURE_MU_SIZE / 2);
        mu = d == 0.0 ? Number(-1.0) : ClampCosine(-(rho * rho + d * d) / (2.0 * r * d));
        ray_r_mu_intersects_ground = true;
    } else {
        Length d_min = atmosphere.top_radius - r;
        Length d_max = rho + H;
        Length d = d_min + (d_max - d_min) *
                               GetUnitRangeFromTextureCoord(2.0 * uvwz.z - 1.0, SCATTERING_TEXTURE_MU_SIZE / 2);
        mu = d == 0.0 ? Number(1.0) : ClampCosine((H * H - rho * rho - d * d) / (2.0 * r * d));
        ray_r_mu_intersects_ground = false;
    }

    Number x_mu_s = GetUnitRangeFromTextureCoord(uvwz.y, SCATTERING_TEXTURE_MU_S_SIZE);
    Length d_min = atmosphere.top_radius - atmosphere.bottom_radius;
    Length d_max = H;
    Length D = DistanceToTopAtmosphereBoundary(atmosphere, atmosphere.bottom_radius, atmosphere.mu_s_min);
    Number A = (D - d_min) / (d_max - d_min);
    Number a = (A - x_mu_s * A) / (1.0 + x_mu_s * A);
    Length d = d_min + min(a, A) * (d_max - d_min);
    mu_s = d == 0.0 ? Number(1.0) : ClampCosine((H * H - d * d) / (2.0 * atmosphere.bottom_radius * d));

    nu = ClampCosine(uvwz.x * 2.0 - 1.0);
}

void GetRMuMuSNuFromScatteringTextureFragCoord(IN(AtmosphereParameters) atmosphere, IN(vec3) frag_coord,
                                               OUT(Length) r, OUT(Number) mu, OUT(Number) mu_s, OUT(Number) nu,
                                               OUT(bool) ray_r_mu_intersects_ground) {
    const vec4 SCATTERING_TEXTURE_SIZE = vec4(SCATTERING_TEXTURE_NU_SIZE - 1, SCATTERING_TEXTURE_MU_S_SIZE,
                                              SCATTERING_TEXTURE_MU_SIZE, SCATTERING_TEXTURE_R_SIZE);
    Number frag_coord_nu = floor(frag_coord.x / Number(SCATTERING_TEXTURE_MU_S_SIZE));
    Number frag_coord_mu_s = frag_coord.x - Number(SCATTERING_TEXTURE_MU_S_SIZE) * frag_coord_nu;
    vec4 uvwz = vec4(frag_coord_nu, frag_coord_mu_s, frag_coord.y, frag_coord.z) / SCATTERING_TEXTURE_SIZE;
    GetRMuMuSNuFromScatteringTextureUvwz(atmosphere, uvwz, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
    // nu is bounded by mu and mu_s (the three directions are not independent).
    nu = clamp(nu, mu * mu_s - sqrt((1.0 - mu * mu) * (1.0 - mu_s * mu_s)),
               mu * mu_s + sqrt((1.0 - mu * mu) * (1.0 - mu_s * mu_s)));
}

void ComputeSingleScatteringTexture(IN(AtmosphereParameters) atmosphere,
                                    IN(TransmittanceTexture) transmittance_texture, IN(vec3) frag_coord,
                                    OUT(Spectrum) rayleigh, OUT(Spectrum) mie) {
    Length r;
    Number mu;
    Number mu_s;
    Number nu;
    bool ray_r_mu_intersects_ground;
    GetRMuMuSNuFromScatteringTextureFragCoord(atmosphere, frag_coord, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
    ComputeSingleScattering(atmosphere, transmittance_texture, r, mu, mu_s, nu, ray_r_mu_intersects_ground, rayleigh,
                            mie);
}

// Looks up a scattering table, interpolating between the two nu slices.
Spectrum GetScattering(IN(AtmosphereParameters) atmosphere, IN(ScatteringTexture) scattering_texture, Length r,
                       Number mu, Number mu_s, Number nu, bool ray_r_mu_intersects_ground) {
    vec4 uvwz = GetScatteringTextureUvwzFromRMuMuSNu(atmosphere, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
    Number tex_coord_x = uvwz.x * Number(SCATTERING_TEXTURE_NU_SIZE - 1);
    Number tex_x = floor(tex_coord_x);
    Number lerp = tex_coord_x - tex_x;
    vec3 uvw0 = vec3((tex_x + uvwz.y) / Number(SCATTERING_TEXTURE_NU_SIZE), uvwz.z, uvwz.w);
    vec3 uvw1 = vec3((tex_x + 1.0 + uvwz.y) / Number(SCATTERING_TEXTURE_NU_SIZE), uvwz.z, uvwz.w);
    return Spectrum(texture(scattering_texture, uvw0) * (1.0 - lerp) + texture(scattering_texture, uvw1) * lerp);
}

// Radiance of a given scattering order arriving at (r, mu) with the phase
// functions applied: order 1 from the single Rayleigh and Mie tables, higher
// orders from the multiple scattering table (stored with the phase folded in).
Spectrum GetScatteringOfOrder(IN(AtmosphereParameters) atmosphere,
                              IN(ScatteringTexture) single_rayleigh_scattering_texture,
                              IN(ScatteringTexture) single_mie_scattering_texture,
                              IN(ScatteringTexture) multiple_scattering_texture, Length r, Number mu, Number mu_s,
                              Number nu, bool ray_r_mu_intersects_ground, int scattering_order) {
    if (scattering_order == 1) {
        Spectrum rayleigh = GetScattering(atmosphere, single_rayleigh_scattering_texture, r, mu, mu_s, nu,
                                          ray_r_mu_intersects_ground);
        Spectrum mie = GetScattering(atmosphere, single_mie_scattering_texture, r, mu, mu_s, nu,
                                     ray_r_mu_intersects_ground);
        return rayleigh * RayleighPhaseFunction(nu) + mie * MiePhaseFunction(atmosphere.mie_phase_function_g, nu);
    } else {
        return GetScattering(atmosphere, multiple_scattering_texture, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
    }
}

// -------------------------------------------------------------- irradiance

vec2 GetIrradianceTextureUvFromRMuS(IN(AtmosphereParameters) atmosphere, Length r, Number mu_s) {
    Number x_r = (r - atmosphere.bottom_radius) / (atmosphere.top_radius - atmosphere.bottom_radius);
    Number x_mu_s = mu_s * 0.5 + 0.5;
    return vec2(GetTextureCoordFromUnitRange(x_mu_s, IRRADIANCE_TEXTURE_WIDTH),
                GetTextureCoordFromUnitRange(x_r, IRRADIANCE_TEXTURE_HEIGHT));
}

void GetRMuSFromIrradianceTextureUv(IN(AtmosphereParameters) atmosphere, IN(vec2) uv, OUT(Length) r,
                                    OUT(Number) mu_s) {
    Number x_mu_s = GetUnitRangeFromTextureCoord(uv.x, IRRADIANCE_TEXTURE_WIDTH);
    Number x_r = GetUnitRangeFromTextureCoord(uv.y, IRRADIANCE_TEXTURE_HEIGHT);
    r = atmosphere.bottom_radius + x_r * (atmosphere.top_radius - atmosphere.bottom_radius);
    mu_s = ClampCosine(2.0 * x_mu_s - 1.0);
}

Spectrum GetIrradiance(IN(AtmosphereParameters) atmosphere, IN(IrradianceTexture) irradiance_texture, Length r,
                       Number mu_s) {
    vec2 uv = GetIrradianceTextureUvFromRMuS(atmosphere, r, mu_s);
    return Spectrum(texture(irradiance_texture, uv));
}

// Direct sun irradiance on a horizontal surface, with the sun disc partly
// below the horizon approximated by the average cosine over the disc.
Spectrum ComputeDirectIrradiance(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                                 Length r, Number mu_s) {
    Number alpha_s = atmosphere.sun_angular_radius;
    Number average_cosine_factor =
        mu_s < -alpha_s ? 0.0 : (mu_s > alpha_s ? mu_s : (mu_s + alpha_s) * (mu_s + alpha_s) / (4.0 * alpha_s));
    return atmosphere.solar_irradiance *
           GetTransmittanceToTopAtmosphereBoundary(atmosphere, transmittance_texture, r, mu_s) * average_cosine_factor;
}

Spectrum ComputeDirectIrradianceTexture(IN(AtmosphereParameters) atmosphere,
                                        IN(TransmittanceTexture) transmittance_texture, IN(vec2) frag_coord) {
    Length r;
    Number mu_s;
    GetRMuSFromIrradianceTextureUv(atmosphere, frag_coord / vec2(IRRADIANCE_TEXTURE_WIDTH, IRRADIANCE_TEXTURE_HEIGHT),
                                   r, mu_s);
    return ComputeDirectIrradiance(atmosphere, transmittance_texture, r, mu_s);
}

// Sky irradiance on a horizontal surface from one scattering order (Elek Eq. 16,
// Sperlhofer Eq. 2-12), integrated over the upper hemisphere.
Spectrum ComputeIndirectIrradiance(IN(AtmosphereParameters) atmosphere,
                                   IN(ScatteringTexture) single_rayleigh_scattering_texture,
                                   IN(ScatteringTexture) single_mie_scattering_texture,
                                   IN(ScatteringTexture) multiple_scattering_texture, Length r, Number mu_s,
                                   int scattering_order) {
    const int SAMPLE_COUNT = 32;
    const Number dphi = PI / Number(SAMPLE_COUNT);
    const Number dtheta = PI / Number(SAMPLE_COUNT);
    Spectrum result = Spectrum(0.0);
    vec3 omega_s = vec3(sqrt(1.0 - mu_s * mu_s), 0.0, mu_s);
    for (int j = 0; j < SAMPLE_COUNT / 2; ++j) {
        Number theta = (Number(j) + 0.5) * dtheta;
        for (int i = 0; i < 2 * SAMPLE_COUNT; ++i) {
            Number phi = (Number(i) + 0.5) * dphi;
            vec3 omega = vec3(cos(phi) * sin(theta), sin(phi) * sin(theta), cos(theta));
            Number domega = dtheta * dphi * sin(theta);
            Number nu = dot(omega, omega_s);
            result += GetScatteringOfOrder(atmosphere, single_rayleigh_scattering_texture,
                                           single_mie_scattering_texture, multiple_scattering_texture, r, omega.z,
                                           mu_s, nu, false, scattering_order) *
                      omega.z * domega;
        }
    }
    return result;
}

Spectrum ComputeIndirectIrradianceTexture(IN(AtmosphereParameters) atmosphere,
                                          IN(ScatteringTexture) single_rayleigh_scattering_texture,
                                          IN(ScatteringTexture) single_mie_scattering_texture,
                                          IN(ScatteringTexture) multiple_scattering_texture, IN(vec2) frag_coord,
                                          int scattering_order) {
    Length r;
    Number mu_s;
    GetRMuSFromIrradianceTextureUv(atmosphere, frag_coord / vec2(IRRADIANCE_TEXTURE_WIDTH, IRRADIANCE_TEXTURE_HEIGHT),
                                   r, mu_s);
    return ComputeIndirectIrradiance(atmosphere, single_rayleigh_scattering_texture, single_mie_scattering_texture,
                                     multiple_scattering_texture, r, mu_s, scattering_order);
}

// ----------------------------------------------------- multiple scattering

// Radiance scattered at a point towards -omega by light of the previous order
// arriving from all directions, ground reflection included (Elek Eq. 12,
// Sperlhofer Eq. 2-10). Directions are in a frame with the zenith along z.
Spectrum ComputeScatteringDensity(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                                  IN(ScatteringTexture) single_rayleigh_scattering_texture,
                                  IN(ScatteringTexture) single_mie_scattering_texture,
                                  IN(ScatteringTexture) multiple_scattering_texture,
                                  IN(IrradianceTexture) irradiance_texture, Length r, Number mu, Number mu_s,
                                  Number nu, int scattering_order) {
    vec3 zenith_direction = vec3(0.0, 0.0, 1.0);
    vec3 omega = vec3(sqrt(1.0 - mu * mu), 0.0, mu);
    Number sun_dir_x = omega.x == 0.0 ? 0.0 : (nu - mu * mu_s) / omega.x;
    Number sun_dir_y = sqrt(max(1.0 - sun_dir_x * sun_dir_x - mu_s * mu_s, 0.0));
    vec3 omega_s = vec3(sun_dir_x, sun_dir_y, mu_s);

    const int SAMPLE_COUNT = 16;
    const Number dphi = PI / Number(SAMPLE_COUNT);
    const Number dtheta = PI / Number(SAMPLE_COUNT);
    Spectrum rayleigh_mie = Spectrum(0.0);
    Number rayleigh_density = GetProfileDensity(atmosphere.rayleigh_density, r - atmosphere.bottom_radius);
    Number mie_density = GetProfileDensity(atmosphere.mie_density, r - atmosphere.bottom_radius);

    for (int l = 0; l < SAMPLE_COUNT; ++l) {
        Number theta = (Number(l) + 0.5) * dtheta;
        Number cos_theta = cos(theta);
        Number sin_theta = sin(theta);
        bool ray_r_theta_intersects_ground = RayIntersectsGround(atmosphere, r, cos_theta);

        // Light reflected by the ground in this direction, if the ray hits it.
        Length distance_to_ground = 0.0;
        Spectrum transmittance_to_ground = Spectrum(0.0);
        Spectrum ground_albedo = Spectrum(0.0);
        if (ray_r_theta_intersects_ground) {
            distance_to_ground = DistanceToBottomAtmosphereBoundary(atmosphere, r, cos_theta);
            transmittance_to_ground =
                GetTransmittance(atmosphere, transmittance_texture, r, cos_theta, distance_to_ground, true);
            ground_albedo = atmosphere.ground_albedo;
        }

        for (int m = 0; m < 2 * SAMPLE_COUNT; ++m) {
            Number phi = (Number(m) + 0.5) * dphi;
            vec3 omega_i = vec3(cos(phi) * sin_theta, sin(phi) * sin_theta, cos_theta);
            Number domega_i = dtheta * dphi * sin(theta);

            Number nu1 = dot(omega_s, omega_i);
            Spectrum incident_radiance = GetScatteringOfOrder(
                atmosphere, single_rayleigh_scattering_texture, single_mie_scattering_texture,
                multiple_scattering_texture, r, omega_i.z, mu_s, nu1, ray_r_theta_intersects_ground,
                scattering_order - 1);

            vec3 ground_normal = normalize(zenith_direction * r + omega_i * distance_to_ground);
            Spectrum ground_irradiance =
                GetIrradiance(atmosphere, irradiance_texture, atmosphere.bottom_radius, dot(ground_normal, omega_s));
            incident_radiance += transmittance_to_ground * ground_albedo * (1.0 / PI) * ground_irradiance;

            Number nu2 = dot(omega, omega_i);
            rayleigh_mie += incident_radiance *
                            (atmosphere.rayleigh_scattering * rayleigh_density * RayleighPhaseFunction(nu2) +
                             atmosphere.mie_scattering * mie_density *
                                 MiePhaseFunction(atmosphere.mie_phase_function_g, nu2)) *
                            domega_i;
        }
    }
    return rayleigh_mie;
}

// One more order of scattering: the scattering density integrated along the
// ray with transmittance (Elek Eq. 13, Sperlhofer Eq. 2-11).
Spectrum ComputeMultipleScattering(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                                   IN(ScatteringTexture) scattering_density_texture, Length r, Number mu,
                                   Number mu_s, Number nu, bool ray_r_mu_intersects_ground) {
    const int SAMPLE_COUNT = 50;
    Length dx =
        DistanceToNearestAtmosphereBoundary(atmosphere, r, mu, ray_r_mu_intersects_ground) / Number(SAMPLE_COUNT);
    Spectrum rayleigh_mie_sum = Spectrum(0.0);
    for (int i = 0; i <= SAMPLE_COUNT; ++i) {
        Length d_i = Number(i) * dx;
        Length r_i = ClampRadius(atmosphere, sqrt(d_i * d_i + 2.0 * r * mu * d_i + r * r));
        Number mu_i = ClampCosine((r * mu + d_i) / r_i);
        Number mu_s_i = ClampCosine((r * mu_s + d_i * nu) / r_i);
        Spectrum rayleigh_mie_i =
            GetScattering(atmosphere, scattering_density_texture, r_i, mu_i, mu_s_i, nu, ray_r_mu_intersects_ground) *
            GetTransmittance(atmosphere, transmittance_texture, r, mu, d_i, ray_r_mu_intersects_ground) * dx;
        Number weight_i = (i == 0 || i == SAMPLE_COUNT) ? 0.5 : 1.0;
        rayleigh_mie_sum += rayleigh_mie_i * weight_i;
    }
    return rayleigh_mie_sum;
}

Spectrum ComputeScatteringDensityTexture(IN(AtmosphereParameters) atmosphere,
                                         IN(TransmittanceTexture) transmittance_texture,
                                         IN(ScatteringTexture) single_rayleigh_scattering_texture,
                                         IN(ScatteringTexture) single_mie_scattering_texture,
                                         IN(ScatteringTexture) multiple_scattering_texture,
                                         IN(IrradianceTexture) irradiance_texture, IN(vec3) frag_coord,
                                         int scattering_order) {
    Length r;
    Number mu;
    Number mu_s;
    Number nu;
    bool ray_r_mu_intersects_ground;
    GetRMuMuSNuFromScatteringTextureFragCoord(atmosphere, frag_coord, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
    return ComputeScatteringDensity(atmosphere, transmittance_texture, single_rayleigh_scattering_texture,
                                    single_mie_scattering_texture, multiple_scattering_texture, irradiance_texture, r,
                                    mu, mu_s, nu, scattering_order);
}

// Returns the order's radiance; nu is returned so the caller can divide by the
// Rayleigh phase before accumulating (the table stores phase-free values).
Spectrum ComputeMultipleScatteringTexture(IN(AtmosphereParameters) atmosphere,
                                          IN(TransmittanceTexture) transmittance_texture,
                                          IN(ScatteringTexture) scattering_density_texture, IN(vec3) frag_coord,
                                          OUT(Number) nu) {
    Length r;
    Number mu;
    Number mu_s;
    bool ray_r_mu_intersects_ground;
    GetRMuMuSNuFromScatteringTextureFragCoord(atmosphere, frag_coord, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
    return ComputeMultipleScattering(atmosphere, transmittance_texture, scattering_density_texture, r, mu, mu_s, nu,
                                     ray_r_mu_intersects_ground);
}
