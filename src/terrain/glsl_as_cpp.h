// The names the terrain's shared GLSL (shaders/noise/simplex.glsl, shaders/terrain/height.glsl,
// shaders/terrain/terrain_shadow.glsl) takes from GLSL, supplied in C++ (STYLE habit 1):
// GLM's float types and functions, the GLSL samplerCube as the CPU continents map with
// textureLod as its seamless bilinear filter (noise::sampleContinents), and OUT(x) as x&.
//
// Included INSIDE the namespace that is to hold the compiled GLSL, right before the .glsl
// files (terrain/height.cpp, terrain/terrain_shadow.cpp); #undef OUT after them. No include
// guard on purpose: each such namespace needs its own copy.
//   namespace glsl {
//   #include "terrain/glsl_as_cpp.h"
//   #include "shaders/noise/simplex.glsl"
//   ...
//   #undef OUT
//   }
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using samplerCube = const noise::CubeMap&;
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
using glm::sqrt;
using glm::step;
using std::abs;
using std::acos;
using std::asin;
using std::floor;
using std::ldexp;
using std::log2;
using std::pow;
using std::sqrt;
inline vec4 textureLod(samplerCube map, vec3 direction, float /*level: the map has one*/) {
    return noise::sampleContinents(map, glm::dvec3(direction));
}
#define OUT(x) x&
