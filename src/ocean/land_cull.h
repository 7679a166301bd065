// Land culling for the ocean pass (issue 15): what the sea need not draw because the land
// stands above it. The ocean's fragment shader discards a fragment where the terrain is
// higher than the highest crest (waterDepth < -maxWaveHeight near the camera); these bounds
// let it, and the tessellation control stage for a whole patch, know that early and for sure:
//
//   - landContinent: the continent value e above which the terrain's height is surely above
//     sea level + the highest crest + a margin. On land the height is the lowlands' ramp of e
//     plus mountains >= 0 (terrain/height.glsl), so a bound on the ramp is a bound on the
//     height; found by bisection on the terrain's own height function (C++, the same text as
//     the GLSL) with the mountains off, and checked monotonic above it.
//   - continentLipschitz: the steepest slope of the map as the GPU filters it (bilinear between
//     texel centres, per radian), from the differences of neighbouring texels and the baked
//     analytic gradient, times a safety factor (bilinear cells, skewed texels near the cube's
//     corners). A patch whose centre has e_c with e_c - L r > patchLandContinent, r its angular
//     radius, has e > landContinent everywhere on it.
//   - patchLandContinent: landContinent plus what the GPU's fixed-point filter weights may move
//     a sample (1/32 of a texel's angle times L).
#pragma once

#include "noise/continents.h"
#include "terrain/terrain_params.h"

namespace planet::ocean {

// The map's steepest slope as filtered, per radian, with the safety factor.
double continentLipschitz(const noise::CubeMap& map);

// The continent value above which the ground is surely higher than seaLevel + maxWaveHeight +
// margin (m); 2 (above any value of the map, so nothing is culled) when no such value exists.
double landContinentThreshold(const TerrainParams& terrain, double seaLevelM, double maxWaveHeightM);

// The depth below the sea surface from which the sea floor is dark, m: the light that reaches it
// has crossed that much water (shaders/ocean/water.glsl's SEA_FLOOR_DARK_DEPTH_M, the same value;
// a test compares them). Seen from above through the sea, such ground is not drawn at all where
// the sea is (darkFloorContinentThreshold).
inline constexpr double kSeaFloorDarkDepthM = 400.0;

// The continent value below which the ground is surely deeper than kSeaFloorDarkDepthM (and a
// margin) under a sea at seaLevelM: under the sea the height is the shelf's ramp of e alone (no
// mountains; terrain/height.glsl), found by bisection on the terrain's own height function and
// checked monotonic below it; -2 (below any value of the map, so nothing is culled) when no such
// value exists. The terrain's control stage drops a patch whose centre value plus the slope bound
// times its radius is below it less the filter's slack (shaders/terrain/terrain.tesc), where the
// ocean is drawn over it from above.
double darkFloorContinentThreshold(const TerrainParams& terrain, double seaLevelM);

// How far the GPU's filter may move a sample's place, radians: its weight rounding, 1/32 of the
// largest texel's angle (2 / size radians).
double continentSampleSlackRad(const noise::CubeMap& map);
// What that may change a patch's centre sample by, in continent value: the slack times the slope.
double continentSampleSlack(const noise::CubeMap& map, double lipschitz);

}  // namespace planet::ocean
