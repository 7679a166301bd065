#include "atmosphere/parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene/toml_error.h"

namespace planet::atmosphere {

namespace {
constexpr double kPerMToPerKm = 1000.0;

double largest(const glm::dvec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
}  // namespace

double airThicknessKm(const AtmosphereParams& a, double planetRadiusKm) {
    const double preset = a.top_radius_km - planetRadiusKm;
    double air = 0.0;  // the highest altitude at which any particles still count
    auto exponential = [&](double coefficientPerM, double scaleHeightKm) {
        const double verticalDepth = coefficientPerM * kPerMToPerKm * scaleHeightKm;  // from the ground up
        if (verticalDepth > kNegligibleOpticalDepth)
            air = std::max(air, scaleHeightKm * std::log(verticalDepth / kNegligibleOpticalDepth));
    };
    exponential(largest(a.rayleigh_scattering_per_m), a.rayleigh_scale_height_km);
    exponential(largest(a.mie_extinction_per_m), a.mie_scale_height_km);
    if (largest(a.ozone_absorption_per_m) > 0.0) air = std::max(air, a.ozone_peak_altitude_km + a.ozone_width_km / 2.0);
    if (air <= 0.0) return preset;  // no particles: nothing to cut
    return std::min(preset, std::max(air, minAtmosphereThicknessKm(planetRadiusKm)));
}

double minAtmosphereThicknessKm(double planetRadiusKm) {
    return std::max(kMinAtmosphereThicknessKm, kMinAtmosphereThicknessPerRadius * planetRadiusKm);
}

double minScaleHeightKm(double planetRadiusKm) { return kMinScaleHeightPerRadius * planetRadiusKm; }

HorizontalOpticalDepth horizontalOpticalDepth(const AtmosphereParameters& atmosphere) {
    Model model(TableSizes::reduced());  // the sizes play no part in the optical length
    auto length = [&](const DensityProfile& profile) {
        return model.ComputeOpticalLengthToTopAtmosphereBoundary(atmosphere, profile, atmosphere.bottom_radius, 0.0);
    };
    HorizontalOpticalDepth depth;
    depth.rayleigh = atmosphere.rayleigh_scattering * length(atmosphere.rayleigh_density);
    depth.mie = atmosphere.mie_extinction * length(atmosphere.mie_density);
    depth.ozone = atmosphere.absorption_extinction * length(atmosphere.absorption_density);
    return depth;
}

namespace {

// Values in messages: whole numbers from 100 on, three significant digits below.
std::string number(double value) {
    char text[48];
    std::snprintf(text, sizeof text, std::abs(value) >= 100.0 ? "%.0f" : "%.3g", value);
    return text;
}

std::string km(double value) { return number(value) + " km"; }

bool holdsParticles(const AtmosphereParams& a) {
    return largest(a.rayleigh_scattering_per_m) > 0.0 || largest(a.mie_extinction_per_m) > 0.0 ||
           largest(a.ozone_absorption_per_m) > 0.0;
}

}  // namespace

std::vector<AtmosphereLimitProblem> checkAtmosphereLimits(const Scene& scene) {
    std::vector<AtmosphereLimitProblem> problems;
    const AtmosphereParams& a = scene.atmosphere;
    const double radius = scene.planet.radius_km;
    if (!holdsParticles(a)) return problems;
    if (radius < kMinAtmospherePlanetRadiusKm || radius > kMaxAtmospherePlanetRadiusKm) {
        problems.push_back({"planet.radius_km",
                            "a planet of " + km(radius) + " with an atmosphere must measure " +
                                km(kMinAtmospherePlanetRadiusKm) + " to " + km(kMaxAtmospherePlanetRadiusKm) +
                                ": the atmosphere tables hold positions as floats in km, too coarse beyond " +
                                km(kMaxAtmospherePlanetRadiusKm) +
                                " for rays grazing the ground, and the rays that hit a smaller planet are too few "
                                "for their view-angle axis (an airless planet may take any radius in range)"});
        return problems;  // the other limits scale with the radius
    }
    const double minHeight = minScaleHeightKm(radius);
    for (const auto& [field, height] : {std::pair<const char*, double>{"atmosphere.rayleigh_scale_height_km",
                                                                       a.rayleigh_scale_height_km},
                                        {"atmosphere.mie_scale_height_km", a.mie_scale_height_km}}) {
        if (height >= minHeight) continue;
        problems.push_back({field, "scale height " + km(height) + " is below " + formatNumber(kMinScaleHeightPerRadius) +
                                       " of planet.radius_km (" + km(minHeight) + " for " + km(radius) +
                                       "): the tables' float positions of rays grazing the ground are too coarse "
                                       "for a thinner layer"});
    }
    const double thickness = a.top_radius_km - radius;
    const double minThickness = minAtmosphereThicknessKm(radius);
    if (thickness < minThickness) {
        problems.push_back({"atmosphere.top_radius_km",
                            "the atmosphere is " + km(thickness) + " thick (top_radius_km - planet.radius_km), below " +
                                km(minThickness) + " (at least " + km(kMinAtmosphereThicknessKm) + " and " +
                                formatNumber(kMinAtmosphereThicknessPerRadius) +
                                " of the radius): the tables' altitude axis would span only a few float steps"});
    }
    if (!problems.empty()) return problems;

    const HorizontalOpticalDepth depth = horizontalOpticalDepth(atmosphere::makeAtmosphereParameters(scene));
    const glm::dvec3 total = depth.total();
    int channel = 0;
    for (int c = 1; c < 3; ++c)
        if (total[c] > total[channel]) channel = c;
    if (!(total[channel] <= kMaxHorizontalOpticalDepth)) {
        static const char* names[3] = {"R", "G", "B"};
        const double r = depth.rayleigh[channel], m = depth.mie[channel], o = depth.ozone[channel];
        const char* field = r >= m && r >= o ? "atmosphere.rayleigh_scattering_per_m"
                            : m >= o         ? "atmosphere.mie_extinction_per_m"
                                             : "atmosphere.ozone_absorption_per_m";
        const char* height = r >= m && r >= o ? " or rayleigh_scale_height_km"
                             : m >= o         ? " or mie_scale_height_km"
                                              : " or ozone_width_km";
        problems.push_back({field, "the air is too thick for the atmosphere tables: a horizontal ray from the ground "
                                   "crosses optical depth " +
                                       number(total[channel]) + " in channel " + names[channel] +
                                       " (Rayleigh " + number(r) + ", Mie " + number(m) + ", ozone " +
                                       number(o) + "), above " + formatNumber(kMaxHorizontalOpticalDepth) +
                                       ": the single-precision transmittance of the rays grazing the ground "
                                       "underflows; lower this" + height});
    }
    return problems;
}

DensityProfile exponentialProfile(double scaleHeightKm) {
    DensityProfile p{};
    p.layers[0] = DensityProfileLayer{0.0, 0.0, 0.0, 0.0, 0.0};  // width 0: layer 1 applies everywhere
    p.layers[1] = DensityProfileLayer{0.0, 1.0, -1.0 / scaleHeightKm, 0.0, 0.0};
    return p;
}

DensityProfile tentProfile(double peakKm, double widthKm) {
    const double half = widthKm / 2.0;
    DensityProfile p{};
    p.layers[0] = DensityProfileLayer{peakKm, 0.0, 0.0, 1.0 / half, 1.0 - peakKm / half};   // rising side
    p.layers[1] = DensityProfileLayer{0.0, 0.0, 0.0, -1.0 / half, 1.0 + peakKm / half};     // falling side
    return p;
}

DensityProfile emptyProfile() {
    DensityProfile p{};
    p.layers[0] = DensityProfileLayer{0.0, 0.0, 0.0, 0.0, 0.0};
    p.layers[1] = DensityProfileLayer{0.0, 0.0, 0.0, 0.0, 0.0};
    return p;
}

AtmosphereParameters makeAtmosphereParameters(const Scene& scene) {
    const AtmosphereParams& a = scene.atmosphere;
    AtmosphereParameters p{};
    p.solar_irradiance = scene.sun.irradiance;
    p.sun_angular_radius = scene.sun.angular_radius_rad;
    p.bottom_radius = scene.planet.radius_km;
    p.top_radius = scene.planet.radius_km + airThicknessKm(a, scene.planet.radius_km);
    p.rayleigh_density = exponentialProfile(a.rayleigh_scale_height_km);
    p.rayleigh_scattering = a.rayleigh_scattering_per_m * kPerMToPerKm;
    p.mie_density = exponentialProfile(a.mie_scale_height_km);
    p.mie_scattering = a.mie_scattering_per_m * kPerMToPerKm;
    p.mie_extinction = a.mie_extinction_per_m * kPerMToPerKm;
    p.mie_phase_function_g = a.mie_g;
    p.absorption_density = tentProfile(a.ozone_peak_altitude_km, a.ozone_width_km);
    p.absorption_extinction = a.ozone_absorption_per_m * kPerMToPerKm;
    p.ground_albedo = a.ground_albedo;
    p.mu_s_min = std::sin(glm::radians(a.min_sun_elevation_deg));
    p.elek_rayleigh_phase = a.elek_rayleigh_phase ? 1.0 : 0.0;
    return p;
}

}  // namespace planet::atmosphere
