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

// TRANSMITTANCE_LOG_LOOKUP: how the transmittance table is read (see
// TransmittanceTableLog). true in the precomputation (the passes define it before
// including this file; C++: a Model member, true in computeReferenceTables), where
// a table lookup's error is integrated into every other table; false at render
// time, where one filtered fetch keeps the sky pass as fast as before.
#ifndef __cplusplus
#ifndef TRANSMITTANCE_LOG_LOOKUP
#define TRANSMITTANCE_LOG_LOOKUP false
#endif
#endif

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

// Altitudes below 0 (a grazing ray rounded under the ground) read the ground's
// density: an exponential profile's layer 0 (width 0) holds no particles, and a
// ray a float rounding below the horizon would otherwise lose its densest air.
Number GetProfileDensity(IN(DensityProfile) profile, Length altitude) {
    altitude = max(altitude, Length(0.0));
    return altitude < profile.layers[0].width ? GetLayerDensity(profile.layers[0], altitude)
                                              : GetLayerDensity(profile.layers[1], altitude);
}

// ------------------------------------------------ quadrature along a ray
//
// The integrals along rays below sample their integrand at evenly spaced points.
// Between two samples the integrand is taken as exp(l) s with l (a log) and s
// both linear, and that product is integrated exactly: the exponential part
// carries the densities' exponential fall with altitude and the transmittance
// (exact for a vertical ray through an exponential profile, and for any ray
// through a homogeneous medium however thick), the linear part the ozone's tent
// and the sun's horizon factor. The trapezoidal rule it replaces assumed the
// integrand linear over a step: a step of several scale heights or optical
// depths then counted the bright end across the whole step (a ray 200 000 km
// long through an 8 km scale height: 240 times the air there is). Logs are kept
// as logs (LOG_ZERO for an exact zero), so a sample whose value underflows in
// float still tells how fast the integrand falls.

const Number LOG_ZERO = -1.0e4;

Number SafeLog(Number x) { return x > 0.0 ? max(log(x), LOG_ZERO) : LOG_ZERO; }
Spectrum SafeLogSpectrum(IN(Spectrum) x) { return Spectrum(SafeLog(x.x), SafeLog(x.y), SafeLog(x.z)); }

// Mean over a step of exp(l(t)) s(t), l and s linear from (l_a, s_a) to (l_b, s_b):
// from the larger end, with delta = |l_a - l_b|,
//   exp(l_hi) (s_hi I0 + (s_lo - s_hi) I1), I0 = (1 - e^-delta) / delta,
//   I1 = (1 - (1 + delta) e^-delta) / delta^2 (their series for a small delta).
// Equal logs give the trapezoidal rule's (s_a + s_b) / 2.
Number ExpLinearMean(Number l_a, Number l_b, Number s_a, Number s_b) {
    bool a_high = l_a >= l_b;
    Number l_hi = a_high ? l_a : l_b;
    Number s_hi = a_high ? s_a : s_b;
    Number s_lo = a_high ? s_b : s_a;
    Number delta = abs(l_a - l_b);
    Number i0;
    Number i1;
    if (delta < 0.1) {
        i0 = 1.0 - delta * (1.0 / 2.0 - delta * (1.0 / 6.0 - delta * (1.0 / 24.0 - delta / 120.0)));
        i1 = 0.5 - delta * (1.0 / 3.0 - delta * (1.0 / 8.0 - delta * (1.0 / 30.0 - delta / 144.0)));
    } else {
        Number e = exp(-delta);
        i0 = (1.0 - e) / delta;
        i1 = (1.0 - (1.0 + delta) * e) / (delta * delta);
    }
    return exp(l_hi) * (s_hi * i0 + (s_lo - s_hi) * i1);
}

Spectrum ExpLinearMeanSpectrum(IN(Spectrum) l_a, IN(Spectrum) l_b, IN(Spectrum) s_a, IN(Spectrum) s_b) {
    return Spectrum(ExpLinearMean(l_a.x, l_b.x, s_a.x, s_b.x), ExpLinearMean(l_a.y, l_b.y, s_a.y, s_b.y),
                    ExpLinearMean(l_a.z, l_b.z, s_a.z, s_b.z));
}

// A profile's density at an altitude as exp(log_density) * linear_density: an
// exponential layer (Elek Eq. 8) in its log, whose float never underflows; any
// other (ozone's tent) as it is.
void GetProfileDensityParts(IN(DensityProfile) profile, Length altitude, OUT(Number) log_density,
                            OUT(Number) linear_density) {
    altitude = max(altitude, Length(0.0));  // as GetProfileDensity
    DensityProfileLayer layer = altitude < profile.layers[0].width ? profile.layers[0] : profile.layers[1];
    if (layer.exp_term > 0.0 && layer.linear_term == 0.0 && layer.constant_term == 0.0) {
        log_density = min(log(layer.exp_term) + layer.exp_scale * altitude, Number(0.0));  // clamped to 1
        linear_density = 1.0;
    } else {
        log_density = 0.0;
        linear_density = GetLayerDensity(layer, altitude);
    }
}

// Integral of the density along the ray to the top boundary.
Length ComputeOpticalLengthToTopAtmosphereBoundary(IN(AtmosphereParameters) atmosphere,
                                                   IN(DensityProfile) profile, Length r, Number mu) {
    const int SAMPLE_COUNT = 500;
    Length dx = DistanceToTopAtmosphereBoundary(atmosphere, r, mu) / Number(SAMPLE_COUNT);
    Length result = 0.0;
    Number l_previous;
    Number s_previous;
    GetProfileDensityParts(profile, r - atmosphere.bottom_radius, l_previous, s_previous);
    for (int i = 1; i <= SAMPLE_COUNT; ++i) {
        Length d_i = Number(i) * dx;
        Length r_i = sqrt(d_i * d_i + 2.0 * r * mu * d_i + r * r);
        Number l_i;
        Number s_i;
        GetProfileDensityParts(profile, r_i - atmosphere.bottom_radius, l_i, s_i);
        result += ExpLinearMean(l_previous, l_i, s_previous, s_i) * dx;
        l_previous = l_i;
        s_previous = s_i;
    }
    return result;
}

// Optical depth to the top boundary, per channel (Elek Eq. 9, Sperlhofer Eq. 2-6, 2-7).
Spectrum ComputeOpticalDepthToTopAtmosphereBoundary(IN(AtmosphereParameters) atmosphere, Length r, Number mu) {
    return atmosphere.rayleigh_scattering *
               ComputeOpticalLengthToTopAtmosphereBoundary(atmosphere, atmosphere.rayleigh_density, r, mu) +
           atmosphere.mie_extinction *
               ComputeOpticalLengthToTopAtmosphereBoundary(atmosphere, atmosphere.mie_density, r, mu) +
           atmosphere.absorption_extinction *
               ComputeOpticalLengthToTopAtmosphereBoundary(atmosphere, atmosphere.absorption_density, r, mu);
}

// Transmittance to the top boundary: exp(-optical depth).
Spectrum ComputeTransmittanceToTopAtmosphereBoundary(IN(AtmosphereParameters) atmosphere, Length r, Number mu) {
    return exp(-ComputeOpticalDepthToTopAtmosphereBoundary(atmosphere, r, mu));
}

// The transmittance table holds T^(1 / TRANSMITTANCE_TABLE_ROOT), the fourth root
// of the transmittance (1 still means clear air, less means less light): a float
// holds exp(-87) at the least, and the ray grazing the ground from the top of a
// thick atmosphere (twice the optical depth of the horizontal ray from the ground)
// passes that long before the rays a view can see become dark; the root keeps
// optical depths up to 4 x 87 in range. The precomputation reads it in log space
// (TRANSMITTANCE_LOG_LOOKUP), the frame with one filtered fetch to the fourth power.
const Number TRANSMITTANCE_TABLE_ROOT = 4.0;

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
// The coordinates from r, rho (distance to the horizon), H (rho at the top) and d (distance to
// the top boundary along the ray): both mapped linearly over their ranges.
vec2 TransmittanceTextureUv(IN(AtmosphereParameters) atmosphere, Length r, Length rho, Length H, Length d) {
    Length d_min = atmosphere.top_radius - r;
    Length d_max = rho + H;
    Number x_mu = (d - d_min) / (d_max - d_min);
    Number x_r = rho / H;
    return vec2(GetTextureCoordFromUnitRange(x_mu, TRANSMITTANCE_TEXTURE_WIDTH),
                GetTextureCoordFromUnitRange(x_r, TRANSMITTANCE_TEXTURE_HEIGHT));
}

vec2 GetTransmittanceTextureUvFromRMu(IN(AtmosphereParameters) atmosphere, Length r, Number mu) {
    Length H = sqrt((atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius));
    Length rho = SafeSqrt((r - atmosphere.bottom_radius) * (r + atmosphere.bottom_radius));  // r - R exact near R
    Length d = DistanceToTopAtmosphereBoundary(atmosphere, r, mu);
    return TransmittanceTextureUv(atmosphere, r, rho, H, d);
}

// The same coordinates from rho^2 = r^2 - R^2 and r mu, for a point given by its
// distance d along a ray: d (d + 2 r mu) + (r - R)(r + R) and r mu + d are exact
// to the ray's own precision, where r_d itself, a float of planet size, is
// rounded to half a metre, which moves the optical depth of a thick air layer
// of 1 km scale height by a percent.
vec2 GetTransmittanceTextureUvFromRho2RMu(IN(AtmosphereParameters) atmosphere, Area rho2, Length r_mu) {
    Area H2 = (atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius);
    Length H = sqrt(H2);
    rho2 = clamp(rho2, Area(0.0), H2);
    Length rho = sqrt(rho2);
    Length r = sqrt(rho2 + atmosphere.bottom_radius * atmosphere.bottom_radius);
    Length d = ClampDistance(-r_mu + SafeSqrt(r_mu * r_mu + (H2 - rho2)));
    return TransmittanceTextureUv(atmosphere, r, rho, H, d);
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
    return exp(-ComputeOpticalDepthToTopAtmosphereBoundary(atmosphere, r, mu) / TRANSMITTANCE_TABLE_ROOT);
}

// ln T from the transmittance table at uv, with GL_LINEAR's texels and weights
// (GL_CLAMP_TO_EDGE) but interpolated in log space: the optical depth is what
// varies smoothly between texels, T itself by orders of magnitude across one
// texel near the horizon in thick air, where a linear blend of T is far off and
// a float rounding of uv (r is a float of planet size) moves it by a large
// fraction of itself. LOG_ZERO texels (exactly 0) stay far below any other.
// Without TRANSMITTANCE_LOG_LOOKUP: the filtered fetch (linear in T^(1/4)).
Spectrum TransmittanceTableLog(IN(TransmittanceTexture) transmittance_texture, IN(vec2) uv) {
    if (!TRANSMITTANCE_LOG_LOOKUP)
        return SafeLogSpectrum(Spectrum(texture(transmittance_texture, uv))) * TRANSMITTANCE_TABLE_ROOT;
    Number x = uv.x * Number(TRANSMITTANCE_TEXTURE_WIDTH) - 0.5;
    Number y = uv.y * Number(TRANSMITTANCE_TEXTURE_HEIGHT) - 0.5;
    Number x_floor = floor(x);
    Number y_floor = floor(y);
    Number wx = x - x_floor;
    Number wy = y - y_floor;
    int x0 = clamp(int(x_floor), 0, TRANSMITTANCE_TEXTURE_WIDTH - 1);
    int x1 = clamp(int(x_floor) + 1, 0, TRANSMITTANCE_TEXTURE_WIDTH - 1);
    int y0 = clamp(int(y_floor), 0, TRANSMITTANCE_TEXTURE_HEIGHT - 1);
    int y1 = clamp(int(y_floor) + 1, 0, TRANSMITTANCE_TEXTURE_HEIGHT - 1);
    Spectrum l00 = SafeLogSpectrum(Spectrum(texelFetch(transmittance_texture, ivec2(x0, y0), 0)));
    Spectrum l10 = SafeLogSpectrum(Spectrum(texelFetch(transmittance_texture, ivec2(x1, y0), 0)));
    Spectrum l01 = SafeLogSpectrum(Spectrum(texelFetch(transmittance_texture, ivec2(x0, y1), 0)));
    Spectrum l11 = SafeLogSpectrum(Spectrum(texelFetch(transmittance_texture, ivec2(x1, y1), 0)));
    return mix(mix(l00, l10, wx), mix(l01, l11, wx), wy) * TRANSMITTANCE_TABLE_ROOT;
}

// ln of the transmittance to the top boundary, and the transmittance itself.
Spectrum GetLogTransmittanceToTopAtmosphereBoundary(IN(AtmosphereParameters) atmosphere,
                                                    IN(TransmittanceTexture) transmittance_texture, Length r,
                                                    Number mu) {
    return TransmittanceTableLog(transmittance_texture, GetTransmittanceTextureUvFromRMu(atmosphere, r, mu));
}

Spectrum GetTransmittanceToTopAtmosphereBoundary(IN(AtmosphereParameters) atmosphere,
                                                 IN(TransmittanceTexture) transmittance_texture, Length r,
                                                 Number mu) {
    if (TRANSMITTANCE_LOG_LOOKUP)
        return exp(GetLogTransmittanceToTopAtmosphereBoundary(atmosphere, transmittance_texture, r, mu));
    Spectrum t = Spectrum(texture(transmittance_texture, GetTransmittanceTextureUvFromRMu(atmosphere, r, mu)));
    t = t * t;
    return t * t;  // the table's T^(1/4), to the fourth power
}

// near / far, at most 1, per channel; 0 where far is 0 (0 / 0 would be NaN, which
// glm's min keeps and GLSL's may not).
Number TransmittanceRatioOf(Number near_value, Number far_value) {
    return far_value > 0.0 ? min(near_value / far_value, Number(1.0)) : Number(0.0);
}
Spectrum TransmittanceRatio(IN(Spectrum) near_value, IN(Spectrum) far_value) {
    return Spectrum(TransmittanceRatioOf(near_value.x, far_value.x), TransmittanceRatioOf(near_value.y, far_value.y),
                    TransmittanceRatioOf(near_value.z, far_value.z));
}

// ln(near / far), at most 0, per channel: a difference of logs, so neither a
// transmittance that underflows nor 0 / 0 can occur; LOG_ZERO where far is
// (interpolated towards) an exact 0.
Number LogTransmittanceRatioOf(Number near_log, Number far_log) {
    return far_log < LOG_ZERO ? LOG_ZERO : min(near_log - far_log, Number(0.0));
}
Spectrum LogTransmittanceRatio(IN(Spectrum) near_log, IN(Spectrum) far_log) {
    return Spectrum(LogTransmittanceRatioOf(near_log.x, far_log.x), LogTransmittanceRatioOf(near_log.y, far_log.y),
                    LogTransmittanceRatioOf(near_log.z, far_log.z));
}

// ln of the transmittance between the point at (r, mu) and the point at distance
// d along the ray: a ratio of two table lookups (Elek Eq. 19, Sperlhofer Eq.
// 4-16), taken on the side of the ray that does not cross the ground.
Spectrum GetLogTransmittance(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                             Length r, Number mu, Length d, bool ray_r_mu_intersects_ground) {
    // The far point by rho_d^2 and r_d mu_d (see GetTransmittanceTextureUvFromRho2RMu).
    Area rho_d2 = d * (d + 2.0 * r * mu) + (r - atmosphere.bottom_radius) * (r + atmosphere.bottom_radius);
    Length r_mu_d = r * mu + d;
    if (ray_r_mu_intersects_ground) {
        return LogTransmittanceRatio(
            TransmittanceTableLog(transmittance_texture, GetTransmittanceTextureUvFromRho2RMu(atmosphere, rho_d2, -r_mu_d)),
            GetLogTransmittanceToTopAtmosphereBoundary(atmosphere, transmittance_texture, r, -mu));
    } else {
        return LogTransmittanceRatio(
            GetLogTransmittanceToTopAtmosphereBoundary(atmosphere, transmittance_texture, r, mu),
            TransmittanceTableLog(transmittance_texture, GetTransmittanceTextureUvFromRho2RMu(atmosphere, rho_d2, r_mu_d)));
    }
}

Spectrum GetTransmittance(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                          Length r, Number mu, Length d, bool ray_r_mu_intersects_ground) {
    if (TRANSMITTANCE_LOG_LOOKUP)
        return exp(GetLogTransmittance(atmosphere, transmittance_texture, r, mu, d, ray_r_mu_intersects_ground));
    // At render time: the ratio of the table's fourth roots, to the fourth power.
    Length r_d = ClampRadius(atmosphere, sqrt(d * d + 2.0 * r * mu * d + r * r));
    Number mu_d = ClampCosine((r * mu + d) / r_d);
    Spectrum q;
    if (ray_r_mu_intersects_ground) {
        q = TransmittanceRatio(
            Spectrum(texture(transmittance_texture, GetTransmittanceTextureUvFromRMu(atmosphere, r_d, -mu_d))),
            Spectrum(texture(transmittance_texture, GetTransmittanceTextureUvFromRMu(atmosphere, r, -mu))));
    } else {
        q = TransmittanceRatio(
            Spectrum(texture(transmittance_texture, GetTransmittanceTextureUvFromRMu(atmosphere, r, mu))),
            Spectrum(texture(transmittance_texture, GetTransmittanceTextureUvFromRMu(atmosphere, r_d, mu_d))));
    }
    q = q * q;
    return q * q;
}

// ------------------------------------ render-time lookups from rho^2 and r mu
//
// A camera a few metres above the ground, or the far end of a view ray there, in float:
// r is a number of planet size (0.5 m steps on Earth), so r^2 - R^2, the horizon's
// cosine -sqrt(r^2 - R^2) / r and the distance to the ground would lose the altitude.
// These take the point by rho^2 = r^2 - R^2 (from the altitude h, h (h + 2R), or along
// a ray, d (d + 2 r mu) + rho^2) and r mu, which keep it; r itself only where its
// rounding does not matter. In double (the CPU reference) they equal the (r, mu) forms.

bool RayIntersectsGroundRho2(Area rho2, Length r_mu) { return r_mu < 0.0 && r_mu * r_mu - rho2 >= 0.0; }

// Distance to the ground along a ray that hits it: the nearer root of
// d^2 + 2 r mu d + rho^2 = 0 as rho^2 / (the farther root), without the cancellation of
// -r mu - sqrt((r mu)^2 - rho^2) (r mu is planet-sized, the distance metres).
Length DistanceToGroundRho2(Area rho2, Length r_mu) {
    Length far_root = -r_mu + SafeSqrt(r_mu * r_mu - rho2);
    return far_root > 0.0 ? max(rho2, Area(0.0)) / far_root : Length(0.0);
}

Spectrum GetTransmittanceToTopAtmosphereBoundaryRho2(IN(AtmosphereParameters) atmosphere,
                                                     IN(TransmittanceTexture) transmittance_texture, Area rho2,
                                                     Length r_mu) {
    vec2 uv = GetTransmittanceTextureUvFromRho2RMu(atmosphere, rho2, r_mu);
    if (TRANSMITTANCE_LOG_LOOKUP) return exp(TransmittanceTableLog(transmittance_texture, uv));
    Spectrum t = Spectrum(texture(transmittance_texture, uv));
    t = t * t;
    return t * t;
}

// GetTransmittance's (r, mu, d) with the start by rho^2 and r mu and the far end by
// rho_d^2 = d (d + 2 r mu) + rho^2 and r_d mu_d = r mu + d.
Spectrum GetTransmittanceRho2(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                              Area rho2, Length r_mu, Length d, bool ray_r_mu_intersects_ground) {
    Area rho_d2 = d * (d + 2.0 * r_mu) + rho2;
    Length r_mu_d = r_mu + d;
    vec2 uv_near = GetTransmittanceTextureUvFromRho2RMu(atmosphere, rho2, ray_r_mu_intersects_ground ? -r_mu : r_mu);
    vec2 uv_far = GetTransmittanceTextureUvFromRho2RMu(atmosphere, rho_d2, ray_r_mu_intersects_ground ? -r_mu_d : r_mu_d);
    if (TRANSMITTANCE_LOG_LOOKUP) {
        Spectrum near_log = TransmittanceTableLog(transmittance_texture, uv_near);
        Spectrum far_log = TransmittanceTableLog(transmittance_texture, uv_far);
        return exp(ray_r_mu_intersects_ground ? LogTransmittanceRatio(far_log, near_log)
                                              : LogTransmittanceRatio(near_log, far_log));
    }
    Spectrum t_near = Spectrum(texture(transmittance_texture, uv_near));
    Spectrum t_far = Spectrum(texture(transmittance_texture, uv_far));
    Spectrum q = ray_r_mu_intersects_ground ? TransmittanceRatio(t_far, t_near) : TransmittanceRatio(t_near, t_far);
    q = q * q;
    return q * q;
}

// Transmittance to the sun, times the visible fraction of the sun disc above
// the horizon (Elek Eq. 17).
// The fraction of the sun's disc above the horizon seen from radius r (altitude
// r - R given separately where it is known more precisely than r).
Number SunAboveHorizonFractionAt(IN(AtmosphereParameters) atmosphere, Length r, Length altitude, Number mu_s) {
    Number sin_theta_h = atmosphere.bottom_radius / r;
    Number cos_theta_h = -sqrt(max(altitude * (altitude + 2.0 * atmosphere.bottom_radius), Area(0.0))) / r;
    return smoothstep(-sin_theta_h * atmosphere.sun_angular_radius, sin_theta_h * atmosphere.sun_angular_radius,
                      mu_s - cos_theta_h);
}

Number SunAboveHorizonFraction(IN(AtmosphereParameters) atmosphere, Length r, Number mu_s) {
    return SunAboveHorizonFractionAt(atmosphere, r, r - atmosphere.bottom_radius, mu_s);
}

Spectrum GetTransmittanceToSun(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                               Length r, Number mu_s) {
    return GetTransmittanceToTopAtmosphereBoundary(atmosphere, transmittance_texture, r, mu_s) *
           SunAboveHorizonFraction(atmosphere, r, mu_s);
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

// The single scattering integrand at distance d along the ray, in the parts the
// quadrature takes (see ExpLinearMean): per channel, the log of the transmittance
// from the ray's origin to the point and from the point to the sun, plus each
// profile's log density (rayleigh_log, mie_log); and the linear factors, the sun's
// fraction above the horizon times each profile's linear density.
void ComputeSingleScatteringIntegrand(IN(AtmosphereParameters) atmosphere,
                                      IN(TransmittanceTexture) transmittance_texture, Length r, Number mu,
                                      Number mu_s, Number nu, Length d, bool ray_r_mu_intersects_ground,
                                      OUT(Spectrum) rayleigh_log, OUT(Spectrum) mie_log, OUT(Number) rayleigh_linear,
                                      OUT(Number) mie_linear) {
    // The point's altitude from r_d^2 - R^2 = d (d + 2 r mu) + (r - R)(r + R), not
    // r_d - R: at the ground end of a ray r_d is a float of planet size (0.5 m
    // steps), which a 10 m scale height or the sun's horizon factor would feel.
    Area r_d2_minus_R2 = max(d * (d + 2.0 * r * mu) + (r - atmosphere.bottom_radius) * (r + atmosphere.bottom_radius),
                             Area(0.0));
    Length r_d = ClampRadius(atmosphere, sqrt(r_d2_minus_R2 + atmosphere.bottom_radius * atmosphere.bottom_radius));
    Length altitude_d = r_d2_minus_R2 / (r_d + atmosphere.bottom_radius);
    Number mu_s_d = ClampCosine((r * mu_s + d * nu) / r_d);
    Spectrum log_transmittance =
        GetLogTransmittance(atmosphere, transmittance_texture, r, mu, d, ray_r_mu_intersects_ground) +
        TransmittanceTableLog(transmittance_texture,
                              GetTransmittanceTextureUvFromRho2RMu(atmosphere, r_d2_minus_R2, r * mu_s + d * nu));
    Number sun_fraction = SunAboveHorizonFractionAt(atmosphere, r_d, altitude_d, mu_s_d);
    Number rayleigh_log_density;
    Number mie_log_density;
    GetProfileDensityParts(atmosphere.rayleigh_density, altitude_d, rayleigh_log_density, rayleigh_linear);
    GetProfileDensityParts(atmosphere.mie_density, altitude_d, mie_log_density, mie_linear);
    rayleigh_log = log_transmittance + Spectrum(rayleigh_log_density);
    mie_log = log_transmittance + Spectrum(mie_log_density);
    rayleigh_linear *= sun_fraction;
    mie_linear *= sun_fraction;
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
    Spectrum rayleigh_log_previous;
    Spectrum mie_log_previous;
    Number rayleigh_linear_previous;
    Number mie_linear_previous;
    ComputeSingleScatteringIntegrand(atmosphere, transmittance_texture, r, mu, mu_s, nu, Length(0.0),
                                     ray_r_mu_intersects_ground, rayleigh_log_previous, mie_log_previous,
                                     rayleigh_linear_previous, mie_linear_previous);
    for (int i = 1; i <= SAMPLE_COUNT; ++i) {
        Length d_i = Number(i) * dx;
        Spectrum rayleigh_log_i;
        Spectrum mie_log_i;
        Number rayleigh_linear_i;
        Number mie_linear_i;
        ComputeSingleScatteringIntegrand(atmosphere, transmittance_texture, r, mu, mu_s, nu, d_i,
                                         ray_r_mu_intersects_ground, rayleigh_log_i, mie_log_i, rayleigh_linear_i,
                                         mie_linear_i);
        rayleigh_sum += ExpLinearMeanSpectrum(rayleigh_log_previous, rayleigh_log_i, Spectrum(rayleigh_linear_previous),
                                              Spectrum(rayleigh_linear_i));
        mie_sum += ExpLinearMeanSpectrum(mie_log_previous, mie_log_i, Spectrum(mie_linear_previous),
                                         Spectrum(mie_linear_i));
        rayleigh_log_previous = rayleigh_log_i;
        mie_log_previous = mie_log_i;
        rayleigh_linear_previous = rayleigh_linear_i;
        mie_linear_previous = mie_linear_i;
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

// The coordinates from r, rho^2 = r^2 - R^2 and r mu, which a point along a ray
// knows more precisely than its r (see GetTransmittanceTextureUvFromRho2RMu).
vec4 GetScatteringTextureUvwzFromRRho2RMu(IN(AtmosphereParameters) atmosphere, Length r, Area rho2, Length r_mu,
                                          Number mu_s, Number nu, bool ray_r_mu_intersects_ground) {
    Length H = sqrt((atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius));
    Length rho = SafeSqrt(rho2);
    Number u_r = GetTextureCoordFromUnitRange(rho / H, SCATTERING_TEXTURE_R_SIZE);

    Area discriminant = r_mu * r_mu - rho2;  // RaySphereDiscriminant(r, mu, bottom_radius)
    Number u_mu;
    if (ray_r_mu_intersects_ground) {
        Length d = -r_mu - SafeSqrt(discriminant);
        Length d_min = max(rho2, Area(0.0)) / (r + atmosphere.bottom_radius);  // r - R
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

vec4 GetScatteringTextureUvwzFromRMuMuSNu(IN(AtmosphereParameters) atmosphere, Length r, Number mu, Number mu_s,
                                          Number nu, bool ray_r_mu_intersects_ground) {
    return GetScatteringTextureUvwzFromRRho2RMu(atmosphere, r,
                                                (r - atmosphere.bottom_radius) * (r + atmosphere.bottom_radius),
                                                r * mu, mu_s, nu, ray_r_mu_intersects_ground);
}

void GetRMuMuSNuFromScatteringTextureUvwz(IN(AtmosphereParameters) atmosphere, IN(vec4) uvwz, OUT(Length) r,
                                          OUT(Number) mu, OUT(Number) mu_s, OUT(Number) nu,
                                          OUT(bool) ray_r_mu_intersects_ground) {
    Length H = sqrt((atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius));
    Length rho = H * GetUnitRangeFromTextureCoord(uvwz.w, SCATTERING_TEXTURE_R_SIZE);
    r = sqrt(rho * rho + atmosphere.bottom_radius * atmosphere.bottom_radius);
    // rho again from the rounded r (r - R is exact): the texel moves by a rounding
    // of r, but the ray tangent to the ground built from this pair then really
    // touches the ground, where a float r of planet size would leave it up to a
    // metre above, enough to move the horizon of a setting sun by a tenth of its disc.
    rho = SafeSqrt((r - atmosphere.bottom_radius) * (r + atmosphere.bottom_radius));

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
Spectrum GetScatteringAtUvwz(IN(ScatteringTexture) scattering_texture, IN(vec4) uvwz) {
    Number tex_coord_x = uvwz.x * Number(SCATTERING_TEXTURE_NU_SIZE - 1);
    Number tex_x = floor(tex_coord_x);
    Number lerp = tex_coord_x - tex_x;
    vec3 uvw0 = vec3((tex_x + uvwz.y) / Number(SCATTERING_TEXTURE_NU_SIZE), uvwz.z, uvwz.w);
    vec3 uvw1 = vec3((tex_x + 1.0 + uvwz.y) / Number(SCATTERING_TEXTURE_NU_SIZE), uvwz.z, uvwz.w);
    return Spectrum(texture(scattering_texture, uvw0) * (1.0 - lerp) + texture(scattering_texture, uvw1) * lerp);
}

Spectrum GetScattering(IN(AtmosphereParameters) atmosphere, IN(ScatteringTexture) scattering_texture, Length r,
                       Number mu, Number mu_s, Number nu, bool ray_r_mu_intersects_ground) {
    return GetScatteringAtUvwz(
        scattering_texture, GetScatteringTextureUvwzFromRMuMuSNu(atmosphere, r, mu, mu_s, nu, ray_r_mu_intersects_ground));
}

// GetScattering from rho^2 and r mu (see GetTransmittanceRho2). The ground half's
// coordinate takes the distance to the ground without cancellation (DistanceToGroundRho2):
// the table's own formula loses it to r mu's rounding looking down from a few metres.
Spectrum GetScatteringRho2(IN(AtmosphereParameters) atmosphere, IN(ScatteringTexture) scattering_texture, Length r,
                           Area rho2, Length r_mu, Number mu_s, Number nu, bool ray_r_mu_intersects_ground) {
    vec4 uvwz = GetScatteringTextureUvwzFromRRho2RMu(atmosphere, r, rho2, r_mu, mu_s, nu, ray_r_mu_intersects_ground);
    if (ray_r_mu_intersects_ground) {
        Length d = DistanceToGroundRho2(rho2, r_mu);
        Length d_min = max(rho2, Area(0.0)) / (r + atmosphere.bottom_radius);  // r - R
        Length d_max = SafeSqrt(rho2);
        uvwz.z = 0.5 - 0.5 * GetTextureCoordFromUnitRange(
                                 d_max == d_min ? 0.0 : clamp((d - d_min) / (d_max - d_min), Number(0.0), Number(1.0)),
                                 SCATTERING_TEXTURE_MU_SIZE / 2);
    }
    return GetScatteringAtUvwz(scattering_texture, uvwz);
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

// GetIrradiance(atmosphere, irradiance_texture, bottom_radius, mu_s) by two texel
// fetches: at r = bottom_radius the table's v is the bottom row's centre, so the
// filtered lookup is a lerp along that row, which this is (cheaper on a CPU rasterizer).
Spectrum GetGroundIrradiance(IN(IrradianceTexture) irradiance_texture, Number mu_s) {
    Number x = clamp((mu_s * 0.5 + 0.5) * Number(IRRADIANCE_TEXTURE_WIDTH - 1), Number(0.0),
                     Number(IRRADIANCE_TEXTURE_WIDTH - 1));
    int i = min(int(floor(x)), IRRADIANCE_TEXTURE_WIDTH - 2);
    Number f = x - Number(i);
    return Spectrum(texelFetch(irradiance_texture, ivec2(i, 0), 0)) * (1.0 - f) +
           Spectrum(texelFetch(irradiance_texture, ivec2(i + 1, 0), 0)) * f;
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
//
// Quadrature: the midpoint rule on a 16 x 32 grid in (theta, phi), omega at
// phi = 0 (unchanged; tests/test_scattering_density_quadrature.cpp measures it
// against a 128 x 256 grid). The cost was in reading the previous order, not in
// the sum, so the reads are hoisted out of the grid without moving a node:
//  - on a ring (fixed theta) only nu1, the angle to the sun, varies, and a
//    scattering table is linear in nu between its SCATTERING_TEXTURE_NU_SIZE
//    slices (GetScatteringAtUvwz): the ring reads each slice once and every
//    direction interpolates between two of them as GetScatteringAtUvwz would
//    (NU_SIZE fetches per ring and table instead of 2 per direction);
//  - the ground seen along a ring is at one distance and transmittance, and the
//    sun's cosine there is (r mu_s + d nu1) / |r z + d omega_i|, one norm per
//    ring; its irradiance is a lerp along the table's bottom row;
//  - the phase functions depend on omega . omega_i, equal at phi and -phi: one
//    evaluation serves both directions of a pair.
// Same nodes, same weights: the result is the per-direction form's to rounding
// (1e-14 in double; full GPU tables within 2.7e-6 of it); on llvmpipe the pass
// takes a third of the time, an order 2.3-2.5 times less (docs/PERFORMANCE.md, 2026-12-02). MAX_NU_SIZE bounds
// SCATTERING_TEXTURE_NU_SIZE (checked in C++: kMaxScatteringNuSize, reference_tables.h).
Spectrum ComputeScatteringDensity(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                                  IN(ScatteringTexture) single_rayleigh_scattering_texture,
                                  IN(ScatteringTexture) single_mie_scattering_texture,
                                  IN(ScatteringTexture) multiple_scattering_texture,
                                  IN(IrradianceTexture) irradiance_texture, Length r, Number mu, Number mu_s,
                                  Number nu, int scattering_order) {
    vec3 omega = vec3(sqrt(1.0 - mu * mu), 0.0, mu);
    Number sun_dir_x = omega.x == 0.0 ? 0.0 : (nu - mu * mu_s) / omega.x;
    Number sun_dir_y = sqrt(max(1.0 - sun_dir_x * sun_dir_x - mu_s * mu_s, 0.0));
    vec3 omega_s = vec3(sun_dir_x, sun_dir_y, mu_s);

    const int SAMPLE_COUNT = 16;
    const Number dphi = PI / Number(SAMPLE_COUNT);
    const Number dtheta = PI / Number(SAMPLE_COUNT);
    const Number cos_dphi = cos(dphi);
    const Number sin_dphi = sin(dphi);
    const int MAX_NU_SIZE = 16;
    // The phase functions are integrated on the same grid as the light and each
    // sum divided by the grid's integral of its phase function: the grid's cells
    // (11 degrees) are as wide as a Mie forward peak (g = 0.8), whose sum over them
    // is far from 1, and every order multiplied the error: a thick haze gave 1.3
    // times the light it received. Normalized, the grid scatters exactly the light
    // that arrives (an isotropic radiance comes out as it went in).
    Spectrum rayleigh_sum = Spectrum(0.0);
    Spectrum mie_sum = Spectrum(0.0);
    Number rayleigh_norm = 0.0;
    Number mie_norm = 0.0;
    Number rayleigh_density = GetProfileDensity(atmosphere.rayleigh_density, r - atmosphere.bottom_radius);
    Number mie_density = GetProfileDensity(atmosphere.mie_density, r - atmosphere.bottom_radius);
    bool single = scattering_order == 2;  // the previous order is single scattering (phase not folded in)
    // The previous order on the current ring, slice by slice in nu: Rayleigh (or
    // the multiple scattering table after order 2) and Mie.
    Spectrum ring_a[MAX_NU_SIZE];
    Spectrum ring_b[MAX_NU_SIZE];
    Number nu_scale = 0.5 * Number(SCATTERING_TEXTURE_NU_SIZE - 1);

    for (int l = 0; l < SAMPLE_COUNT; ++l) {
        Number theta = (Number(l) + 0.5) * dtheta;
        Number cos_theta = cos(theta);
        Number sin_theta = sin(theta);
        bool ray_r_theta_intersects_ground = RayIntersectsGround(atmosphere, r, cos_theta);

        vec4 uvwz = GetScatteringTextureUvwzFromRMuMuSNu(atmosphere, r, cos_theta, mu_s, -1.0,
                                                         ray_r_theta_intersects_ground);
        for (int k = 0; k < SCATTERING_TEXTURE_NU_SIZE; ++k) {
            vec3 uvw = vec3((Number(k) + uvwz.y) / Number(SCATTERING_TEXTURE_NU_SIZE), uvwz.z, uvwz.w);
            if (single) {
                ring_a[k] = Spectrum(texture(single_rayleigh_scattering_texture, uvw));
                ring_b[k] = Spectrum(texture(single_mie_scattering_texture, uvw));
            } else {
                ring_a[k] = Spectrum(texture(multiple_scattering_texture, uvw));
            }
        }

        // Light reflected by the ground in this direction, if the ray hits it:
        // albedo / pi times the irradiance there, seen through the transmittance.
        Length distance_to_ground = 0.0;
        Length ground_point_radius = atmosphere.bottom_radius;
        Spectrum ground_reflectance = Spectrum(0.0);
        if (ray_r_theta_intersects_ground) {
            distance_to_ground = DistanceToBottomAtmosphereBoundary(atmosphere, r, cos_theta);
            ground_point_radius = sqrt(r * r + 2.0 * r * cos_theta * distance_to_ground +
                                       distance_to_ground * distance_to_ground);
            ground_reflectance =
                GetTransmittance(atmosphere, transmittance_texture, r, cos_theta, distance_to_ground, true) *
                atmosphere.ground_albedo * (1.0 / PI);
        }

        Number domega_i = dtheta * dphi * sin_theta;
        Number cos_phi = cos(0.5 * dphi);  // phi = (m + 0.5) dphi, stepped by a rotation
        Number sin_phi = sin(0.5 * dphi);
        for (int m = 0; m < SAMPLE_COUNT; ++m) {
            // The directions at phi and -phi: omega_i = (cos phi sin theta, +-sin phi sin theta, cos theta).
            Number x_i = cos_phi * sin_theta;
            Number y_i = sin_phi * sin_theta;
            Number cos_next = cos_phi * cos_dphi - sin_phi * sin_dphi;
            sin_phi = sin_phi * cos_dphi + cos_phi * sin_dphi;
            cos_phi = cos_next;
            Number nu1_even = omega_s.x * x_i + omega_s.z * cos_theta;
            Number nu1_odd = omega_s.y * y_i;
            Spectrum incident_radiance = Spectrum(0.0);
            for (int side = 0; side < 2; ++side) {
                Number nu1 = side == 0 ? nu1_even + nu1_odd : nu1_even - nu1_odd;
                // GetScatteringAtUvwz's interpolation between the nu slices, as hat
                // weights over all of them (constant indices: the arrays stay in registers).
                Number x = clamp((nu1 + 1.0) * nu_scale, Number(0.0), Number(SCATTERING_TEXTURE_NU_SIZE - 1));
                Spectrum a = Spectrum(0.0);
                Spectrum b = Spectrum(0.0);
                for (int k = 0; k < SCATTERING_TEXTURE_NU_SIZE; ++k) {
                    Number w = max(1.0 - abs(x - Number(k)), Number(0.0));
                    a += ring_a[k] * w;
                    if (single) b += ring_b[k] * w;
                }
                if (single) {
                    incident_radiance += a * RayleighPhaseFunction(nu1) +
                                         b * MiePhaseFunction(atmosphere.mie_phase_function_g, nu1);
                } else {
                    incident_radiance += a;
                }
                if (ray_r_theta_intersects_ground) {
                    Number ground_mu_s = (r * mu_s + distance_to_ground * nu1) / ground_point_radius;
                    incident_radiance += ground_reflectance * GetGroundIrradiance(irradiance_texture, ground_mu_s);
                }
            }

            Number nu2 = omega.x * x_i + omega.z * cos_theta;
            Number rayleigh_phase = RayleighPhaseFunction(nu2) * domega_i;
            Number mie_phase = MiePhaseFunction(atmosphere.mie_phase_function_g, nu2) * domega_i;
            rayleigh_sum += incident_radiance * rayleigh_phase;
            mie_sum += incident_radiance * mie_phase;
            rayleigh_norm += 2.0 * rayleigh_phase;
            mie_norm += 2.0 * mie_phase;
        }
    }
    return atmosphere.rayleigh_scattering * rayleigh_density * (rayleigh_sum / rayleigh_norm) +
           atmosphere.mie_scattering * mie_density * (mie_sum / mie_norm);
}

// One more order of scattering: the scattering density integrated along the
// ray with transmittance (Elek Eq. 13, Sperlhofer Eq. 2-11).
Spectrum ComputeMultipleScattering(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                                   IN(ScatteringTexture) scattering_density_texture, Length r, Number mu,
                                   Number mu_s, Number nu, bool ray_r_mu_intersects_ground) {
    const int SAMPLE_COUNT = 50;
    Length dx =
        DistanceToNearestAtmosphereBoundary(atmosphere, r, mu, ray_r_mu_intersects_ground) / Number(SAMPLE_COUNT);
    // The density J (a table, linear between samples) times the transmittance
    // from the ray's origin (exponential between samples; see ExpLinearMean).
    Spectrum rayleigh_mie_sum = Spectrum(0.0);
    Spectrum log_transmittance_previous = Spectrum(0.0);
    Spectrum density_previous = Spectrum(0.0);
    for (int i = 0; i <= SAMPLE_COUNT; ++i) {
        Length d_i = Number(i) * dx;
        // The point by rho_i^2 and r_i mu_i, as GetLogTransmittance takes it.
        Area H2 = (atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius);
        Area rho_i2 = clamp(d_i * (d_i + 2.0 * r * mu) +
                                (r - atmosphere.bottom_radius) * (r + atmosphere.bottom_radius),
                            Area(0.0), H2);
        Length r_i = sqrt(rho_i2 + atmosphere.bottom_radius * atmosphere.bottom_radius);
        Number mu_s_i = ClampCosine((r * mu_s + d_i * nu) / r_i);
        Spectrum density_i = GetScatteringAtUvwz(
            scattering_density_texture, GetScatteringTextureUvwzFromRRho2RMu(atmosphere, r_i, rho_i2, r * mu + d_i, mu_s_i,
                                                                             nu, ray_r_mu_intersects_ground));
        Spectrum log_transmittance_i =
            GetLogTransmittance(atmosphere, transmittance_texture, r, mu, d_i, ray_r_mu_intersects_ground);
        if (i > 0)
            rayleigh_mie_sum += ExpLinearMeanSpectrum(log_transmittance_previous, log_transmittance_i,
                                                      density_previous, density_i) *
                                dx;
        log_transmittance_previous = log_transmittance_i;
        density_previous = density_i;
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
