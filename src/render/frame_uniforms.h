// FrameUniforms: the per-frame uniform block every pass reads (BLOCK_FRAME).
//
// C++ mirror of shaders/common/frame_uniforms.glsl (std140: each vec3 is followed by
// one float that fills its 16 bytes; offsets static_asserted below). Positions are
// camera-relative: the camera sits at the origin of a frame with world orientation; the
// planet centre is given relative to the camera, and the previous frame's camera
// relative to this one, both computed in double on the CPU. (STYLE habit 3.)
//
// Sub-pixel jitter: a frame may be rendered with its projection moved by a fraction of a
// pixel (`jitterPx`, pixels). It is applied once here, in clip space, as
//     clipFromView = translate(2 jitter / viewport) * unjittered clipFromView
// and viewFromClip is its inverse, so every pass agrees: the terrain's and the sea's
// rasterised geometry, the full-screen passes' rays (worldRayFromNdc through viewFromClip)
// and depth reconstruction. A pixel centre's NDC then names the point at (centre - jitter)
// of the unjittered frame. previousClipFromWorld carries the previous frame's jitter, so a
// reprojected point lands on the history texel that sampled it. (Stills average several
// jittered frames: src/app/render_command.cpp.)
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
    glm::vec2 jitter;                 // pixels: the offset applied to clipFromView (0: unjittered)
    float nearPlane;                  // m
    float exposure;
    int frameIndex;
    float cameraDepthBelowSea;        // m below the mean sea surface (> 0: under water)
    float stillSincePrevious;         // 1: the camera and the sun are the previous frame's, and the clock too or its
                                      // clouds' drift is under kStillCloudDriftPx (nothing moved, at the pixels' scale)
    float previousJitterX;            // pixels: the previous frame's jitter (x; y after the drift)
    glm::vec3 cloudDriftSincePrevious; // m, world axes: how far the wind moved the clouds since the previous frame
    float previousJitterY;
    float temporalRefineError;        // render.temporal_refine_error (render/sky_temporal.frag)
    float viewStillSincePrevious;     // 1: the camera and the sun are the previous frame's (the clock and the
                                      // anti-aliasing's sub-pixel jitter may have moved on)
    float padding[2];
    // The view's four side planes (x = -w, x = w, y = -w, y = w of its clip space) in camera-relative
    // world axes, each (unit normal pointing inside, offset): a point p is dot(n, p) + d metres inside.
    glm::vec4 viewSidePlanes[4];
};
static_assert(offsetof(FrameUniforms, planetCenterFromCamera) == 320 && offsetof(FrameUniforms, cameraUp) == 336 &&
                  offsetof(FrameUniforms, sunDirection) == 352 && offsetof(FrameUniforms, cameraFromPrevious) == 368 &&
                  offsetof(FrameUniforms, viewportSize) == 384 && offsetof(FrameUniforms, jitter) == 400 &&
                  offsetof(FrameUniforms, nearPlane) == 408 && offsetof(FrameUniforms, frameIndex) == 416 &&
                  offsetof(FrameUniforms, cloudDriftSincePrevious) == 432 &&
                  offsetof(FrameUniforms, temporalRefineError) == 448 &&
                  offsetof(FrameUniforms, viewStillSincePrevious) == 452 &&
                  offsetof(FrameUniforms, viewSidePlanes) == 464 && sizeof(FrameUniforms) == 528,
              "FrameUniforms must match the std140 block in shaders/common/frame_uniforms.glsl");

// The camera a previous frame was rendered with, kept in double for reprojection.
struct PreviousFrame {
    Camera camera;
    glm::ivec2 size{0, 0};
    double time_s = 0.0;              // the scene's clock
    glm::dvec3 sunDirection{0.0};     // the scene's sun
    glm::dvec2 jitterPx{0.0};         // the sub-pixel offset its projection had, pixels
};

// How far the wind moves the clouds in `seconds`, in pixels of a `size` frame, seen from the
// camera where they are nearest (the layer's top below a camera above it; infinity from within
// or under the layer, where a cloud may touch the camera; 0 without clouds or wind).
double cloudDriftPixels(const Scene& scene, const Camera& camera, glm::ivec2 size, double seconds);
// Below this drift a frame whose clock ran counts as still (FrameUniforms::stillSincePrevious):
// the clouds are the only thing in the sky the clock moves, and the reconstruction's still
// program then keeps a running mean of up to 16 samples a pixel, one a visit every 16 frames,
// whose lag (about 15 visits, 240 frames) is then under a quarter of a pixel. From orbit (400 km,
// 60 degrees over 720 pixels) a 10 m/s wind moves the cloud tops 6e-4 pixels a frame at 30 Hz,
// from space 1e-5; from an aircraft 6 km above them, 0.03.
inline constexpr double kStillCloudDriftPx = 1.0e-3;

// The camera and the sun stood still between two frames, to within rounding (a millimetre, a
// microradian): FrameUniforms::viewStillSincePrevious.
bool viewStoodStill(const Camera& before, const Camera& now, glm::dvec3 sunBefore, glm::dvec3 sunNow);

// A camera's clipFromView for a frame size, moved by a sub-pixel offset (pixels; +x right,
// +y up): the image content moves by jitterPx.
glm::dmat4 jitteredClipFromView(const Camera& camera, glm::ivec2 size, glm::dvec2 jitterPx);

// Per-frame uniforms for a scene seen by a camera at a frame size, formed in double and
// rounded to float once (camera-relative rendering). `previous`, when given, is the frame
// the history holds: its camera becomes previousClipFromWorld and cameraFromPrevious, and
// historyValid is 1; without it the previous terms are this frame's own and historyValid 0.
// `jitterPx` moves this frame's projection by a sub-pixel offset (see above; 0: none).
FrameUniforms makeFrameUniforms(const Scene& scene, const Camera& camera, glm::ivec2 size, int frameIndex,
                                const std::optional<PreviousFrame>& previous, glm::dvec2 jitterPx = glm::dvec2(0.0));

// Element `index` (from 1) of the Halton sequence in `base`, in [0, 1).
double halton(int index, int base);
// The sub-pixel jitter of frame `frameIndex`: Halton (2, 3) over a cycle of 16 frames,
// centred, in pixels in [-0.5, 0.5); each cycle starts one element further on, so that frames
// 16 apart take every element in turn.
glm::vec2 subPixelJitter(int frameIndex);
// The offset of sample `sample` of `samples` (>= 1) that a still averages: Halton (2, 3)
// from element 1, moved so that the offsets of the `samples` average to exactly (0, 0)
// (Halton's first elements are not centred: for 4 samples their mean is (-0.09, -0.11) px,
// which would shift the whole image). One sample: (0, 0), the unjittered frame.
glm::dvec2 stillSampleJitter(int sample, int samples);

// Mean sea surface radius - camera distance, m (> 0 when the camera is under water;
// -1e30 on a dry world, which has no sea, so that no point is below it).
double cameraDepthBelowSeaM(const Scene& scene, const Camera& camera);

}  // namespace planet
