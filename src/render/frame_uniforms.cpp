#include "render/frame_uniforms.h"

#include <cmath>
#include <limits>

#include <glm/gtc/matrix_access.hpp>

#include "clouds/cloud_block.h"

namespace planet {

double halton(int index, int base) {
    double result = 0.0;
    double fraction = 1.0;
    for (int i = index; i > 0; i /= base) {
        fraction /= base;
        result += fraction * (i % base);
    }
    return result;
}

glm::vec2 subPixelJitter(int frameIndex) {
    // One step further along the cycle at every new cycle: the reduced-rate march traces each
    // pixel every 16 frames (render/sparse_pattern.glsl), and with the same cycle it would trace
    // it at the same jitter every time.
    const int i = (frameIndex + frameIndex / 16) % 16 + 1;  // from 1: element 0 of every Halton sequence is 0
    return glm::vec2(static_cast<float>(halton(i, 2) - 0.5), static_cast<float>(halton(i, 3) - 0.5));
}

glm::dvec2 stillSampleJitter(int sample, int samples) {
    if (samples <= 1) return glm::dvec2(0.0);
    auto element = [](int i) { return glm::dvec2(halton(i + 1, 2), halton(i + 1, 3)); };
    glm::dvec2 mean(0.0);
    for (int i = 0; i < samples; ++i) mean += element(i) / static_cast<double>(samples);
    return element(sample) - mean;
}

namespace {
// One side plane of a view, w + side x (axis 0) or w + side y (axis 1) >= 0 of clip = clipFromWorld p
// (Gribb & Hartmann's extraction), as (unit normal, offset in metres).
glm::dvec4 sidePlane(const glm::dmat4& clipFromWorld, int axis, double side) {
    const glm::dvec4 plane = glm::row(clipFromWorld, 3) + side * glm::row(clipFromWorld, axis);
    return plane / glm::length(glm::dvec3(plane));
}
}  // namespace

// The camera and the sun stood still between two frames: the camera moved by less than a
// millimetre, and it and the sun turned by less than a microradian (a camera path between two
// equal keyframes moves them by rounding errors, which nothing on screen shows).
bool viewStoodStill(const Camera& before, const Camera& now, glm::dvec3 sunBefore, glm::dvec3 sunNow) {
    constexpr double kMetres = 1.0e-3, kRadians = 1.0e-6;
    // |q1 . q2| = cos(angle / 2): 1 - that is about angle^2 / 8
    const double turned = 1.0 - std::abs(glm::dot(before.orientation, now.orientation));
    return glm::length(now.position - before.position) < kMetres && turned < kRadians * kRadians / 8.0 &&
           glm::dot(sunBefore, sunNow) > 1.0 - kRadians * kRadians / 2.0;
}

glm::dmat4 jitteredClipFromView(const Camera& camera, glm::ivec2 size, glm::dvec2 jitterPx) {
    const double aspect = static_cast<double>(size.x) / static_cast<double>(size.y);
    // NDC spans 2 across the viewport, so a pixel is 2 / size; x' = x + offset.x * w (and
    // so for y) moves NDC by offset after the divide. glm is column-major: [column][row].
    const glm::dvec2 offset = 2.0 * jitterPx / glm::dvec2(size);
    glm::dmat4 jitteredFromClip(1.0);
    jitteredFromClip[3][0] = offset.x;
    jitteredFromClip[3][1] = offset.y;
    return jitteredFromClip * camera.clipFromView(aspect);
}

double cameraDepthBelowSeaM(const Scene& scene, const Camera& camera) {
    if (!scene.terrain.ocean) return -1e30;  // no sea: everything, camera or ground, is above it
    return scene.planetRadiusM() + scene.ocean.sea_level_m - glm::length(camera.position);
}

double cloudDriftPixels(const Scene& scene, const Camera& camera, glm::ivec2 size, double seconds) {
    const double drift_m =
        glm::length(clouds::windDriftKm(scene, scene.time_s) - clouds::windDriftKm(scene, scene.time_s - seconds)) * 1000.0;
    if (drift_m == 0.0 || !scene.clouds.enabled) return 0.0;
    // The nearest cloud: the layer's top below a camera above it; within or under the layer, at
    // the camera (any drift is a whole pixel there).
    const double aboveTop_m = camera.altitude(scene.planetRadiusM()) - scene.clouds.top_altitude_km * 1000.0;
    if (!(aboveTop_m > 0.0)) return std::numeric_limits<double>::infinity();
    const double pixelAngle = camera.fovY_rad / std::max(size.y, 1);
    return drift_m / aboveTop_m / pixelAngle;
}

FrameUniforms makeFrameUniforms(const Scene& scene, const Camera& camera, glm::ivec2 size, int frameIndex,
                                const std::optional<PreviousFrame>& previous, glm::dvec2 jitterPx) {
    const glm::dmat4 clipFromView = jitteredClipFromView(camera, size, jitterPx);
    const double radius = scene.planetRadiusM();
    // Everything below is formed in double and only then rounded to float, so
    // the GPU never subtracts two planet-sized numbers.
    const glm::dvec3 centreFromCamera = -camera.position;
    const double distance = glm::length(camera.position);
    // The app keeps cameras outside the planet (sanitizeCamera); a camera at the
    // very centre still gets a defined up rather than a division by zero.
    const glm::dvec3 up = distance > 0.0 ? camera.position / distance : glm::dvec3(0.0, 0.0, 1.0);

    FrameUniforms u{};
    u.clipFromView = glm::mat4(clipFromView);
    u.viewFromClip = glm::mat4(glm::inverse(clipFromView));
    u.viewFromWorld = camera.viewFromWorldRotation();
    u.worldFromView = glm::mat4(glm::dmat4(camera.worldFromView()));
    const Camera& before = previous ? previous->camera : camera;
    const glm::ivec2 beforeSize = previous ? previous->size : size;
    const glm::dvec2 beforeJitter = previous ? previous->jitterPx : jitterPx;
    u.previousClipFromWorld = glm::mat4(jitteredClipFromView(before, beforeSize, beforeJitter) *
                                        glm::dmat4(glm::transpose(before.worldFromView())));
    u.planetCenterFromCamera = glm::vec3(centreFromCamera);
    u.planetRadius = static_cast<float>(radius);
    u.cameraUp = glm::vec3(up);
    u.cameraAltitude = static_cast<float>(distance - radius);
    u.sunDirection = glm::vec3(scene.sunDirection());
    u.time = static_cast<float>(scene.time_s);
    u.cameraFromPrevious = glm::vec3(camera.position - before.position);
    u.historyValid = previous ? 1.0f : 0.0f;
    // The view: the camera and the light; with the clock, everything (the wind moves the clouds).
    const bool viewStill = previous && viewStoodStill(before, camera, previous->sunDirection, scene.sunDirection());
    // Only the clock ran, and the explorer's anti-aliasing moved the sub-pixel jitter: the
    // camera and the sun stood (render/sky_history.glsl then reads a pixel's own history texel).
    u.viewStillSincePrevious = viewStill ? 1.0f : 0.0f;
    u.stillSincePrevious =
        viewStill && (previous->time_s == scene.time_s ||
                      cloudDriftPixels(scene, camera, size, scene.time_s - previous->time_s) < kStillCloudDriftPx)
            ? 1.0f
            : 0.0f;
    u.viewportSize = glm::vec2(size);
    u.inverseViewportSize = 1.0f / glm::vec2(size);
    u.jitter = glm::vec2(jitterPx);
    u.previousJitterX = static_cast<float>(beforeJitter.x);
    u.previousJitterY = static_cast<float>(beforeJitter.y);
    u.nearPlane = static_cast<float>(camera.near_m);
    u.exposure = static_cast<float>(scene.render.exposure);
    u.temporalRefineError = static_cast<float>(scene.render.temporal_refine_error);
    u.frameIndex = frameIndex;
    u.cameraDepthBelowSea = static_cast<float>(cameraDepthBelowSeaM(scene, camera));
    const double beforeTime = previous ? previous->time_s : scene.time_s;
    u.cloudDriftSincePrevious = glm::vec3((clouds::windDriftKm(scene) - clouds::windDriftKm(scene, beforeTime)) * 1000.0);
    const glm::dmat4 clipFromWorld = clipFromView * glm::dmat4(glm::transpose(camera.worldFromView()));
    for (int k = 0; k < 4; ++k) u.viewSidePlanes[k] = glm::vec4(sidePlane(clipFromWorld, k / 2, k % 2 == 0 ? 1.0 : -1.0));
    return u;
}

}  // namespace planet
