// Terrain height field, normal and material on the CPU: the very GLSL of
// shaders/terrain/height.glsl compiled as C++ in float (as noise/noise.h does for the noise).
//
// Directions are unit vectors in the world frame (+Z north); heights in metres above sea
// level, in [-ocean_depth_m, max_height_m]. The GLSL names are the same. tests/
// test_terrain_height.cpp checks the properties and the GPU's values against these.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "terrain/terrain_params.h"

namespace planet::terrain {

// Material ids of terrainMaterial (the GLSL TERRAIN_MATERIAL_* constants; static_asserted equal).
enum class Material : int { SeaFloor = 0, Rock = 1, Snow = 2, Sand = 3, Grass = 4 };
inline constexpr int kMaterialCount = 5;

// TerrainParams in float, as the shader takes it; mirror of the GLSL struct TerrainShape,
// laid out as std140 (64 bytes, static_asserted in height.cpp), so it can be copied into a
// uniform block as is.
struct TerrainShape {
    glm::vec4 continentOffset;  // noise-space offset of the continents (xyz), from the seed
    glm::vec4 mountainOffset;   // noise-space offset of the mountains (xyz), from the seed
    float maxHeight;            // m
    float oceanDepth;           // m
    float continentFrequency;   // per planet radius
    float mountainFrequency;    // per planet radius
    float ridgedWeight;         // [0, 1]
    int octaves;                // [1, 10]
    float padding0 = 0.0f;
    float padding1 = 0.0f;
};

// The shape for a set of parameters. The seed picks the noise offsets (hashed into
// [-32, 32)^3, in steps of 1/256: nearby seeds give unrelated planets).
TerrainShape makeTerrainShape(const TerrainParams& params);

// Height above sea level, m. GLSL: terrainHeight(d, shape).
float terrainHeight(glm::vec3 unitDirection, const TerrainShape& shape);

// Height of the visible surface above sea level (m) under a world position:
// the terrain, or 0 over the sea (the flat water stand-in the terrain pass
// draws) when the world has an ocean.
double surfaceHeightM(const TerrainParams& params, const glm::dvec3& position);

// Height and its gradient with respect to the direction as a point in R^3 (only the
// tangential part means anything: m per radian). GLSL: terrainHeightGrad.
float terrainHeightGrad(glm::vec3 unitDirection, const TerrainShape& shape, glm::vec3& gradient);

// Continent value in [-1, 1]; land where above kCoastContinent. GLSL: continentValue.
float continentValue(glm::vec3 unitDirection, const TerrainShape& shape);
extern const float kCoastContinent;

// Unit surface normal of the terrain on a planet of radius planetRadius (m). GLSL: terrainNormal.
glm::vec3 terrainNormal(glm::vec3 unitDirection, const TerrainShape& shape, float planetRadius);

// Rise over run of a surface with this normal; 0 flat, 1 at 45 deg. GLSL: terrainSlope.
float terrainSlope(glm::vec3 normal, glm::vec3 up);

// Latitude of a direction, rad. GLSL: terrainLatitude.
float terrainLatitude(glm::vec3 unitDirection);

// Snow line at a latitude (rad), m above sea level. GLSL: terrainSnowLine.
float terrainSnowLine(float latitude);

// Material at a point (rule in shaders/terrain/height.glsl). GLSL: terrainMaterial.
Material terrainMaterial(float height, float slope, float latitude);

// Smooth blend weight of a material at a point; all materials' weights sum to 1.
// GLSL: terrainMaterialWeight.
float terrainMaterialWeight(Material material, float height, float slope, float latitude);

// The rule's thresholds (GLSL constants of the same meaning), for tests and UI.
struct MaterialThresholds {
    float beachDepthM, beachHeightM, rockSlope, blendHeightM, blendSnowM, blendSlope;
};
MaterialThresholds materialThresholds();

}  // namespace planet::terrain
