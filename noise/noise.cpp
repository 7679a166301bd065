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
using glm::sign;
using glm::sqrt;
using glm::step;
using std::abs;
using std::floor;
using std::sqrt;
#define OUT(x) x&
#include "shaders/noise/simplex.glsl"
#include "shaders/noise/worley.glsl"
#undef OUT
}  // namespace glsl

namespace {
int periodCells(float period) { return period > 0.0f ? static_cast<int>(std::floor(period + 0.5f)) : 0; }
}  // namespace

float simplex(glm::vec3 p) { return glsl::simplexNoise(p); }

float simplexGrad(glm::vec3 p, glm::vec3& gradient) { return glsl::simplexNoiseGrad(p, gradient); }

float fbm(glm::vec3 p, int octaves, float lacunarity, float gain) { return glsl::fbm(p, octaves, lacunarity, gain); }

float fbmGrad(glm::vec3 p, int octaves, float lacunarity, float gain, glm::vec3& gradient) {
    return glsl::fbmGrad(p, octaves, lacunarity, gain, gradient);
}

float ridgedFbm(glm::vec3 p, int octaves, float lacunarity, float gain) {
    return glsl::ridgedFbm(p, octaves, lacunarity, gain);
}

float worley(glm::vec3 p, float period) { return glsl::worleyF1(p, periodCells(period)); }

glm::vec3 worleyFeaturePoint(glm::ivec3 cell, float period) {
    return glsl::worleyFeaturePoint(cell, periodCells(period));
}

}  // namespace planet::noise
