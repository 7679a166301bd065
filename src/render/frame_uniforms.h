// FrameUniforms: the per-frame uniform block every pass reads (BLOCK_FRAME).
//
// C++ mirror of shaders/common/frame_uniforms.glsl (std140: each vec3 is followed by
// one float that fills its 16 bytes; offsets static_asserted below). Positions are
// camera-relative: the camera sits at the origin of a frame with world orientation; the
// planet centre is given relative to the camera, and the previous frame's camera
// relative to this one, both computed in double on the CPU. (STYLE habit 3.)
#pragma once

#include <cstddef>
#include <optional>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/scene.h"

namespace planet {

struct FrameUniforms {
    glm::mat4 clipFromView;           // reversed-Z, infinite far plane
    glm::mat4 viewFromClip;
    glm::mat4 viewFromWorld;          // rotation only (camera-relative world -> view)
    glm::mat4 worldFromView;          // rotation only
    glm::mat4 previousClipFromWorld;  // the previous frame's clipFromView * viewFromWorld
    glm::vec3 planetCenterFromCamera; // m, world axes
    float planetRadius;               // m
    glm::vec3 cameraUp;               // radial unit up at the camera
    float cameraAltitude;             // m above the planet radius
    glm::vec3 sunDirection;           // unit, towards the sun
    float time;                       // s, the scene's clock
    glm::vec3 cameraFromPrevious;     // m: this camera - the previous frame's, formed in double
    float historyValid;               // 1: the previous frame may be reprojected
    glm::vec2 viewportSize;           // pixels
    glm::vec2 inverseViewportSize;
    glm::vec2 jitter;                 // pixels, Halton (2, 3) in [-0.5, 0.5]
    float nearPlane;                  // m
    float exposure;
    int frameIndex;
    float cameraDepthBelowSea;        // m below the mean sea surface (> 0: under water)
    float stillSincePrevious;         // 1: the camera and the clock are the previous frame's (nothing moved)
    float padding1 = 0.0f;
    glm::vec3 cloudDriftSincePrevious; // m, world axes: how far the wind moved the clouds since the previous frame
    float padding2 = 0.0f;
};
static_assert(offsetof(FrameUniforms, planetCenterFromCamera) == 320 && offsetof(FrameUniforms, cameraUp) == 336 &&
                  offsetof(FrameUniforms, sunDirection) == 352 && offsetof(FrameUniforms, cameraFromPrevious) == 368 &&
                  offsetof(FrameUniforms, viewportSize) == 384 && offsetof(FrameUniforms, jitter) == 400 &&
                  offsetof(FrameUniforms, nearPlane) == 408 && offsetof(FrameUniforms, frameIndex) == 416 &&
                  offsetof(FrameUniforms, cloudDriftSincePrevious) == 432 && sizeof(FrameUniforms) == 448,
              "FrameUniforms must match the std140 block in shaders/common/frame_uniforms.glsl");

// The camera a previous frame was rendered with, kept in double for reprojection.
struct PreviousFrame {
    Camera camera;
    glm::ivec2 size{0, 0};
    double time_s = 0.0;              // the scene's clock
    glm::dvec3 sunDirection{0.0};     // the scene's sun
};

// Per-frame uniforms for a scene seen by a camera at a frame size, formed in double and
// rounded to float once (camera-relative rendering). `previous`, when given, is the frame
// the history holds: its camera becomes previousClipFromWorld and cameraFromPrevious, and
// historyValid is 1; without it the previous terms are this frame's own and historyValid 0.
FrameUniforms makeFrameUniforms(const Scene& scene, const Camera& camera, glm::ivec2 size, int frameIndex,
                                const std::optional<PreviousFrame>& previous);

// Element `index` (from 1) of the Halton sequence in `base`, in [0, 1).
double halton(int index, int base);
// The sub-pixel jitter of frame `frameIndex`: Halton (2, 3) over a cycle of 16 frames,
// centred, in pixels in [-0.5, 0.5).
glm::vec2 subPixelJitter(int frameIndex);

// Mean sea surface radius - camera distance, m (> 0 when the camera is under water;
// -1e30 on a dry world, which has no sea, so that no point is below it).
double cameraDepthBelowSeaM(const Scene& scene, const Camera& camera);

}  // namespace planet
