// The shared terrain GLSL compiled as C++ in float (see height.h).
//
// shaders/noise/simplex.glsl and shaders/terrain/height.glsl are included here, in one
// translation unit, into namespace planet::terrain::glsl, the way noise/noise.cpp does:
// GLM's float types and functions supply the GLSL names and OUT(x) is x&. (The noise
// functions are compiled a second time here, into this namespace; they are small.)
#include <algorithm>
#include "terrain/height.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace planet::terrain {
namespace glsl {
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using glm::abs;
using glm::asin;
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::floor;
using glm::inversesqrt;
using glm::length;
using glm::max;
using glm::min;
using glm::normalize;
using glm::sign;
using glm::smoothstep;
using glm::step;
using std::abs;
using std::asin;
using std::floor;
#define OUT(x) x&
#include "shaders/noise/simplex.glsl"
#include "shaders/terrain/height.glsl"
#undef OUT
}  // namespace glsl

// The C++ mirror is the GLSL struct itself, compiled here; both must keep the std140 layout.
static_assert(sizeof(glsl::TerrainShape) == 64 && sizeof(TerrainShape) == 64, "std140 size of TerrainShape");
static_assert(offsetof(TerrainShape, mountainOffset) == 16 && offsetof(TerrainShape, maxHeight) == 32 &&
                  offsetof(TerrainShape, octaves) == 52 && offsetof(glsl::TerrainShape, octaves) == 52,
              "std140 offsets of TerrainShape");
static_assert(int(Material::SeaFloor) == glsl::TERRAIN_MATERIAL_SEA_FLOOR &&
                  int(Material::Rock) == glsl::TERRAIN_MATERIAL_ROCK &&
                  int(Material::Snow) == glsl::TERRAIN_MATERIAL_SNOW &&
                  int(Material::Sand) == glsl::TERRAIN_MATERIAL_SAND &&
                  int(Material::Grass) == glsl::TERRAIN_MATERIAL_GRASS &&
                  kMaterialCount == glsl::TERRAIN_MATERIAL_COUNT,
              "material ids match the GLSL constants");

namespace {

glsl::TerrainShape toGlsl(const TerrainShape& s) {
    return glsl::TerrainShape{s.continentOffset, s.mountainOffset, s.maxHeight,         s.oceanDepth, s.continentFrequency,
                              s.mountainFrequency, s.ridgedWeight, s.octaves, s.padding0, s.padding1};
}

// A 32-bit integer hash (Chris Wellons' lowbias32): nearby inputs give unrelated outputs.
std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// An offset in [-32, 32) in steps of 1/256 (exact in float; keeps noise coordinates small,
// see the precision note in simplex.glsl).
float offsetFromHash(std::uint32_t h) { return float(h & 0x3fffU) / 256.0f - 32.0f; }

glm::vec4 seedOffset(int seed, std::uint32_t stream) {
    const std::uint32_t base = hash32(static_cast<std::uint32_t>(seed) * 4u + stream);
    return {offsetFromHash(hash32(base ^ 0x1u)), offsetFromHash(hash32(base ^ 0x2u)), offsetFromHash(hash32(base ^ 0x3u)),
            0.0f};
}

}  // namespace

const float kCoastContinent = glsl::TERRAIN_COAST_CONTINENT;

TerrainShape makeTerrainShape(const TerrainParams& p) {
    TerrainShape s{};
    s.continentOffset = seedOffset(p.seed, 0);
    s.mountainOffset = seedOffset(p.seed, 1);
    s.maxHeight = static_cast<float>(p.max_height_m);
    s.oceanDepth = static_cast<float>(p.ocean_depth_m);
    s.continentFrequency = static_cast<float>(p.continent_frequency);
    s.mountainFrequency = static_cast<float>(p.mountain_frequency);
    s.ridgedWeight = static_cast<float>(p.ridged_weight);
    s.octaves = p.noise_octaves;
    return s;
}

float terrainHeight(glm::vec3 d, const TerrainShape& shape) { return glsl::terrainHeight(d, toGlsl(shape)); }

float terrainHeightGrad(glm::vec3 d, const TerrainShape& shape, glm::vec3& gradient) {
    return glsl::terrainHeightGrad(d, toGlsl(shape), gradient);
}

float continentValue(glm::vec3 d, const TerrainShape& shape) { return glsl::continentValue(d, toGlsl(shape)); }

glm::vec3 terrainNormal(glm::vec3 d, const TerrainShape& shape, float planetRadius) {
    return glsl::terrainNormal(d, toGlsl(shape), planetRadius);
}

float terrainSlope(glm::vec3 normal, glm::vec3 up) { return glsl::terrainSlope(normal, up); }

float terrainLatitude(glm::vec3 d) { return glsl::terrainLatitude(d); }

float terrainSnowLine(float latitude) { return glsl::terrainSnowLine(latitude); }

Material terrainMaterial(float height, float slope, float latitude) {
    return static_cast<Material>(glsl::terrainMaterial(height, slope, latitude));
}

float terrainMaterialWeight(Material material, float height, float slope, float latitude) {
    return glsl::terrainMaterialWeight(static_cast<int>(material), height, slope, latitude);
}

MaterialThresholds materialThresholds() {
    return {glsl::TERRAIN_BEACH_DEPTH_M, glsl::TERRAIN_BEACH_HEIGHT_M, glsl::TERRAIN_ROCK_SLOPE,
            glsl::TERRAIN_BLEND_HEIGHT_M, glsl::TERRAIN_BLEND_SNOW_M, glsl::TERRAIN_BLEND_SLOPE};
}

double surfaceHeightM(const TerrainParams& params, const glm::dvec3& position) {
    const double length = glm::length(position);
    if (!(length > 0.0)) return 0.0;
    const double height = terrainHeight(glm::vec3(position / length), makeTerrainShape(params));
    return params.ocean ? std::max(0.0, height) : height;
}

}  // namespace planet::terrain
