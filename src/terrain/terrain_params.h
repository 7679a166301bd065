// Terrain parameters as a user sets them (preset [terrain] section).
//
// The terrain is a height field over the sphere, in metres above sea level
// (planet.radius_km), evaluated by shaders/terrain/height.glsl: the continents,
// baked once into a cube map of elevation (noise/continents.h; Michelic §6),
// decide land and sea and the depth of the oceans; ridged fBm mountains, the
// noise layers of Michelic's Table 1, rise inland, weighted by the distance
// from the coast (Michelic §3: layered 3D simplex noise sampled at the point's
// direction). Frequencies are per planet radius: the noise is sampled at
// unitDirection * frequency, so a frequency f has features about 2 pi R / f
// across whatever the radius. makeTerrainShape and continentParams
// (terrain/height.h) turn these into what the shader and the bake take.
#pragma once

namespace planet {

struct TerrainParams {
    double max_height_m = 8000.0;       // highest possible terrain above sea level, m, [0, 50000]
    double ocean_depth_m = 4000.0;      // depth of the abyssal plains below sea level, m, [0, 20000]
    int noise_octaves = 8;              // mountain noise layers (Michelic Table 1), 0 = continents only, [0, 10]
    double mountain_frequency = 120.0;  // lowest mountain octave, per planet radius, [0.1, 10000]
    double ridged_weight = 0.6;         // mountains: 0 rounded fBm hills, 1 sharp ridged crests, [0, 1]
    double continent_frequency = 1.5;   // lowest continent octave, per planet radius, [0.01, 100] (baked)
    int continent_octaves = 6;          // fBm octaves baked into the continents map, [1, 10] (baked)
    double sea_fraction = 0.6;          // share of the surface below sea level, [0, 1] (baked)
    int continent_map_size = 512;       // continents cube map face size, texels, [16, 2048] (baked)
    int seed = 1;                       // picks the noise domain offsets: another planet, [0, 1000000] (baked)
    int grid_size = 100;                // projected grid, N x N vertices (Michelic §3), [8, 512]
    int grid_exponent = 4;              // n of Eq. 2's hemisphere pre-displacement, 2 or 4, [2, 4]
    double grid_hysteresis = 0.05;      // the anchor moves after this fraction of the altitude, [0, 1]
    double target_edge_px = 12.0;       // tessellation aims at triangle edges this long on screen, [1, 200]
    double min_relief_slope = 0.1;      // the least relief (rise over run) an edge seen grazing is split for, [0, 1]
    bool ocean = true;                  // water fills everything below sea level (false: dry basins, Mars)
    bool shadows = true;                // mountains cast shadows (a march towards the sun per lit pixel; terrain/terrain_shadow.glsl)
    bool detail = true;                 // ground detail at close range (terrain/detail.glsl)
    bool light_shafts = false;          // the terrain's shadows in the air (a few shadow marches a pixel; atmosphere/interface.glsl)
};

}  // namespace planet
