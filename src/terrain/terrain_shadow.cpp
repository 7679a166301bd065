// shaders/terrain/terrain_shadow.glsl compiled as C++ in float (see terrain_shadow.h).
//
// The shader needs terrainHeight, so simplex.glsl and height.glsl are included again here,
// into this file's own namespace (height.cpp's namespace planet::terrain::glsl holds the
// same functions with external linkage; a second copy there would collide).
#include "terrain/terrain_shadow.h"

#include <cmath>

#include <glm/glm.hpp>

#include "noise/noise.h"

namespace planet::terrain {
namespace shadow_glsl {
#include "terrain/glsl_as_cpp.h"
#include "shaders/noise/simplex.glsl"
#include "shaders/terrain/height.glsl"
#include "shaders/terrain/terrain_shadow.glsl"
#undef OUT
}  // namespace shadow_glsl

namespace {

shadow_glsl::TerrainShape toGlsl(const TerrainShape& s) {
    return shadow_glsl::TerrainShape{s.mountainOffset,    s.maxHeight,    s.oceanDepth,
                                     s.mountainFrequency, s.ridgedWeight, s.mountainOctaves,
                                     s.padding0,          s.padding1,     s.padding2};
}

}  // namespace

TerrainShadowConstants terrainShadowConstants() {
    return {shadow_glsl::TERRAIN_SHADOW_MAX_KM, shadow_glsl::TERRAIN_SHADOW_FIRST_KM, shadow_glsl::TERRAIN_SHADOW_BIAS_M,
            shadow_glsl::TERRAIN_SHADOW_SAMPLES};
}

float terrainSunVisibility(glm::vec3 pointKm, glm::vec3 sun, float planetRadiusKm, float sunAngularRadius,
                           float footprintKm, const TerrainShape& shape, const noise::CubeMap& continents) {
    return shadow_glsl::terrainSunVisibility(pointKm, sun, planetRadiusKm, sunAngularRadius, footprintKm,
                                             shadow_glsl::TERRAIN_SHADOW_SAMPLES, toGlsl(shape), continents);
}

float terrainSunVisibilityAbove(glm::vec3 pointKm, float startM, glm::vec3 sun, float planetRadiusKm,
                                float sunAngularRadius, float footprintKm, const TerrainShape& shape,
                                const noise::CubeMap& continents) {
    return shadow_glsl::terrainSunVisibilityAbove(pointKm, startM, sun, planetRadiusKm, sunAngularRadius, footprintKm,
                                                  shadow_glsl::TERRAIN_SHADOW_SAMPLES, toGlsl(shape), continents);
}

float terrainShadowClearanceMarch(glm::vec3 pointKm, float startM, glm::vec3 sun, float planetRadiusKm,
                                  float sunAngularRadius, float footprintKm, const TerrainShape& shape,
                                  const noise::CubeMap& continents, float exactBelow, bool boundOctaves) {
    return shadow_glsl::terrainShadowClearanceMarch(pointKm, startM, sun, planetRadiusKm, sunAngularRadius,
                                                    footprintKm, shadow_glsl::TERRAIN_SHADOW_SAMPLES, toGlsl(shape),
                                                    continents, exactBelow, boundOctaves);
}

float terrainShadowExactMargin() { return shadow_glsl::TERRAIN_SHADOW_EXACT_MARGIN; }

float terrainShadowHeightBelow(glm::vec3 direction, const TerrainShape& shape, const noise::CubeMap& continents,
                               int octaves, float ceilingM, bool boundOctaves) {
    return shadow_glsl::terrainShadowHeightBelow(direction, toGlsl(shape), continents, octaves, ceilingM,
                                                 boundOctaves);
}

bool terrainShadowMayReachSea(glm::vec3 up, glm::vec3 sun, float seaLevelM, float planetRadiusKm,
                              float continentLipschitz, float sampleSlackRad, const TerrainShape& shape,
                              const noise::CubeMap& continents) {
    return shadow_glsl::terrainShadowMayReachSea(up, sun, seaLevelM, planetRadiusKm, continentLipschitz, sampleSlackRad,
                                                 toGlsl(shape), continents);
}

float terrainShadowDiscShare(float clearance, float sunAngularRadius) {
    return shadow_glsl::terrainShadowDiscShare(clearance, sunAngularRadius);
}

int terrainShadowOctaves(const TerrainShape& shape, float planetRadiusKm, float featureKm) {
    return shadow_glsl::terrainShadowOctaves(toGlsl(shape), planetRadiusKm, featureKm);
}

}  // namespace planet::terrain
