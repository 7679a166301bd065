// The [ocean] rows of the scene parameter table: unit, inclusive range and help
// text for every field of OceanParams (ocean_params.h, whose comments they repeat).
#include "ocean/ocean_params_table.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace planet {

void addOceanParams(std::vector<ParamSpec>& table) {
    auto add = [&](const char* key, const char* unit, double lo, double hi, const char* help, auto member) {
        table.push_back(ParamSpec{"ocean", key, unit, lo, hi, help,
                                  [member](Scene& s) { return ParamRef{&(s.ocean.*member)}; }});
    };
    add("sea_level_m", "m", -10000.0, 10000.0, "Height of the mean sea surface above the planet radius.",
        &OceanParams::sea_level_m);
    add("grid_size", "", 8.0, 512.0, "Vertices per side of the ocean's projected grid (Michelic §6: 80).",
        &OceanParams::grid_size);
    add("target_edge_px", "px", 1.0, 200.0, "Triangle edge length on screen the ocean's tessellation aims for.",
        &OceanParams::target_edge_px);
    add("wave_count", "", 0.0, 4096.0, "Number of Gerstner waves generated from the spectrum.",
        &OceanParams::wave_count);
    add("wind_speed_mps", "m/s", 0.5, 40.0, "Wind speed 10 m above the sea; sets the spectrum's peak and height.",
        &OceanParams::wind_speed_mps);
    add("wind_bearing_deg", "deg", -360.0, 360.0, "Direction the wind blows towards, clockwise from north.",
        &OceanParams::wind_bearing_deg);
    add("wind_latitude_deg", "deg", -90.0, 90.0, "Latitude of the point where the wind has that bearing.",
        &OceanParams::wind_latitude_deg);
    add("wind_longitude_deg", "deg", -180.0, 180.0, "Longitude of the point where the wind has that bearing.",
        &OceanParams::wind_longitude_deg);
    add("fetch_km", "km", 0.0, 10000.0, "Distance the wind has blown over water (JONSWAP); 0: fully developed sea.",
        &OceanParams::fetch_km);
    add("directional_spread_deg", "deg", 0.0, 180.0, "Spread of the wave directions about the wind.",
        &OceanParams::directional_spread_deg);
    add("min_wavelength_m", "m", 0.01, 10000.0, "Shortest generated wave.", &OceanParams::min_wavelength_m);
    add("choppiness", "", 0.0, 1.0, "Sharpness of the crests: the sum of Q A k over the waves (up to 1: no loops; cusps at 1).",
        &OceanParams::choppiness);
    add("seed", "", 0.0, 1e6, "Random seed of the wave set: same seed, same sea.", &OceanParams::seed);
    add("fade_start", "", 0.0, 1.0, "e0 of Michelic Eq. 11: Q is 0 where 1 - |v.o| is below it (near origins).",
        &OceanParams::fade_start);
    add("fade_end", "", 0.0, 1.0, "e1 of Michelic Eq. 11: Q is fully on where 1 - |v.o| is above it.",
        &OceanParams::fade_end);
}

bool isWaveGeneratorParam(const ParamSpec& spec) {
    static constexpr std::array<std::string_view, 9> keys = {
        "wave_count", "wind_speed_mps", "wind_bearing_deg", "wind_latitude_deg", "wind_longitude_deg",
        "fetch_km",   "directional_spread_deg", "min_wavelength_m", "choppiness"};
    return spec.section == "ocean" &&
           (spec.key == "seed" || std::find(keys.begin(), keys.end(), spec.key) != keys.end());
}

}  // namespace planet
