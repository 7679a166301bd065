// The [terrain] rows of the scene parameter table: unit, inclusive range and
// help text for every field of TerrainParams (terrain_params.h, whose comments
// the ranges here repeat).
#include "terrain/terrain_params_table.h"

namespace planet {

void addTerrainParams(std::vector<ParamSpec>& table) {
    auto add = [&](const char* key, const char* unit, double lo, double hi, const char* help, auto member) {
        table.push_back(ParamSpec{"terrain", key, unit, lo, hi, help,
                                  [member](Scene& s) { return ParamRef{&(s.terrain.*member)}; }});
    };
    add("max_height_m", "m", 0.0, 50000.0, "Highest possible terrain above sea level (mountain peaks reach it).",
        &TerrainParams::max_height_m);
    add("ocean_depth_m", "m", 0.0, 20000.0, "Depth of the ocean floor below sea level, away from the coasts.",
        &TerrainParams::ocean_depth_m);
    add("noise_octaves", "", 0.0, 10.0,
        "Mountain noise layers (Michelic Table 1); each adds detail at half the size. 0: continents only.",
        &TerrainParams::noise_octaves);
    add("mountain_frequency", "1/radius", 0.1, 10000.0,
        "Frequency of the largest mountain features, per planet radius.",
        &TerrainParams::mountain_frequency);
    add("ridged_weight", "", 0.0, 1.0, "Mountain shape: 0 rounded fBm hills, 1 sharp ridged crests.",
        &TerrainParams::ridged_weight);
    add("continent_frequency", "1/radius", 0.01, 100.0,
        "Frequency of the continents, per planet radius: larger gives more, smaller land masses. Rebakes the "
        "continents map.",
        &TerrainParams::continent_frequency);
    add("continent_octaves", "", 1.0, 10.0,
        "fBm octaves baked into the continents map; octaves finer than about 4 texels alias. Rebakes the map.",
        &TerrainParams::continent_octaves);
    add("sea_fraction", "", 0.0, 1.0,
        "Share of the planet's surface below sea level; the coastline moves with it. Rebakes the continents map.",
        &TerrainParams::sea_fraction);
    add("continent_map_size", "texels", 16.0, 2048.0,
        "Face size of the continents cube map (6 faces of RGBA32F, 24 MiB at 512). Rebakes the map.",
        &TerrainParams::continent_map_size);
    add("seed", "", 0.0, 1e6,
        "Noise seed: another value gives another planet with the same statistics. Rebakes the continents map.",
        &TerrainParams::seed);
    add("grid_size", "", 8.0, 512.0, "Vertices per side of the projected grid (Michelic §3); tessellation refines it.",
        &TerrainParams::grid_size);
    add("grid_exponent", "", 2.0, 4.0, "n of the grid's hemisphere pre-displacement (Michelic Eq. 2): 4, or 2.",
        &TerrainParams::grid_exponent);
    add("grid_hysteresis", "", 0.0, 1.0,
        "The grid's projection camera follows the camera after it moved this fraction of its altitude.",
        &TerrainParams::grid_hysteresis);
    add("target_edge_px", "px", 1.0, 200.0, "Triangle edge length on screen the tessellation aims for.",
        &TerrainParams::target_edge_px);
    add("min_relief_slope", "", 0.0, 1.0,
        "The least relief (rise over run) the tessellation allows along an edge seen at a grazing angle: it is "
        "split by its size on screen as seen, or where larger by the relief its segments could show (its ends' "
        "slope, tripled, at least this, times its length); 1 splits every edge as if seen face on.",
        &TerrainParams::min_relief_slope);
    add("ocean", "", 0.0, 1.0, "Water fills everything below sea level; off for a dry world (basins stay ground).",
        &TerrainParams::ocean);
    add("shadows", "", 0.0, 1.0,
        "The terrain casts shadows: mountains shade the ground at a low sun (a march over the height field "
        "towards the sun: on the ground at one pixel of each 2x2 block (4x4 from 720 rows up) and where those "
        "disagree, on the sea "
        "at each lit pixel near land).",
        &TerrainParams::shadows);
    add("light_shafts", "", 0.0, 1.0,
        "Light shafts: the terrain's shadows in the air, taken out of the light the air scatters towards the camera "
        "(8 shadow marches along each view ray's first 60 km below the highest terrain; needs shadows).",
        &TerrainParams::light_shafts);
    add("detail", "", 0.0, 1.0,
        "Ground detail up close: tri-planar detail normals and colour per material at 0.5, 4 and 32 m, placed where "
        "the view ray meets the height field, filtered by the pixel's footprint (within 3 km of the camera; 1.4 "
        "to 1.6 times the terrain pass on a software renderer).",
        &TerrainParams::detail);
}

}  // namespace planet
