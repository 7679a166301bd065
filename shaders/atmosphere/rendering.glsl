// Atmosphere lookups at render time, shared by GLSL and C++ (see functions.glsl).
//
// Sky radiance along a view ray (Sperlhofer Eq. 2-16), in-scattering and
// transmittance between the camera and a surface point for aerial perspective
// (Sperlhofer Eq. 4-16, 4-18; Elek Eq. 19-20), and the sun and sky irradiance
// of a surface point (Elek Eq. 17, 20). Positions are relative to the planet
// centre, in km. Sperlhofer 5.1 horizon fixes: in-scattering near the horizon
// is interpolated from samples above and below it (5.1.2) and single Mie
// scattering fades out as the sun sets (5.1.3).
//
// Every lookup takes `elek_table`: false reads Bruneton's 4D table (r, mu, mu_s, nu),
// true Elek's 3D table (elek_table.glsl; include it first), passed in the same two
// ScatteringTexture arguments. The ray-level functions are written once for both; in
// GLSL the flag is a compile-time constant at every call (atmosphere/interface.glsl), so
// the unused lookup is folded away.

// The tables end at the lowest sun they cover (mu_s_min, about -12 deg on
// Earth) and clamp beyond it, which would repeat that twilight all night.
// Below it, fade to the dark night sky instead.
Number NightFade(IN(AtmosphereParameters) atmosphere, Number mu_s) {
    return smoothstep(atmosphere.mu_s_min - 0.05, atmosphere.mu_s_min, mu_s);
}

// Scattering table lookup returning the Rayleigh + multiple part and the single
// Mie part, both without phase functions.
Spectrum GetCombinedScattering(IN(AtmosphereParameters) atmosphere, IN(ScatteringTexture) scattering_texture,
                               IN(ScatteringTexture) single_mie_scattering_texture, Length r, Number mu, Number mu_s,
                               Number nu, bool ray_r_mu_intersects_ground, OUT(Spectrum) single_mie_scattering) {
    single_mie_scattering =
        GetScattering(atmosphere, single_mie_scattering_texture, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
    return GetScattering(atmosphere, scattering_texture, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
}

// Either table's lookup (see the file header): Rayleigh + multiple part returned, single
// Mie in `single_mie_scattering`, both phase-free.
Spectrum GetCombinedScatteringFrom(IN(AtmosphereParameters) atmosphere, bool elek_table,
                                   IN(ScatteringTexture) scattering_texture,
                                   IN(ScatteringTexture) single_mie_scattering_texture, Length r, Number mu,
                                   Number mu_s, Number nu, bool ray_r_mu_intersects_ground,
                                   OUT(Spectrum) single_mie_scattering) {
    if (elek_table)
        return GetCombinedScatteringElek(atmosphere, scattering_texture, single_mie_scattering_texture, r, mu, mu_s,
                                         ray_r_mu_intersects_ground, single_mie_scattering);
    return GetCombinedScattering(atmosphere, scattering_texture, single_mie_scattering_texture, r, mu, mu_s, nu,
                                 ray_r_mu_intersects_ground, single_mie_scattering);
}

// The same from r, rho^2 = r^2 - R^2 and mu (functions.glsl's render-time lookups from rho^2):
// what every lookup below calls, so a camera's altitude given apart reaches the table.
Spectrum GetCombinedScatteringRho2From(IN(AtmosphereParameters) atmosphere, bool elek_table,
                                       IN(ScatteringTexture) scattering_texture,
                                       IN(ScatteringTexture) single_mie_scattering_texture, Length r, Area rho2,
                                       Number mu, Number mu_s, Number nu, bool ray_r_mu_intersects_ground,
                                       OUT(Spectrum) single_mie_scattering) {
    if (elek_table)
        return GetCombinedScatteringElekRho2(atmosphere, scattering_texture, single_mie_scattering_texture, r, rho2,
                                             mu, mu_s, ray_r_mu_intersects_ground, single_mie_scattering);
    single_mie_scattering = GetScatteringRho2(atmosphere, single_mie_scattering_texture, r, rho2, r * mu, mu_s, nu,
                                              ray_r_mu_intersects_ground);
    return GetScatteringRho2(atmosphere, scattering_texture, r, rho2, r * mu, mu_s, nu, ray_r_mu_intersects_ground);
}

Spectrum ApplyPhaseFunctions(IN(AtmosphereParameters) atmosphere, IN(Spectrum) scattering,
                             IN(Spectrum) single_mie_scattering, Number nu) {
    return scattering * RenderRayleighPhaseFunction(atmosphere, nu) +
           single_mie_scattering * MiePhaseFunction(atmosphere.mie_phase_function_g, nu);
}

// A view ray as the tables parametrize it: radius, view, sun and view-sun
// cosines. A camera in space is moved to where its ray enters the atmosphere
// (`skipped` km on); `inside` is false when the ray never enters it. rho2 =
// r^2 - R^2, exact where the altitude was given apart (ViewRayInAtmosphereAt): every
// lookup takes the ray's start by rho2 and r mu, never by r - R.
struct ViewRay {
    Length r;
    Area rho2;
    Number mu;
    Number mu_s;
    Number nu;
    Length skipped;
    bool inside;
};

ViewRay ViewRayInAtmosphere(IN(AtmosphereParameters) atmosphere, IN(vec3) camera_position, IN(vec3) view_ray,
                            IN(vec3) sun_direction) {
    ViewRay ray;
    vec3 camera = camera_position;
    Length r = length(camera);
    Length rmu = dot(camera, view_ray);
    Length distance_to_top_atmosphere_boundary =
        -rmu - sqrt(rmu * rmu - (r - atmosphere.top_radius) * (r + atmosphere.top_radius));
    ray.skipped = 0.0;
    ray.inside = true;
    if (distance_to_top_atmosphere_boundary > 0.0) {
        camera = camera + view_ray * distance_to_top_atmosphere_boundary;
        r = atmosphere.top_radius;
        rmu += distance_to_top_atmosphere_boundary;
        ray.skipped = distance_to_top_atmosphere_boundary;
    } else if (r > atmosphere.top_radius) {
        ray.inside = false;
    }
    ray.r = r;
    ray.rho2 = (r - atmosphere.bottom_radius) * (r + atmosphere.bottom_radius);
    ray.mu = rmu / r;
    ray.mu_s = dot(camera, sun_direction) / r;
    ray.nu = dot(view_ray, sun_direction);
    return ray;
}

// The same for a camera given by its unit `up` (from the planet centre) and its
// `altitude` above the bottom radius (km), formed apart from the radius: in float a
// radius of planet size resolves half a metre, and a camera 0.1 m up would sit on the
// ground (its rays below the horizon of zero length). r^2 - R^2 = h (h + 2R) and mu =
// up . view keep the altitude; r = R + h only where its rounding is harmless.
ViewRay ViewRayInAtmosphereAt(IN(AtmosphereParameters) atmosphere, IN(vec3) up, Length altitude, IN(vec3) view_ray,
                              IN(vec3) sun_direction) {
    ViewRay ray;
    altitude = max(altitude, Length(0.0));  // a camera under the ground sees from the ground
    Length r = atmosphere.bottom_radius + altitude;
    Area rho2 = altitude * (altitude + 2.0 * atmosphere.bottom_radius);
    Area H2 = (atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius);
    Number mu = dot(up, view_ray);
    Length rmu = r * mu;
    Length rmu_s = r * dot(up, sun_direction);
    Length distance_to_top_atmosphere_boundary = -rmu - sqrt(rmu * rmu - (rho2 - H2));  // (r - T)(r + T) = rho2 - H2
    ray.skipped = 0.0;
    ray.inside = true;
    ray.nu = dot(view_ray, sun_direction);
    if (distance_to_top_atmosphere_boundary > 0.0) {
        r = atmosphere.top_radius;
        rho2 = H2;
        rmu += distance_to_top_atmosphere_boundary;
        rmu_s += distance_to_top_atmosphere_boundary * ray.nu;
        ray.skipped = distance_to_top_atmosphere_boundary;
    } else if (rho2 > H2) {
        ray.inside = false;
    }
    ray.r = r;
    ray.rho2 = rho2;
    ray.mu = ClampCosine(rmu / r);
    ray.mu_s = ClampCosine(rmu_s / r);
    return ray;
}

// Radiance scattered towards a camera at `camera` along `view_ray` up to the
// ground or space, without the ground's own reflected light or the sun disc.
// `transmittance` is that of the whole ray (0 if it hits the ground).
Spectrum GetSkyRadianceOfRay(IN(AtmosphereParameters) atmosphere, bool elek_table,
                             IN(TransmittanceTexture) transmittance_texture, IN(ScatteringTexture) scattering_texture,
                             IN(ScatteringTexture) single_mie_scattering_texture, IN(ViewRay) ray,
                             OUT(Spectrum) transmittance) {
    if (!ray.inside) {
        transmittance = Spectrum(1.0);  // the ray misses the atmosphere
        return Spectrum(0.0);
    }
    Length r = ray.r;
    Number mu = ray.mu;
    Number mu_s = ray.mu_s;
    Number nu = ray.nu;
    bool ray_r_mu_intersects_ground = RayIntersectsGroundRho2(ray.rho2, r * mu);

    transmittance = ray_r_mu_intersects_ground
                        ? Spectrum(0.0)
                        : GetTransmittanceToTopAtmosphereBoundaryRho2(atmosphere, transmittance_texture, ray.rho2, r * mu);
    Spectrum single_mie_scattering;
    Spectrum scattering =
        GetCombinedScatteringRho2From(atmosphere, elek_table, scattering_texture, single_mie_scattering_texture, r,
                                      ray.rho2, mu, mu_s, nu, ray_r_mu_intersects_ground, single_mie_scattering);
    return ApplyPhaseFunctions(atmosphere, scattering, single_mie_scattering, nu) * NightFade(atmosphere, mu_s);
}

Spectrum GetSkyRadianceFrom(IN(AtmosphereParameters) atmosphere, bool elek_table,
                            IN(TransmittanceTexture) transmittance_texture, IN(ScatteringTexture) scattering_texture,
                            IN(ScatteringTexture) single_mie_scattering_texture, IN(vec3) camera_position,
                            IN(vec3) view_ray, IN(vec3) sun_direction, OUT(Spectrum) transmittance) {
    return GetSkyRadianceOfRay(atmosphere, elek_table, transmittance_texture, scattering_texture,
                               single_mie_scattering_texture,
                               ViewRayInAtmosphere(atmosphere, camera_position, view_ray, sun_direction), transmittance);
}

// Transmittance from the camera to the end of its view ray: the ground where
// the ray hits it, else the top of the atmosphere (1 for a ray missing it).
// GetSkyRadiance reports 0 for ground rays, because the sky behind the ground
// is hidden; this is what `planet sky-probe` reports.
Spectrum GetViewRayTransmittanceOfRay(IN(AtmosphereParameters) atmosphere,
                                      IN(TransmittanceTexture) transmittance_texture, IN(ViewRay) ray) {
    if (!ray.inside) return Spectrum(1.0);
    Length r_mu = ray.r * ray.mu;
    if (!RayIntersectsGroundRho2(ray.rho2, r_mu))
        return GetTransmittanceToTopAtmosphereBoundaryRho2(atmosphere, transmittance_texture, ray.rho2, r_mu);
    return GetTransmittanceRho2(atmosphere, transmittance_texture, ray.rho2, r_mu, DistanceToGroundRho2(ray.rho2, r_mu),
                                true);
}
Spectrum GetViewRayTransmittance(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                                 IN(vec3) camera_position, IN(vec3) view_ray) {
    return GetViewRayTransmittanceOfRay(atmosphere, transmittance_texture,
                                        ViewRayInAtmosphere(atmosphere, camera_position, view_ray, view_ray));
}
Spectrum GetViewRayTransmittanceAt(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                                   IN(vec3) up, Length altitude, IN(vec3) view_ray) {
    return GetViewRayTransmittanceOfRay(atmosphere, transmittance_texture,
                                        ViewRayInAtmosphereAt(atmosphere, up, altitude, view_ray, view_ray));
}

// In-scattering between (r, mu) and the point at distance d along the ray
// (Sperlhofer Eq. 4-18: L(a->b) = L(a->inf) - T(a->b) L(b->inf)), phase-free.
Spectrum ScatteringBetween(IN(AtmosphereParameters) atmosphere, bool elek_table,
                           IN(TransmittanceTexture) transmittance_texture, IN(ScatteringTexture) scattering_texture,
                           IN(ScatteringTexture) single_mie_scattering_texture, Length r, Area rho2, Number mu,
                           Number mu_s, Number nu, Length d, OUT(Spectrum) transmittance,
                           OUT(Spectrum) single_mie_scattering) {
    bool ray_r_mu_intersects_ground = RayIntersectsGroundRho2(rho2, r * mu);
    transmittance = GetTransmittanceRho2(atmosphere, transmittance_texture, rho2, r * mu, d, ray_r_mu_intersects_ground);
    Spectrum scattering =
        GetCombinedScatteringRho2From(atmosphere, elek_table, scattering_texture, single_mie_scattering_texture, r,
                                      rho2, mu, mu_s, nu, ray_r_mu_intersects_ground, single_mie_scattering);
    // The far point by r_p^2 - R^2 = d (d + 2 r mu) + rho^2 (no planet-sized difference).
    Area H2 = (atmosphere.top_radius - atmosphere.bottom_radius) * (atmosphere.top_radius + atmosphere.bottom_radius);
    Area rho2_p = clamp(d * (d + 2.0 * r * mu) + rho2, Area(0.0), H2);
    Length r_p = ClampRadius(atmosphere, sqrt(rho2_p + atmosphere.bottom_radius * atmosphere.bottom_radius));
    Number mu_p = ClampCosine((r * mu + d) / r_p);
    Number mu_s_p = ClampCosine((r * mu_s + d * nu) / r_p);
    Spectrum single_mie_scattering_p;
    Spectrum scattering_p =
        GetCombinedScatteringRho2From(atmosphere, elek_table, scattering_texture, single_mie_scattering_texture, r_p,
                                      rho2_p, mu_p, mu_s_p, nu, ray_r_mu_intersects_ground, single_mie_scattering_p);
    single_mie_scattering = max(single_mie_scattering - transmittance * single_mie_scattering_p, Spectrum(0.0));
    return max(scattering - transmittance * scattering_p, Spectrum(0.0));
}

// Aerial perspective: radiance scattered towards the camera between the camera
// and the point at distance d (km) along the unit view ray, and the
// transmittance between them. Taking the ray and distance rather than the
// point keeps a point 2 m away exact: in float, point - camera at planet scale
// would be rounded to half a metre.
Spectrum GetSkyRadianceToPointOfRay(IN(AtmosphereParameters) atmosphere, bool elek_table,
                                    IN(TransmittanceTexture) transmittance_texture,
                                    IN(ScatteringTexture) scattering_texture,
                                    IN(ScatteringTexture) single_mie_scattering_texture, IN(ViewRay) ray,
                                    Length distance, Length shadow_length, OUT(Spectrum) transmittance) {
    if (!ray.inside) {
        transmittance = Spectrum(1.0);
        return Spectrum(0.0);
    }
    Length r = ray.r;
    Number mu = ray.mu;
    Number mu_s = ray.mu_s;
    Number nu = ray.nu;
    Length d_full = max(distance - ray.skipped, Length(0.0));
    // Bruneton's shadow_length (his Eq. 17 for light shafts): the last shadow_length of the
    // segment sees no sun, so the in-scattering stops that much short of the point; the
    // transmittance stays that of the whole segment.
    Length d = max(d_full - shadow_length, Length(0.0));

    // Sperlhofer 5.1.2: the table's two halves meet at the horizon, where the
    // difference of two large, nearly equal lookups is unreliable. Within EPS
    // of it, interpolate between rays just above and just below.
    // Written as a loop of one or two samples, not as an `if` around a second lookup: a
    // software renderer (llvmpipe) runs an `if` body for every pixel, masked, whether or
    // not one takes it, but leaves a loop once no pixel of its group wants another turn.
    // So the common ray costs one ScatteringBetween and only groups touching the horizon
    // (|mu - mu_horizon| < EPS) pay for the second; a GPU does the same per warp. The
    // sum (1 - a) S(mu_horizon - EPS) + a S(mu_horizon + EPS) is mix()'s formula, and a
    // ray away from the horizon takes one sample at weight 1 (the unblended value).
    const Number EPS = 0.004;
    Area rho2 = ray.rho2;
    Number mu_horizon = -SafeSqrt(rho2) / r;  // not -sqrt(1 - (R / r)^2), which loses a low camera's altitude
    bool near_horizon = abs(mu - mu_horizon) < EPS;
    Number a = (mu - mu_horizon + EPS) / (2.0 * EPS);
    int samples = near_horizon ? 2 : 1;
    Spectrum scattering = Spectrum(0.0);
    Spectrum single_mie_scattering = Spectrum(0.0);
    Spectrum transmittance_sum = Spectrum(0.0);
    for (int i = 0; i < samples; ++i) {
        // Below the horizon first: without the blend the one sample is mu itself.
        Number mu_i = near_horizon ? (i == 0 ? mu_horizon - EPS : mu_horizon + EPS) : mu;
        Number weight = near_horizon ? (i == 0 ? 1.0 - a : a) : Number(1.0);
        Spectrum transmittance_i;
        Spectrum mie_i;
        Spectrum scattering_i = ScatteringBetween(atmosphere, elek_table, transmittance_texture, scattering_texture,
                                                  single_mie_scattering_texture, r, rho2, mu_i, mu_s, nu, d,
                                                  transmittance_i, mie_i);
        if (shadow_length > Length(0.0))  // the whole segment's transmittance, blended as the rest
            transmittance_i = GetTransmittanceRho2(atmosphere, transmittance_texture, rho2, r * mu_i, d_full,
                                                   RayIntersectsGroundRho2(rho2, r * mu_i));
        scattering = scattering + scattering_i * weight;
        single_mie_scattering = single_mie_scattering + mie_i * weight;
        transmittance_sum = transmittance_sum + transmittance_i * weight;
    }
    transmittance = transmittance_sum;
    // Sperlhofer 5.1.3: single Mie scattering is unreliable once the sun has set.
    single_mie_scattering = single_mie_scattering * smoothstep(Number(0.0), Number(0.01), mu_s);
    return ApplyPhaseFunctions(atmosphere, scattering, single_mie_scattering, nu) * NightFade(atmosphere, mu_s);
}

Spectrum GetSkyRadianceToPointAlongRayFrom(IN(AtmosphereParameters) atmosphere, bool elek_table,
                                           IN(TransmittanceTexture) transmittance_texture,
                                           IN(ScatteringTexture) scattering_texture,
                                           IN(ScatteringTexture) single_mie_scattering_texture,
                                           IN(vec3) camera_position, IN(vec3) view_ray, Length distance,
                                           IN(vec3) sun_direction, Length shadow_length,
                                           OUT(Spectrum) transmittance) {
    return GetSkyRadianceToPointOfRay(atmosphere, elek_table, transmittance_texture, scattering_texture,
                                      single_mie_scattering_texture,
                                      ViewRayInAtmosphere(atmosphere, camera_position, view_ray, sun_direction),
                                      distance, shadow_length, transmittance);
}

// The lookups above with Bruneton's 4D table and with Elek's 3D table, by name.
Spectrum GetSkyRadiance(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                        IN(ScatteringTexture) scattering_texture, IN(ScatteringTexture) single_mie_scattering_texture,
                        IN(vec3) camera_position, IN(vec3) view_ray, IN(vec3) sun_direction,
                        OUT(Spectrum) transmittance) {
    return GetSkyRadianceFrom(atmosphere, false, transmittance_texture, scattering_texture,
                              single_mie_scattering_texture, camera_position, view_ray, sun_direction, transmittance);
}
Spectrum GetSkyRadianceElek(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                            IN(ScatteringTexture) elek_scattering_texture,
                            IN(ScatteringTexture) elek_single_mie_scattering_texture, IN(vec3) camera_position,
                            IN(vec3) view_ray, IN(vec3) sun_direction, OUT(Spectrum) transmittance) {
    return GetSkyRadianceFrom(atmosphere, true, transmittance_texture, elek_scattering_texture,
                              elek_single_mie_scattering_texture, camera_position, view_ray, sun_direction,
                              transmittance);
}
Spectrum GetSkyRadianceToPointAlongRay(IN(AtmosphereParameters) atmosphere,
                                       IN(TransmittanceTexture) transmittance_texture,
                                       IN(ScatteringTexture) scattering_texture,
                                       IN(ScatteringTexture) single_mie_scattering_texture, IN(vec3) camera_position,
                                       IN(vec3) view_ray, Length distance, IN(vec3) sun_direction,
                                       OUT(Spectrum) transmittance) {
    return GetSkyRadianceToPointAlongRayFrom(atmosphere, false, transmittance_texture, scattering_texture,
                                             single_mie_scattering_texture, camera_position, view_ray, distance,
                                             sun_direction, Length(0.0), transmittance);
}
Spectrum GetSkyRadianceToPointAlongRayElek(IN(AtmosphereParameters) atmosphere,
                                           IN(TransmittanceTexture) transmittance_texture,
                                           IN(ScatteringTexture) elek_scattering_texture,
                                           IN(ScatteringTexture) elek_single_mie_scattering_texture,
                                           IN(vec3) camera_position, IN(vec3) view_ray, Length distance,
                                           IN(vec3) sun_direction, OUT(Spectrum) transmittance) {
    return GetSkyRadianceToPointAlongRayFrom(atmosphere, true, transmittance_texture, elek_scattering_texture,
                                             elek_single_mie_scattering_texture, camera_position, view_ray, distance,
                                             sun_direction, Length(0.0), transmittance);
}

// The same for two points (positions relative to the planet centre, km).
Spectrum GetSkyRadianceToPoint(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                               IN(ScatteringTexture) scattering_texture,
                               IN(ScatteringTexture) single_mie_scattering_texture, IN(vec3) camera_position,
                               IN(vec3) point, IN(vec3) sun_direction, OUT(Spectrum) transmittance) {
    return GetSkyRadianceToPointAlongRay(atmosphere, transmittance_texture, scattering_texture,
                                         single_mie_scattering_texture, camera_position,
                                         normalize(point - camera_position), length(point - camera_position),
                                         sun_direction, transmittance);
}

// Irradiance of a surface point with a given normal: direct sun through the
// atmosphere (Elek Eq. 17) returned, sky irradiance (the precomputed horizontal
// value scaled for the tilt of the normal) in `sky_irradiance`.
Spectrum GetSunAndSkyIrradiance(IN(AtmosphereParameters) atmosphere, IN(TransmittanceTexture) transmittance_texture,
                                IN(IrradianceTexture) irradiance_texture, IN(vec3) point, IN(vec3) normal,
                                IN(vec3) sun_direction, OUT(Spectrum) sky_irradiance) {
    Length r = length(point);
    Number mu_s = dot(point, sun_direction) / r;
    sky_irradiance = GetIrradiance(atmosphere, irradiance_texture, r, mu_s) * (1.0 + dot(normal, point) / r) * 0.5 *
                     NightFade(atmosphere, mu_s);
    return atmosphere.solar_irradiance * GetTransmittanceToSun(atmosphere, transmittance_texture, r, mu_s) *
           max(dot(normal, sun_direction), Number(0.0));
}
