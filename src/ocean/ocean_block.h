// OceanBlock: the sea's parameters as the ocean's stages read them (BLOCK_OCEAN), C++
// mirror of shaders/ocean/ocean_block.glsl (std140: eight scalars, 32 bytes).
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
};
static_assert(offsetof(OceanBlock, fadeStart) == 16 && offsetof(OceanBlock, waveCount) == 28 &&
                  sizeof(OceanBlock) == 32,
              "OceanBlock must match std140 (shaders/ocean/ocean_block.glsl)");

OceanBlock makeOceanBlock(const Scene& scene);

}  // namespace planet::ocean
