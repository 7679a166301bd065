// The [atmosphere] rows of the scene parameter table: unit, inclusive range
// and help text for every field of AtmosphereParams (atmosphere_params.h,
// whose comments the ranges here repeat). Ranges are per field; the rules
// that tie fields together (top above the ground, Mie extinction at least
// Mie scattering) are validateScene's, in scene/scene_params.cpp.
#include "atmosphere/atmosphere_params_table.h"

#include <utility>

namespace planet {

void addAtmosphereParams(std::vector<ParamSpec>& table) {
    auto add = [&](const char* key, const char* unit, double lo, double hi, const char* help,
                   std::function<ParamRef(Scene&)> field) {
        table.push_back(ParamSpec{"atmosphere", key, unit, lo, hi, help, std::move(field)});
    };
    add("top_radius_km", "km", 1.0, 2e5,
        "Radius of the top of the atmosphere, from the planet centre; at least 1 km and 1e-4 of the radius above "
        "planet.radius_km (the tables end where the air does).",
        [](Scene& s) { return ParamRef{&s.atmosphere.top_radius_km}; });
    add("rayleigh_scattering_per_m", "1/m", 0.0, 0.01,
        "Rayleigh (molecular) scattering coefficient at sea level (R, G, B at 680, 550, 440 nm).",
        [](Scene& s) { return ParamRef{&s.atmosphere.rayleigh_scattering_per_m}; });
    add("rayleigh_scale_height_km", "km", 0.2, 1000.0,
        "Altitude over which the Rayleigh density falls by a factor e; at least 3e-5 of planet.radius_km.",
        [](Scene& s) { return ParamRef{&s.atmosphere.rayleigh_scale_height_km}; });
    add("mie_scattering_per_m", "1/m", 0.0, 0.01, "Mie (aerosol) scattering coefficient at sea level (R, G, B).",
        [](Scene& s) { return ParamRef{&s.atmosphere.mie_scattering_per_m}; });
    add("mie_extinction_per_m", "1/m", 0.0, 0.01,
        "Mie extinction (scattering + absorption) at sea level (R, G, B); at least mie_scattering_per_m.",
        [](Scene& s) { return ParamRef{&s.atmosphere.mie_extinction_per_m}; });
    add("mie_scale_height_km", "km", 0.2, 1000.0,
        "Altitude over which the Mie density falls by a factor e; at least 3e-5 of planet.radius_km.",
        [](Scene& s) { return ParamRef{&s.atmosphere.mie_scale_height_km}; });
    add("mie_g", "", -0.999, 0.999, "Mie phase asymmetry g (Cornette-Shanks); > 0 scatters forward.",
        [](Scene& s) { return ParamRef{&s.atmosphere.mie_g}; });
    add("ozone_absorption_per_m", "1/m", 0.0, 0.01, "Ozone absorption coefficient at the peak of the layer (R, G, B).",
        [](Scene& s) { return ParamRef{&s.atmosphere.ozone_absorption_per_m}; });
    add("ozone_peak_altitude_km", "km", 0.0, 1000.0, "Altitude of the peak of the ozone layer's tent profile.",
        [](Scene& s) { return ParamRef{&s.atmosphere.ozone_peak_altitude_km}; });
    add("ozone_width_km", "km", 0.01, 1000.0, "Full width of the ozone tent; zero density outside it.",
        [](Scene& s) { return ParamRef{&s.atmosphere.ozone_width_km}; });
    add("ground_albedo", "", 0.0, 1.0, "Ground reflectance seen by multiple scattering, linear RGB.",
        [](Scene& s) { return ParamRef{&s.atmosphere.ground_albedo}; });
    add("scattering_orders", "", 1.0, 10.0, "Scattering orders precomputed: 1 is single scattering only.",
        [](Scene& s) { return ParamRef{&s.atmosphere.scattering_orders}; });
    add("min_sun_elevation_deg", "deg", -90.0, 0.0, "Lowest sun elevation the precomputed tables cover.",
        [](Scene& s) { return ParamRef{&s.atmosphere.min_sun_elevation_deg}; });
    add("elek_rayleigh_phase", "", 0.0, 1.0, "Use Elek's ad hoc Rayleigh phase function (Eq. 15) instead of Eq. 2.",
        [](Scene& s) { return ParamRef{&s.atmosphere.elek_rayleigh_phase}; });
    add("elek_3d_table", "", 0.0, 1.0,
        "Render with Elek's 3D table (altitude, view and sun zenith; azimuth dropped) instead of the 4D one.",
        [](Scene& s) { return ParamRef{&s.atmosphere.elek_3d_table}; });
}

}  // namespace planet
