// FrameUniforms: the per-frame uniform block every pass reads (binding 0).
//
// C++ mirror of shaders/common/frame_uniforms.glsl (std140: only vec4/mat4
// members, so the C++ layout matches with no padding rules to remember).
// Positions are camera-relative: the camera sits at the origin of a frame with
// world orientation; the planet centre is given relative to the camera,
// computed in double on the CPU. (STYLE habit 3.)
#pragma once

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/scene.h"

namespace planet {

struct FrameUniforms {
    glm::mat4 clipFromView;           // reversed-Z, infinite far plane
    glm::mat4 viewFromClip;
    glm::mat4 viewFromWorld;          // rotation only (camera-relative world -> view)
    glm::mat4 worldFromView;          // rotation only
    glm::vec4 planetCenterFromCamera; // xyz: centre - camera (m, world axes); w: planet radius (m)
    glm::vec4 cameraUp;               // xyz: radial unit up at the camera; w: camera altitude (m), from double
    glm::vec4 sunDirection;           // xyz: unit vector towards the sun (world axes); w: angular radius (rad)
    glm::vec4 viewport;               // width, height, 1/width, 1/height (pixels)
    glm::vec4 camera;                 // x: near plane (m); y: exposure; zw: unused
};
static_assert(sizeof(FrameUniforms) == 4 * 64 + 5 * 16, "FrameUniforms must match the std140 GLSL block");

// Per-frame uniforms for a scene seen by a camera at a frame size, formed in
// double and rounded to float once (camera-relative rendering).
FrameUniforms makeFrameUniforms(const Scene& scene, const Camera& camera, glm::ivec2 size);

}  // namespace planet
