// The shared noise GLSL compiled as C++ in float (see noise.h).
//
// The GLSL files are included here, in one translation unit, rather than in the
// header: they define plain (non-inline) functions, and the GLSL spellings (vec3, fract,
// uint...) stay out of every other file.
#include "noise/noise.h"

#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace planet::noise {
namespace glsl {
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using ivec3 = glm::ivec3;
using uvec3 = glm::uvec3;
using uint = std::uint32_t;
using glm::abs;
using glm::clamp;
using glm::dot;
using glm::floor;
using glm::inversesqrt;
using glm::max;
using glm::min;
using glm::mix;
using glm::sign;
using glm::sqrt;
using glm::step;
using std::abs;
using std::floor;
using std::sqrt;
#define OUT(x) x&
#include "shaders/noise/simplex.glsl"
#include "shaders/noise/worley.glsl"
#include "shaders/noise/perlin.glsl"
#undef OUT
}  // namespace glsl

namespace {
int periodCells(float period) { return period > 0.0f ? static_cast<int>(std::floor(period + 0.5f)) : 0; }

// A 32-bit integer hash (Chris Wellons' lowbias32): nearby inputs give unrelated outputs.
std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

float offsetFromHash(std::uint32_t h) { return float(h & 0x3fffU) / 256.0f - 32.0f; }
}  // namespace

glm::vec3 seedOffset(int seed, unsigned stream) {
    const std::uint32_t base = hash32(static_cast<std::uint32_t>(seed) * 4u + stream);
    return {offsetFromHash(hash32(base ^ 0x1u)), offsetFromHash(hash32(base ^ 0x2u)), offsetFromHash(hash32(base ^ 0x3u))};
}

float simplex(glm::vec3 p) { return glsl::simplexNoise(p); }

float simplexGrad(glm::vec3 p, glm::vec3& gradient) { return glsl::simplexNoiseGrad(p, gradient); }

float fbm(glm::vec3 p, int octaves, float lacunarity, float gain) { return glsl::fbm(p, octaves, lacunarity, gain); }

float fbmGrad(glm::vec3 p, int octaves, float lacunarity, float gain, glm::vec3& gradient) {
    return glsl::fbmGrad(p, octaves, lacunarity, gain, gradient);
}

float ridgedFbm(glm::vec3 p, int octaves, float lacunarity, float gain) {
    return glsl::ridgedFbm(p, octaves, lacunarity, gain);
}

float worley(glm::vec3 p, float period, unsigned stream) { return glsl::worleyF1(p, periodCells(period), stream); }

float perlinTiled(glm::vec3 p, float period, unsigned stream) {
    return glsl::perlinNoiseTiledStream(p, periodCells(period), stream);
}

float perlinFbmTiled(glm::vec3 p, float period, int octaves, float gain, unsigned stream) {
    return glsl::perlinFbmTiled(p, period, octaves, gain, stream);
}

unsigned seedStream(int seed, unsigned purpose) {
    return hash32(hash32(static_cast<std::uint32_t>(seed)) ^ hash32(purpose + 0x9e3779b9U));
}

glm::vec3 worleyFeaturePoint(glm::ivec3 cell, float period, unsigned stream) {
    return glsl::worleyFeaturePoint(cell, periodCells(period), stream);
}

glm::vec3 worleyFeatureOffset(glm::ivec3 cell, float period, unsigned stream) {
    return glsl::worleyFeatureOffset(cell, periodCells(period), stream);
}

}  // namespace planet::noise
