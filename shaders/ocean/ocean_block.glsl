// The sea's parameters for every ocean stage; mirror of src/ocean/ocean_block.h (std140).
#include "common/bindings.glsl"

layout(std140, binding = BLOCK_OCEAN) uniform OceanBlock {
    float seaLevel;              // m above the planet radius (the mean sea surface)
    float maxWaveHeight;         // m: the sum of the amplitudes (culling, land test)
    float targetEdgePixels;      // triangle edge on screen the tessellation aims for
    float coarsestEdgePixels;    // the larger of the terrain's and the ocean's target edge (mesh sag)
    float fadeStart;             // e0 of Michelic Eq. 11
    float fadeEnd;               // e1 of Michelic Eq. 11
    float subgridSlopeVariance;  // ripples shorter than any wave (src/ocean/ocean_gpu.h)
    int waveCount;               // records in OceanWaves
    // Land culling (src/ocean/land_cull.h): at a continent value of landContinent or more the
    // ground stands above the highest crest; a patch whose centre value less
    // continentLipschitz x its angular radius is above patchLandContinent is land throughout.
    float landContinent;
    float patchLandContinent;
    float continentLipschitz;    // per radian, with a safety factor
    int landCulling;             // 0: off (tests compare with it on)
    // How far the filter may move a sample's place on the map, rad: its weight rounding, 1/32
    // of a texel (src/ocean/land_cull.h), for the slope bounds (terrainReachBelowLandKm).
    float continentSampleSlackRad;
    float padding0, padding1, padding2;  // to the C++ mirror's 64 bytes
} ocean;
