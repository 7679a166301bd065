// Ocean parameters as a user sets them (preset [ocean] section).
//
// The sea is a sphere of radius planet.radius_km + sea_level_m displaced by a
// sum of spherical Gerstner waves (Michelic §4, Eq. 7-11). The waves are
// either generated from the few physical parameters below (wind, fetch, seed:
// ocean/wave_spectrum.h) or listed one by one in the preset ([[ocean.wave]]
// tables, which then replace the generated set); either way they end up in
// Scene::waves, which is what the renderer draws and the panel edits.
#pragma once

namespace planet {

struct OceanParams {
    double sea_level_m = 0.0;          // sea surface above the planet radius, m, [-10000, 10000]
    int grid_size = 80;                // the ocean's own projected grid, N x N (Michelic §6: 80), [8, 512]
    double target_edge_px = 8.0;       // tessellation aims at triangle edges this long on screen, [1, 200]
    // Wave generation (ocean/wave_spectrum.h).
    int wave_count = 40;               // waves generated, [0, 4096]
    double wind_speed_mps = 8.0;       // wind speed 10 m above the sea, m/s, [0.5, 40]
    double wind_bearing_deg = 60.0;    // direction the wind blows towards, deg clockwise from north, [-360, 360]
    double wind_latitude_deg = 43.0;   // where the wind blows from that bearing (the waves' origins lie upwind), deg, [-90, 90]
    double wind_longitude_deg = -6.5;  // deg, [-180, 180]
    double fetch_km = 0.0;             // JONSWAP fetch; 0: fully developed sea (Pierson-Moskowitz), km, [0, 10000]
    double directional_spread_deg = 30.0;  // std. deviation of wave directions about the wind, deg, [0, 180]
    double min_wavelength_m = 0.5;     // shortest generated wave, m, [0.01, 10000]
    double choppiness = 0.6;           // sum over waves of Q_i A_i k_i (crest sharpness; up to 1 no loops, cusps at 1), [0, 1]
    int seed = 1;                      // same seed, same sea, [0, 1000000]
    // Eq. 11: Q fades to 0 where 1 - |v . o_i| < fade_start, fully on above fade_end.
    double fade_start = 1.0e-4;        // e0, [0, 1]
    double fade_end = 1.0e-3;          // e1, [0, 1], > e0
};

}  // namespace planet
