// The cloud layer's shared model (shaders/clouds/cloud_model.glsl) compiled as C++ in
// double, as the atmosphere's model is (src/atmosphere/model.h): the tests check the very
// functions the GPU runs against worked values, and a CPU march can be built on them.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace planet::clouds::glsl {
using Number = double;
using Length = double;
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using glm::clamp;
using glm::exp;
using glm::max;
using glm::min;
using std::exp;
using std::abs;
using std::log;
using std::sqrt;
#define IN(x) const x&
#define OUT(x) x&
#define INOUT(x) x&
// Internal linkage: every translation unit that includes this has its own copy (GLSL has
// no `inline`), and uses what it needs of it.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace {
#include "shaders/clouds/cloud_model.glsl"
}  // namespace
#pragma GCC diagnostic pop
#undef IN
#undef OUT
#undef INOUT
}  // namespace planet::clouds::glsl
