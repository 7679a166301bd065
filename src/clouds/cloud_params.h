// Cloud parameters as a user sets them (preset [clouds] section).
//
// One layer of clouds between two altitudes (Michelic §5, fig. 10): a baked, tiling
// density volume repeated every tile_width_km across the planet (Eq. 12), faded to zero
// at the layer's bottom and top by Eq. 13's height signal, thinned by the coverage
// (Eq. 14 and a coverage remap), lit by the sun through the atmosphere and by the sky,
// and marched together with the atmosphere along every view ray (Eq. 15-20).
// constant_density replaces the noise by a layer of uniform density for analytic checks.
#pragma once

namespace planet {

struct CloudParams {
    bool enabled = true;                   // draw the cloud layer
    double bottom_altitude_km = 1.5;       // bottom of the layer above the planet radius, km, [0, 100]
    double top_altitude_km = 4.0;          // top of the layer, km, [0.01, 200], > bottom
    double tile_width_km = 16.0;           // w of Michelic Eq. 12: the density volume repeats every w, km, [0.1, 1000]
    double coverage = 0.5;                 // share of the sky covered, [0, 1] (0: clear)
    double density_scale = 1.0;            // multiplies the volume's density, [0, 100]
    double extinction_per_km = 40.0;       // E of Eq. 15 at density 1, 1/km, [0, 10000]
    double single_scattering_albedo = 0.99;  // S / E of Eq. 16, [0, 1]
    double phase_g_forward = 0.6;          // Henyey-Greenstein asymmetry of the forward lobe, [-0.99, 0.99]
    double phase_g_back = -0.3;            // of the back lobe, [-0.99, 0.99]
    double phase_back_weight = 0.0;        // weight of the back lobe, [0, 1]; 0: Michelic's single HG
    int sun_samples = 6;                   // density samples towards the sun for T_sun (Michelic: 6), [0, 64]
    double sun_step_km = 0.2;              // spacing of those samples, km, [0.001, 100]
    double step_km = 0.05;                 // march step inside clouds, km, [0.001, 100]
    int max_steps = 256;                   // cloud steps per pixel at most, [1, 8192]
    int atmosphere_slices = 4;             // atmosphere slices per crossing of the layer (Eq. 17-18), [1, 64]
    int multiple_scattering_octaves = 4;   // Wrenninge's octaves; 1: single scattering only, [1, 8]
    double powder = 0.0;                   // strength of the dark-edge "powder" term, [0, 1]; 0: off
    bool energy_conserving_step = true;    // integrate each step's in-scattering over its extinction (Hillaire 2016)
    bool constant_density = false;         // a layer of uniform density density_scale instead of the noise
    bool far_field = true;                 // smooth, coverage-true clouds where a pixel spans voxels (off: the volume everywhere)
    bool type_profiles = true;             // the weather map's cloud type shapes the vertical profile (else Eq. 13 alone)
    // The baked density volume (noise/cloud_volume.h); a change rebakes it (cached).
    int volume_seed = 1;                   // any int
    int volume_size = 256;                 // voxels per side, [16, 512]; 256^3 half floats are 32 MiB
    int shape_frequency = 4;               // Perlin-Worley shape cells per tile, [1, 64]
    int detail_frequency = 16;             // Worley erosion cells per tile, [1, 256]
    double erosion = 0.4;                  // how deeply the detail eats the shapes' edges, [0, 1]
    double cloud_fraction = 0.4;           // share of the volume's voxels that are cloud, [0.01, 0.99]
    int border_voxels = 4;                 // zero-density border around clouds (Michelic fig. 9), voxels, [2, 32]
    // The weather map (noise/weather_map.h): where the clouds are and of which type; a change rebakes it.
    int weather_seed = 1;                  // any int
    int weather_map_size = 1024;           // texels per cube face, [4, 4096]
    double weather_frequency = 2.0;        // cycles per planet radius of the largest weather systems, (0, 100]
    double latitude_bands = 0.5;           // strength of the zonal pattern (ITCZ, subtropics, storm tracks), [0, 2]
    double wind_speed_mps = 10.0;          // the clouds drift with the scene's clock, m/s, [0, 200]
    double wind_bearing_deg = 90.0;        // towards which they drift, clockwise from north, [-360, 360]
};

}  // namespace planet
