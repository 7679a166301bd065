// The cloud layer's model, shared by GLSL and C++ (src/clouds/cloud_model.h compiles this
// text in double, as the atmosphere's model is): geometry of the layer, Michelic's height
// signal and density (Eq. 12-14), the phase function, and one march step of Beer-Lambert
// transmittance and in-scattering (Eq. 15-16). Lengths in km, positions from the planet
// centre; extinction and scattering per km at density 1. Written in the subset of GLSL
// that is also C++: Number/Length/vec3 names, single-component access, IN/OUT macros.
//
// Michelic §5: "We define a cloud layer with a top and bottom radius and tile the cloud
// texture in world space across the planet"; values of the texture < 0 mean "no cloud
// within the zero-density border", so a march may take a large step there (fig. 9).

#ifndef IN
#define IN(x) const in x
#endif
#ifndef OUT
#define OUT(x) out x
#endif
#ifndef INOUT
#define INOUT(x) inout x
#endif

const Number CLOUD_PI = 3.14159265358979323846;

// Michelic Eq. 13: 1 in the middle of the layer, 0 at its bottom (l_b) and top (l_t).
Number CloudHeightSignal(Length r, Length bottom_radius, Length top_radius) {
    Number x = 2.0 * clamp(r - bottom_radius, Length(0.0), top_radius - bottom_radius) / (top_radius - bottom_radius) -
               1.0;
    return 1.0 - x * x;
}

// Coverage applied to a texture value in [0, 1]: the value's top `coverage` fraction is
// kept and stretched back to [0, 1] (Schneider's remap), so coverage 0 leaves no cloud and
// coverage 1 the texture as baked. Negative values (empty space) pass through.
Number CloudCoverageRemap(Number texture_value, Number coverage) {
    if (texture_value < 0.0) return texture_value;
    if (coverage <= 0.0) return Number(0.0);
    return clamp((texture_value - (1.0 - coverage)) / coverage, Number(0.0), Number(1.0));
}

// The density of a texture value at height signal h under the local coverage: Eq. 14's h x value,
// remapped by the coverage (CloudCoverageRemap) after h rather than before, as Schneider's clouds take
// their height gradient. Where h is small (towards a cloud's bottom and top) a value must be high to
// stay cloud, so a cloud narrows towards its top and bottom, and where a weather field ends (the
// coverage falling) its flanks round off. The first form, h x remap(value), kept a cloud's cross-section
// the same at every height: each field ended in a wall as tall as its profile, under a flat lid (at
// 40 per km even the profile's faint top is opaque), a bank with vertical sides seen from the side (the
// `mountains` view). With the whole coverage (1) it is Eq. 14 exactly; a narrower cloud than the volume's
// where the coverage is partial, whose cross-section at mid-height (h = 1) is the first form's. -1 (no
// cloud, a large step is safe) where the texture says so.
Number CloudDensityFromTextureAndCoverage(Number texture_value, Number height_signal, Number coverage) {
    if (texture_value < 0.0) return Number(-1.0);
    return CloudCoverageRemap(height_signal * texture_value, coverage);
}

// The coverage at a place: the weather map's coverage there (mean 1/2 over the sphere)
// scaled by the layer's coverage parameter so that the parameter is the mean over the
// sphere: below 1/2 the map is scaled down to 0, above it the map is raised towards
// overcast (1 everywhere at 1). Piecewise linear, continuous at 1/2 where it is the map.
Number CloudLocalCoverage(Number map_coverage, Number coverage) {
    return coverage <= 0.5 ? 2.0 * coverage * map_coverage
                           : map_coverage + (2.0 * coverage - 1.0) * (1.0 - map_coverage);
}

// The per-type vertical profile (noise/weather_map.h): at a height `fraction` of the layer
// (0 bottom, 1 top) a cloud of type t (0 stratus, 0.5 cumulus, 1 high thin cloud) fills
// [b(t), c(t)], piecewise linear through (t, b, c) = (0, 0, 0.25), (0.5, 0, 0.7),
// (1, 0.8, 1), faded inside that interval the way Eq. 13 fades the whole layer.
void CloudTypeBounds(Number type, OUT(Number) bottom, OUT(Number) top) {
    Number t = clamp(type, Number(0.0), Number(1.0));
    bottom = t <= 0.5 ? Number(0.0) : 1.6 * (t - 0.5);
    top = t <= 0.5 ? 0.25 + 0.9 * t : 0.7 + 0.6 * (t - 0.5);
}

Number CloudTypeHeightSignal(Number fraction, Number type) {
    Number b;
    Number c;
    CloudTypeBounds(type, b, c);
    if (fraction <= b || fraction >= c) return Number(0.0);
    Number x = 2.0 * (fraction - b) / (c - b) - 1.0;
    return 1.0 - x * x;
}

// The share of the layer's depth a cloud of type t spans (c(t) - b(t) above).
Number CloudTypeProfileWidth(Number type) {
    Number b;
    Number c;
    CloudTypeBounds(type, b, c);
    return c - b;
}

// The far field: where a pixel's footprint spans many voxels, the volume would only alias
// (speckle from orbit), so the density becomes a smooth one whose vertical column has the
// transmittance 1 - coverage: looking down, the share of the ground a cloud field hides is
// its coverage, as in a satellite image. With height signal h, the column of h is
// column_fraction x depth (2/3 of the profile's span for Eq. 13's parabola), so
//   density = h (-ln(1 - coverage')) / (extinction x column_fraction x depth),
// coverage' = 0.98 coverage keeping the overcast column finite (T = 2 %).
Number CloudFarFieldDensity(Number coverage, Number height_signal, Number column_fraction, Length depth,
                            Number extinction) {
    Number tau = -log(1.0 - 0.98 * clamp(coverage, Number(0.0), Number(1.0)));
    return height_signal * tau / max(extinction * column_fraction * depth, Number(1e-9));
}

// The part of Eq. 13's parabola 4x(1 - x) above u on its own span (u in [0, 1]):
// integral from u to 1 of 4x(1 - x) dx = 2/3 - 2u^2 + 4u^3/3 (2/3 below the span, 0 above).
Number CloudProfileAbove(Number u) {
    Number x = clamp(u, Number(0.0), Number(1.0));
    return 2.0 / 3.0 - 2.0 * x * x + 4.0 / 3.0 * x * x * x;
}

// The far field's optical depth per unit extinction (density x km) along `way` km of a
// straight path whose ends lie at ua and ub of the cloud's span (0 its bottom, 1 its top;
// `span` its share of the layer's `depth`), heights taken as linear along the path: the
// field of CloudFarFieldDensity, in closed form, h averaged over [ua, ub] as
// (CloudProfileAbove(ua) - CloudProfileAbove(ub)) / (ub - ua).
Number CloudFarFieldPath(Number coverage, Number span, Number ua, Number ub, Length way, Length depth,
                         Number extinction) {
    Number um = clamp(0.5 * (ua + ub), Number(0.0), Number(1.0));
    Number mean_h = abs(ub - ua) < 1e-4 ? (0.5 * (ua + ub) == um ? 4.0 * um * (1.0 - um) : Number(0.0))
                                         : (CloudProfileAbove(ua) - CloudProfileAbove(ub)) / (ub - ua);
    Number tau = -log(1.0 - 0.98 * clamp(coverage, Number(0.0), Number(1.0)));
    return way * mean_h * tau / max(extinction * (2.0 / 3.0) * span * depth, Number(1e-9));
}

// Henyey-Greenstein phase function, per steradian, for the cosine between the light's
// direction of travel and the direction towards the viewer (1 = straight through).
Number HenyeyGreenstein(Number g, Number cos_theta) {
    Number denominator = 1.0 + g * g - 2.0 * g * cos_theta;
    return (1.0 - g * g) / (4.0 * CLOUD_PI * denominator * sqrt(denominator));
}

// A forward lobe and a back lobe, mixed (back_weight 0: one lobe, Michelic's HG).
Number CloudPhase(Number g_forward, Number g_back, Number back_weight, Number cos_theta) {
    return (1.0 - back_weight) * HenyeyGreenstein(g_forward, cos_theta) +
           back_weight * HenyeyGreenstein(g_back, cos_theta);
}

// Where a ray from `origin` (|origin| = r, mu = cosine of its zenith angle) crosses the
// sphere of radius `radius`: the nearer (sign -1) or farther (sign +1) root, or -1 when it
// does not. Discriminant written as (r mu)^2 - (r - R)(r + R) (Sperlhofer 5.1) for grazing rays.
Length CloudRaySphere(Length r, Number mu, Length radius, Number root_sign) {
    Length rmu = r * mu;
    Length discriminant = rmu * rmu - (r - radius) * (r + radius);
    if (discriminant < 0.0) return Length(-1.0);
    return -rmu + root_sign * sqrt(discriminant);
}

// The parts of the ray [0, max_distance] inside the shell bottom_radius <= |p| <= top_radius:
// up to two intervals, returned in order; the count is the return value. A ray from
// inside the shell starts at 0; one that dips below the bottom sphere leaves the shell there
// and may come back; one that grazes the top may cross only the top part.
int CloudLayerIntervals(Length r, Number mu, Length max_distance, Length bottom_radius, Length top_radius,
                        OUT(vec2) first, OUT(vec2) second) {
    first = vec2(0.0, 0.0);
    second = vec2(0.0, 0.0);
    // The ray's parameters where it is inside the top sphere: [top_in, top_out].
    Length top_in = 0.0;
    Length top_out = 0.0;
    if (r > top_radius) {
        top_in = CloudRaySphere(r, mu, top_radius, -1.0);
        if (top_in < 0.0 || mu >= 0.0) return 0;  // misses the layer, or goes away from it
        top_out = CloudRaySphere(r, mu, top_radius, 1.0);
    } else {
        top_out = CloudRaySphere(r, mu, top_radius, 1.0);
    }
    // Where it is inside the bottom sphere (the hole of the shell): [bottom_in, bottom_out].
    Length bottom_in = -1.0;
    Length bottom_out = -1.0;
    if (r < bottom_radius) {
        bottom_in = 0.0;
        bottom_out = CloudRaySphere(r, mu, bottom_radius, 1.0);
    } else {
        Length t = CloudRaySphere(r, mu, bottom_radius, -1.0);
        if (t >= 0.0 && mu < 0.0) {
            bottom_in = t;
            bottom_out = CloudRaySphere(r, mu, bottom_radius, 1.0);
        }
    }
    int count = 0;
    Length a = top_in;
    Length b = top_out;
    if (bottom_in >= 0.0 && bottom_out > a) {
        // [a, bottom_in] and [bottom_out, b]
        if (bottom_in > a) {
            first = vec2(a, min(bottom_in, max_distance));
            count = 1;
        }
        a = max(a, bottom_out);
    }
    if (b > a && a < max_distance) {
        vec2 part = vec2(a, min(b, max_distance));
        if (count == 0) {
            first = part;
        } else {
            second = part;
        }
        count = count + 1;
    }
    if (count >= 1 && first.x >= max_distance) count = 0;
    return count;
}

// One march step of length `step` (km) through density `density` (>= 0), lit by `source`
// (the radiance scattered towards the viewer per unit scattering coefficient: phase times
// the light arriving, plus the ambient term), updating the transmittance since the segment
// began (Eq. 15) and the in-scattered light (Eq. 16).
//   energy_conserving: the step's in-scattering integrated over its own extinction,
//     S src (1 - exp(-E d step)) / (E d) (Hillaire 2016), so the result does not depend on
//     the step size for a constant source;
//   otherwise Michelic's sum as written: S src step d T_n, with T_n after the step.
void CloudMarchStep(Number density, Length step, Number extinction, Number scattering, IN(vec3) source,
                    bool energy_conserving, INOUT(vec3) transmittance, INOUT(vec3) inscatter) {
    Number optical = extinction * density * step;
    Number step_transmittance = exp(-optical);
    if (energy_conserving) {
        Number integral = optical > 1e-7 ? (1.0 - step_transmittance) / (extinction * density)
                                         : step * (1.0 - 0.5 * optical);  // the same, for a thin step
        inscatter = inscatter + transmittance * (scattering * density * integral) * source;
        transmittance = transmittance * step_transmittance;
    } else {
        transmittance = transmittance * step_transmittance;                     // Eq. 15
        inscatter = inscatter + transmittance * (scattering * step * density) * source;  // Eq. 16
    }
}

// Michelic Eq. 19-20: a slice of the view ray with atmosphere transmittance T_A and
// in-scattering I_A, and clouds T_C, I_C, added to the totals so far (T, I).
void CombineSlice(IN(vec3) atmosphere_transmittance, IN(vec3) atmosphere_inscatter, IN(vec3) cloud_transmittance,
                  IN(vec3) cloud_inscatter, INOUT(vec3) transmittance, INOUT(vec3) inscatter) {
    inscatter = inscatter + (atmosphere_inscatter * cloud_transmittance + cloud_inscatter) * transmittance;  // Eq. 20
    transmittance = transmittance * atmosphere_transmittance * cloud_transmittance;                     // Eq. 19
}
