// The projected grids' constants shared with the shaders, from the very file they include
// (shaders/grid/constants.glsl, compiled here as C++).
#pragma once

namespace planet::grid_constant {
#include "shaders/grid/constants.glsl"
}  // namespace planet::grid_constant
