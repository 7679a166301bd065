// The [clouds] rows of the scene parameter table: unit, inclusive range and help text for
// every field of CloudParams (cloud_params.h, whose comments the ranges repeat).
#include "clouds/cloud_params_table.h"

namespace planet {

void addCloudParams(std::vector<ParamSpec>& table) {
    auto add = [&](const char* key, const char* unit, double lo, double hi, const char* help, auto member) {
        table.push_back(ParamSpec{"clouds", key, unit, lo, hi, help,
                                  [member](Scene& s) { return ParamRef{&(s.clouds.*member)}; }});
    };
    add("enabled", "", 0.0, 1.0, "Draw the cloud layer.", &CloudParams::enabled);
    add("bottom_altitude_km", "km", 0.0, 100.0, "Bottom of the cloud layer above sea level (Michelic's l_b).",
        &CloudParams::bottom_altitude_km);
    add("top_altitude_km", "km", 0.01, 200.0, "Top of the cloud layer above sea level (l_t); above the bottom.",
        &CloudParams::top_altitude_km);
    add("tile_width_km", "km", 0.1, 1000.0, "The density volume repeats every this many km (w of Michelic Eq. 12).",
        &CloudParams::tile_width_km);
    add("coverage", "", 0.0, 1.0, "Share of the sky the clouds cover; 0 is a clear sky.", &CloudParams::coverage);
    add("density_scale", "", 0.0, 100.0, "Multiplies the cloud density.", &CloudParams::density_scale);
    add("extinction_per_km", "1/km", 0.0, 10000.0,
        "Extinction at density 1 (E of Michelic Eq. 15); cumulus are about 20-100 per km.",
        &CloudParams::extinction_per_km);
    add("single_scattering_albedo", "", 0.0, 1.0, "Share of the extinction that is scattering (S / E of Eq. 16).",
        &CloudParams::single_scattering_albedo);
    add("phase_g_forward", "", -0.99, 0.99, "Henyey-Greenstein asymmetry of the forward lobe (> 0: forward).",
        &CloudParams::phase_g_forward);
    add("phase_g_back", "", -0.99, 0.99, "Asymmetry of the back lobe (< 0: backward).", &CloudParams::phase_g_back);
    add("phase_back_weight", "", 0.0, 1.0, "Weight of the back lobe; 0 is one Henyey-Greenstein lobe (Michelic).",
        &CloudParams::phase_back_weight);
    add("sun_samples", "", 0.0, 64.0, "Density samples towards the sun for the light reaching a sample (Michelic: 6).",
        &CloudParams::sun_samples);
    add("sun_step_km", "km", 0.001, 100.0, "Spacing of the samples towards the sun.", &CloudParams::sun_step_km);
    add("step_km", "km", 0.001, 100.0, "March step inside clouds; empty space is crossed in larger steps.",
        &CloudParams::step_km);
    add("max_steps", "", 1.0, 8192.0, "Cloud march steps per pixel at most.", &CloudParams::max_steps);
    add("atmosphere_slices", "", 1.0, 64.0,
        "Atmosphere slices per crossing of the layer, interleaved with the clouds (Michelic Eq. 17-20).",
        &CloudParams::atmosphere_slices);
    add("multiple_scattering_octaves", "", 1.0, 8.0,
        "Octaves of Wrenninge's multiple-scattering approximation; 1 is single scattering only.",
        &CloudParams::multiple_scattering_octaves);
    add("powder", "", 0.0, 1.0, "Strength of the dark-edge 'powder' term; 0 is off.", &CloudParams::powder);
    add("energy_conserving_step", "", 0.0, 1.0,
        "Integrate each step's in-scattering over its own extinction (Hillaire 2016); off: Michelic Eq. 16 as written.",
        &CloudParams::energy_conserving_step);
    add("constant_density", "", 0.0, 1.0,
        "A layer of uniform density (density_scale) instead of the noise, for analytic checks.",
        &CloudParams::constant_density);
    add("far_field", "", 0.0, 1.0,
        "Where a pixel spans several voxels (far away, from orbit), draw a smooth field whose column hides the "
        "weather map's coverage instead of the aliasing volume; off: the volume everywhere (reference frames).",
        &CloudParams::far_field);
    add("type_profiles", "", 0.0, 1.0,
        "Shape the layer's vertical profile by the weather map's cloud type (stratus low and flat, cumulus heaped, "
        "high thin sheets near the top); off: Michelic Eq. 13 alone.",
        &CloudParams::type_profiles);
    add("volume_seed", "", 0.0, 1e6, "Seed of the baked density volume.", &CloudParams::volume_seed);
    add("volume_size", "voxels", 16.0, 512.0, "Voxels per side of the baked density volume (Michelic: 256).",
        &CloudParams::volume_size);
    add("shape_frequency", "cells", 1.0, 64.0, "Perlin-Worley shape cells per tile of the volume.",
        &CloudParams::shape_frequency);
    add("detail_frequency", "cells", 1.0, 256.0, "Worley erosion cells per tile of the volume.",
        &CloudParams::detail_frequency);
    add("erosion", "", 0.0, 1.0, "How deeply the Worley detail erodes the shapes' edges.", &CloudParams::erosion);
    add("cloud_fraction", "", 0.01, 0.99, "Share of the volume's voxels that are cloud (before the coverage).",
        &CloudParams::cloud_fraction);
    add("border_voxels", "voxels", 2.0, 32.0,
        "Zero-density border around every cloud in the volume (Michelic fig. 9); empty space is crossed in steps of "
        "border_voxels - 1 voxels.",
        &CloudParams::border_voxels);
    add("weather_seed", "", 0.0, 1e6, "Seed of the weather map.", &CloudParams::weather_seed);
    add("weather_map_size", "texels", 4.0, 4096.0,
        "Texels per cube face of the weather map: 10 km a texel on the earth at 1024 (at 256, 39 km: the edges of "
        "the cloud fields seen from orbit are stair-steps of its texels).",
        &CloudParams::weather_map_size);
    add("weather_frequency", "1/radius", 0.01, 100.0, "Cycles per planet radius of the largest weather systems.",
        &CloudParams::weather_frequency);
    add("latitude_bands", "", 0.0, 2.0,
        "Strength of the zonal pattern: cloudy along the equator and the storm tracks, clear under the subtropics.",
        &CloudParams::latitude_bands);
    add("wind_speed_mps", "m/s", 0.0, 200.0, "The clouds drift with the scene's clock at this speed.",
        &CloudParams::wind_speed_mps);
    add("wind_bearing_deg", "deg", -360.0, 360.0, "Direction the clouds drift towards, clockwise from north.",
        &CloudParams::wind_bearing_deg);
}

}  // namespace planet
