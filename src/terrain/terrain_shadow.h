// Terrain shadows on the CPU: the very GLSL of shaders/terrain/terrain_shadow.glsl compiled
// as C++ in float (as terrain/height.cpp does for the height field), so tests and tools get
// the visibility the GPU computes. What the march does and why: that file's header.
//
// Points in km from the planet centre, the sun a unit direction, heights in m.
#pragma once

#include <glm/vec3.hpp>

#include "noise/continents.h"
#include "terrain/height.h"

namespace planet::terrain {

// The march's constants (the GLSL's), for tests.
struct TerrainShadowConstants {
    float maxKm, firstKm, biasM;
    int samples;
};
TerrainShadowConstants terrainShadowConstants();

// The share of the sun's disc the terrain leaves visible from the ground under `pointKm`,
// in [0, 1], with the shader's TERRAIN_SHADOW_SAMPLES samples. GLSL: terrainSunVisibility.
float terrainSunVisibility(glm::vec3 pointKm, glm::vec3 sun, float planetRadiusKm, float sunAngularRadius,
                           float footprintKm, const TerrainShape& shape, const noise::CubeMap& continents);

// The same from `startM` metres above sea level where the ground is lower (the sea's surface,
// a point in the air). GLSL: terrainSunVisibilityAbove.
float terrainSunVisibilityAbove(glm::vec3 pointKm, float startM, glm::vec3 sun, float planetRadiusKm,
                                float sunAngularRadius, float footprintKm, const TerrainShape& shape,
                                const noise::CubeMap& continents);

// The march's smallest clearance angle (rad; 1 where nothing was marched), with the octaves' bounds
// taken where the terrain cannot come within `exactBelow` rad of the ray (`boundOctaves`; the
// shader's: the sun's radius plus TERRAIN_SHADOW_EXACT_MARGIN) or every octave evaluated.
// GLSL: terrainShadowClearanceMarch.
float terrainShadowClearanceMarch(glm::vec3 pointKm, float startM, glm::vec3 sun, float planetRadiusKm,
                                  float sunAngularRadius, float footprintKm, const TerrainShape& shape,
                                  const noise::CubeMap& continents, float exactBelow, bool boundOctaves);
// The shader's exactBelow margin: TERRAIN_SHADOW_EXACT_MARGIN.
float terrainShadowExactMargin();

// The height (m) of the field with `octaves` mountain octaves at a unit direction, or where it
// cannot rise above `ceilingM` (the octaves summed so far show it), a bound on it no lower than
// the height. GLSL: terrainShadowHeightBelow.
float terrainShadowHeightBelow(glm::vec3 direction, const TerrainShape& shape, const noise::CubeMap& continents,
                               int octaves, float ceilingM, bool boundOctaves = true);

// Whether the terrain may shadow the sea's surface at `up` from `seaLevelM`: false only where
// the map's slope bound keeps the continent value below 0 as far as the march reaches.
// GLSL: terrainShadowMayReachSea (the ocean pass skips the march where it is false).
bool terrainShadowMayReachSea(glm::vec3 up, glm::vec3 sun, float seaLevelM, float planetRadiusKm,
                              float continentLipschitz, float sampleSlackRad, const TerrainShape& shape,
                              const noise::CubeMap& continents);

// The share of a disc of angular radius `sunAngularRadius` above a straight horizon
// `clearance` rad below its centre. GLSL: terrainShadowDiscShare.
float terrainShadowDiscShare(float clearance, float sunAngularRadius);

// Mountain octaves a march sample takes when features finer than `featureKm` cannot matter.
// GLSL: terrainShadowOctaves.
int terrainShadowOctaves(const TerrainShape& shape, float planetRadiusKm, float featureKm);

}  // namespace planet::terrain
