// Scene: every parameter a frame depends on, as plain per-feature structs.
//
// Each phenomenon owns its parameter struct (default member initialisers carry
// the Earth defaults, comments carry unit and valid range). Presets map onto
// these one to one through the table in scene_params.cpp, which is also what
// the explorer's panels and the preset writer walk, so a parameter added there
// is loadable, validated, tunable and savable at once.
//
// World frame: planet centre at the origin, +Z through the north pole,
// longitude 0 along +X, longitude 90 E along +Y. Lengths in metres unless a
// field name says otherwise.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "atmosphere/atmosphere_params.h"
#include "clouds/cloud_params.h"
#include "ocean/ocean_params.h"
#include "ocean/wave_spectrum.h"
#include "ocean/waves.h"
#include "terrain/terrain_params.h"

namespace planet {

struct PlanetParams {
    double radius_km = 6360.0;                     // km, [1, 100000]
    glm::dvec3 albedo = {0.09, 0.12, 0.06};        // lowland (grass) albedo, linear RGB, [0, 1]
};

struct SunParams {
    double latitude_deg = 20.0;                    // subsolar point latitude, deg, [-90, 90]
    double longitude_deg = 30.0;                   // subsolar point longitude, deg, [-180, 180]
    // Solar irradiance at the top of the atmosphere for R, G, B (680, 550, 440 nm),
    // W m^-2 nm^-1 (Bruneton's demo values), [0, 100].
    glm::dvec3 irradiance = {1.474, 1.8504, 1.91198};
    double angular_radius_rad = 0.004675;          // rad, [0.0001, 0.1]
};

struct RenderParams {
    // Tone mapping: display = 1 - exp(-exposure * radiance), then sRGB (Bruneton's
    // demo operator). Dimensionless, [0.001, 1000].
    double exposure = 10.0;
    // March clouds and air at a reduced rate (one pixel of each 4x4 block a frame) and
    // reproject the rest from the frame history (render/sky_temporal.frag); off: every pixel
    // every frame (reference frames). A frame without history is marched at full rate.
    bool temporal = true;
    // With the temporal march, in a frame where anything moved: the pixels around a sample
    // whose reprojected history was off by more than this share (relative luminance) are
    // marched again at full rate (render/sky_refine.comp), as are those with nothing to
    // reproject, on an edge between surfaces, or with a history read across one. 1: only
    // those. [0, 1]
    double temporal_refine_error = 0.05;
};

struct Scene {
    PlanetParams planet;
    AtmosphereParams atmosphere;  // bottom radius is planet.radius_km
    TerrainParams terrain;
    CloudParams clouds;           // the cloud layer
    OceanParams ocean;            // drawn when terrain.ocean is on
    // The waves the ocean draws: generated from `ocean` (ocean/wave_spectrum.h), or read
    // from the preset's [[ocean.wave]] list, or edited one by one in the explorer.
    std::vector<ocean::GerstnerWave> waves = ocean::generateWaves(OceanParams{});
    SunParams sun;
    RenderParams render;
    double time_s = 0.0;          // simulation clock (waves move with it), s; not a preset parameter

    double planetRadiusM() const { return planet.radius_km * 1000.0; }
    // Unit vector from the planet centre towards the sun, world frame.
    glm::dvec3 sunDirection() const;
};

// Unit vector in the world frame for a geographic latitude/longitude (degrees).
glm::dvec3 directionFromLatLon(double latitudeDeg, double longitudeDeg);

// Local solar time at a place (unit direction from the planet centre), hours in [0, 24):
// 12 where the subsolar point's longitude is the place's, 6 and 18 a quarter turn away.
double localSolarHour(const SunParams& sun, glm::dvec3 place);
// Moves the subsolar point's longitude so that it is `hour` o'clock at `place` (the
// planet turns under a fixed sun; the sun's latitude, the season, stays).
void setLocalSolarHour(SunParams& sun, glm::dvec3 place, double hour);

}  // namespace planet
