#include "atmosphere/parameters.h"

#include <cmath>

namespace planet::atmosphere {

namespace {
constexpr double kPerMToPerKm = 1000.0;
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
    p.top_radius = a.top_radius_km;
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
