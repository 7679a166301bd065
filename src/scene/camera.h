// Camera: double-precision pose, reversed-Z infinite projection, local frames.
//
// The scene spans 2 m (standing on a beach) to 1e9 m (deep space), far beyond
// what 32-bit floats hold in world space (float spacing at 6.36e6 m is 0.5 m).
// So the camera keeps its pose in double, and rendering is camera-relative:
// the CPU subtracts the camera position in double and sends the small result
// as float, and the GPU only gets the rotation part of the view transform
// (viewFromWorldRotation).
//
// Depth uses reversed Z with the far plane at infinity (glClipControl with
// GL_LOWER_LEFT / GL_ZERO_TO_ONE, a 32-bit float depth buffer cleared to 0,
// glDepthFunc(GL_GREATER)): depth = near / distance. Float's relative
// precision is then the same at every distance, which separates surfaces
// 1e-5 apart (relative) anywhere from 0.1 m to 1e9 m.
//
// Frames: world as in scene/scene.h (centre at the origin, +Z north pole).
// View is OpenGL's: looks down -Z, +Y up, +X right.
#pragma once

#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace planet {

// Limits the renderer supports; sanitizeCamera enforces them.
inline constexpr double kCameraMinAltitudeM = 0.1;  // m above the sphere; below this the camera is inside the ground
inline constexpr double kCameraMaxDistanceM = 1e9;  // m from the planet centre; the supported depth range

struct Camera {
    glm::dvec3 position{0.0, 0.0, 7e6};             // world frame, m
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};     // worldFromView rotation (w, x, y, z), unit length
    double fovY_rad = glm::radians(60.0);           // vertical field of view, rad, (0, pi)
    double near_m = 0.1;                            // near plane of the reversed-Z infinite projection, m, > 0

    glm::dvec3 forward() const;  // world-frame view direction (view -Z)
    glm::dvec3 right() const;    // world-frame view +X
    glm::dvec3 up() const;       // world-frame view +Y
    glm::dmat3 worldFromView() const;
    // Float, rotation only: viewFromWorld without the translation, for camera-relative rendering.
    glm::mat4 viewFromWorldRotation() const;
    glm::dmat4 clipFromView(double aspect) const;
    // worldPoint - position, computed in double then cast to float: what the GPU gets.
    glm::vec3 relativePosition(const glm::dvec3& worldPoint) const;
    double altitude(double planetRadiusM) const;  // |position| - radius, m
};

// Reversed-Z perspective with the far plane at infinity (see the file header).
// A view-space point at z = -near maps to NDC depth 1, z -> -inf to 0; x and y
// map as in a standard perspective. fovY in rad, aspect = width / height.
glm::dmat4 reversedZInfinitePerspective(double fovY, double aspect, double near);
// NDC depth of a view-space z (z < 0 in front of the camera): near / -viewZ.
double depthFromViewZ(double viewZ, double near);
// Inverse of depthFromViewZ: -near / depth.
double viewZFromDepth(double depth, double near);

// Orientation (worldFromView) whose view axes are right (+X), up (+Y) and
// forward (-Z) in the world frame. The axes must be orthonormal with
// cross(right, up) = -forward.
glm::dquat orientationFromAxes(const glm::dvec3& right, const glm::dvec3& up, const glm::dvec3& forward);

// Local east/north/up at a world position. up = normalize(position); east =
// normalize(cross(+Z, up)); at the poles (and the centre) east falls back to
// the limit along longitude 0, which is +Y.
struct LocalFrame {
    glm::dvec3 east, north, up;
};
LocalFrame localFrameAt(const glm::dvec3& position);

// A camera at geographic coordinates: altitude above the sphere of radius
// planetRadiusM (m), heading clockwise from north (deg), pitch above the local
// horizon (deg, -90 looks straight down), vertical fov (deg). No roll: the
// camera's right vector is horizontal.
Camera cameraAtGeographic(double latDeg, double lonDeg, double altitudeM, double headingDeg, double pitchDeg,
                          double fovYDeg, double planetRadiusM);

// Keep the camera usable whatever happened to it:
//  - NaN/Inf position or orientation -> a default orbit view (above lat 0,
//    lon 0 at altitude 2 radii, looking at the centre);
//  - invalid fov or near -> defaults; non-unit orientation -> renormalised;
//  - less than kCameraMinAltitudeM above the sphere -> lifted radially to it;
//  - farther than kCameraMaxDistanceM from the centre -> pulled back along the
//    same direction.
// Returns a human-readable description of what was corrected, or "" if nothing was.
std::string sanitizeCamera(Camera& camera, double planetRadiusM);

}  // namespace planet
