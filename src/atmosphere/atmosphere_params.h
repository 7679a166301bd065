// Atmosphere parameters as a user sets them (preset [atmosphere] section).
//
// SI units in the names. The bottom of the atmosphere is the planet's radius
// (planet.radius_km), so it has one source of truth. Earth defaults are those
// of Bruneton's 2017 model at 680, 550, 440 nm for R, G, B.
// Densities: Rayleigh and Mie fall off exponentially with altitude (Elek Eq. 8,
// Sperlhofer Eq. 2-5); ozone has a tent profile peaking at ozone_peak_altitude_km
// and zero outside ozone_width_km around it.
#pragma once

#include <glm/glm.hpp>

namespace planet {

struct AtmosphereParams {
    double top_radius_km = 6420.0;                                      // km, > planet radius, [1, 200000]
    glm::dvec3 rayleigh_scattering_per_m = {5.802e-6, 13.558e-6, 33.1e-6};  // 1/m at sea level, [0, 0.01]
    double rayleigh_scale_height_km = 8.0;                              // km, [0.01, 1000]
    glm::dvec3 mie_scattering_per_m = {3.996e-6, 3.996e-6, 3.996e-6};   // 1/m, [0, 0.01]
    glm::dvec3 mie_extinction_per_m = {4.44e-6, 4.44e-6, 4.44e-6};      // 1/m, >= scattering, [0, 0.01]
    double mie_scale_height_km = 1.2;                                   // km, [0.01, 1000]
    double mie_g = 0.8;                                                 // Cornette-Shanks asymmetry, [-0.999, 0.999]
    glm::dvec3 ozone_absorption_per_m = {0.650e-6, 1.881e-6, 0.085e-6}; // 1/m at the peak, [0, 0.01]
    double ozone_peak_altitude_km = 25.0;                               // km, [0, 1000]
    double ozone_width_km = 30.0;                                       // km, full width of the tent, [0.01, 1000]
    glm::dvec3 ground_albedo = {0.1, 0.1, 0.1};                         // for multiple scattering, [0, 1]
    int scattering_orders = 4;                                          // single + multiple, [1, 10]
    double min_sun_elevation_deg = -12.0;  // lowest sun the tables cover (Bruneton's mu_s_min), [-90, 0]
    bool elek_rayleigh_phase = false;      // Elek Eq. 15 ad hoc phase instead of Eq. 2
    bool elek_3d_table = false;            // render with Elek's 3D table (no azimuth) instead of the 4D one
};

}  // namespace planet
