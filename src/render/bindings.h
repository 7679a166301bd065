// Texture units and buffer bindings of the frame, from the very file the shaders include
// (shaders/common/bindings.glsl, compiled here as C++): one source of truth, no literal
// unit numbers in the C++ (STYLE habit 3).
#pragma once

namespace planet::binding {
#include "shaders/common/bindings.glsl"
}  // namespace planet::binding
