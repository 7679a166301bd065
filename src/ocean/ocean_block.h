// OceanBlock: the sea's parameters as the ocean's stages read them (BLOCK_OCEAN), C++
// mirror of shaders/ocean/ocean_block.glsl (std140: twelve scalars, 48 bytes).
#pragma once

#include <cstddef>

#include "scene/scene.h"

namespace planet::ocean {

struct OceanBlock {
    float seaLevel;              // m above the planet radius
    float maxWaveHeight;         // m, sum of the amplitudes
    float targetEdgePixels;      // px
    float coarsestEdgePixels;    // px, max of the terrain's and the ocean's target edge
    float fadeStart;             // Michelic Eq. 11 e0
    float fadeEnd;               // Michelic Eq. 11 e1
    float subgridSlopeVariance;  // ripples below the shortest wave
    int waveCount;
    // Land culling (src/ocean/land_cull.h): where the continent value is at least
    // landContinent the ground stands above the highest crest, so no sea shows there; a
    // patch is dropped when its centre's value, less continentLipschitz times its angular
    // radius, is above patchLandContinent (landContinent plus the filter's rounding).
    float landContinent;
    float patchLandContinent;
    float continentLipschitz;  // per radian: the filtered map's steepest slope, with a safety factor
    int landCulling;           // 0: off (tests compare with it on)
    // How far the GPU's filter may move a sample's place on the map, radians (land_cull.h's
    // continentSampleSlackRad), for the shaders' slope bounds (terrainReachBelowLandKm).
    float continentSampleSlackRad;
    float padding0, padding1, padding2;
};
static_assert(offsetof(OceanBlock, fadeStart) == 16 && offsetof(OceanBlock, waveCount) == 28 &&
                  offsetof(OceanBlock, landContinent) == 32 && offsetof(OceanBlock, landCulling) == 44 &&
                  offsetof(OceanBlock, continentSampleSlackRad) == 48 && sizeof(OceanBlock) == 64,
              "OceanBlock must match std140 (shaders/ocean/ocean_block.glsl)");

OceanBlock makeOceanBlock(const Scene& scene);

}  // namespace planet::ocean
