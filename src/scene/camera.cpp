// Camera pose, projection, local frames and sanitising (see camera.h).
//
// Organisation: Camera members, then the projection helpers, then the
// geographic helpers, then sanitizeCamera split into one small fix per rule.
#include "scene/camera.h"

#include <cmath>

#include "scene/scene.h"

namespace planet {

namespace {

bool isFinite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool isFinite(const glm::dquat& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

}  // namespace

glm::dquat orientationFromAxes(const glm::dvec3& right, const glm::dvec3& up, const glm::dvec3& forward) {
    const glm::dmat3 worldFromView(right, up, -forward);  // columns: view +X, +Y, +Z in world
    return glm::normalize(glm::quat_cast(worldFromView));
}

// --- Camera ----------------------------------------------------------------

glm::dvec3 Camera::forward() const { return orientation * glm::dvec3(0.0, 0.0, -1.0); }
glm::dvec3 Camera::right() const { return orientation * glm::dvec3(1.0, 0.0, 0.0); }
glm::dvec3 Camera::up() const { return orientation * glm::dvec3(0.0, 1.0, 0.0); }

glm::dmat3 Camera::worldFromView() const { return glm::mat3_cast(orientation); }

glm::mat4 Camera::viewFromWorldRotation() const {
    // Inverse of a rotation is its transpose; done in double, cast once.
    return glm::mat4(glm::mat3(glm::transpose(worldFromView())));
}

glm::dmat4 Camera::clipFromView(double aspect) const { return reversedZInfinitePerspective(fovY_rad, aspect, near_m); }

glm::vec3 Camera::relativePosition(const glm::dvec3& worldPoint) const {
    return glm::vec3(worldPoint - position);  // subtract in double, then the small result fits a float
}

double Camera::altitude(double planetRadiusM) const { return glm::length(position) - planetRadiusM; }

// --- Projection ------------------------------------------------------------

glm::dmat4 reversedZInfinitePerspective(double fovY, double aspect, double near) {
    // clip = (f/aspect x, f y, near, -z): after the divide by w = -z,
    // depth = near / -z, which is 1 at the near plane and 0 at infinity.
    const double f = 1.0 / std::tan(0.5 * fovY);
    glm::dmat4 m(0.0);  // m[column][row]
    m[0][0] = f / aspect;
    m[1][1] = f;
    m[2][3] = -1.0;
    m[3][2] = near;
    return m;
}

double depthFromViewZ(double viewZ, double near) { return near / -viewZ; }

double viewZFromDepth(double depth, double near) { return -near / depth; }

// --- Geographic helpers ----------------------------------------------------

LocalFrame localFrameAt(const glm::dvec3& position) {
    const double r = glm::length(position);
    const glm::dvec3 up = r > 0.0 ? position / r : glm::dvec3(0.0, 0.0, 1.0);
    glm::dvec3 east = glm::cross(glm::dvec3(0.0, 0.0, 1.0), up);
    const double eastLength = glm::length(east);
    // At the poles cross(+Z, up) vanishes; use east's limit along longitude 0 (+Y),
    // which is already perpendicular to up there.
    east = eastLength > 1e-12 ? east / eastLength : glm::dvec3(0.0, 1.0, 0.0);
    return {east, glm::cross(up, east), up};
}

Camera cameraAtGeographic(double latDeg, double lonDeg, double altitudeM, double headingDeg, double pitchDeg,
                          double fovYDeg, double planetRadiusM) {
    Camera camera;
    camera.position = directionFromLatLon(latDeg, lonDeg) * (planetRadiusM + altitudeM);
    camera.fovY_rad = glm::radians(fovYDeg);

    const LocalFrame local = localFrameAt(camera.position);
    const double heading = glm::radians(headingDeg);
    const double pitch = glm::radians(pitchDeg);
    // Heading turns clockwise seen from above: north towards east.
    const glm::dvec3 level = local.north * std::cos(heading) + local.east * std::sin(heading);
    const glm::dvec3 right = local.east * std::cos(heading) - local.north * std::sin(heading);
    const glm::dvec3 forward = level * std::cos(pitch) + local.up * std::sin(pitch);
    camera.orientation = orientationFromAxes(right, glm::cross(right, forward), forward);
    return camera;
}

// --- Sanitising ------------------------------------------------------------

namespace {

void append(std::string& message, const std::string& text) {
    if (!message.empty()) message += "; ";
    message += text;
}

Camera defaultOrbitCamera(double planetRadiusM) {
    return cameraAtGeographic(0.0, 0.0, 2.0 * planetRadiusM, 0.0, -90.0, 60.0, planetRadiusM);
}

void fixNonFinitePose(Camera& camera, double planetRadiusM, std::string& message) {
    if (isFinite(camera.position) && isFinite(camera.orientation) && glm::length(camera.orientation) > 1e-6) return;
    const Camera fallback = defaultOrbitCamera(planetRadiusM);
    camera.position = fallback.position;
    camera.orientation = fallback.orientation;
    append(message, "non-finite camera pose reset to the default orbit view");
}

void fixProjection(Camera& camera, std::string& message) {
    const Camera defaults;
    if (!std::isfinite(camera.fovY_rad) || camera.fovY_rad <= 1e-4 || camera.fovY_rad >= glm::pi<double>() - 1e-4) {
        camera.fovY_rad = defaults.fovY_rad;
        append(message, "invalid field of view reset to 60 deg");
    }
    if (!std::isfinite(camera.near_m) || camera.near_m <= 0.0) {
        camera.near_m = defaults.near_m;
        append(message, "invalid near plane reset to 0.1 m");
    }
}

void fixOrientationLength(Camera& camera, std::string& message) {
    const double deviation = std::abs(glm::length(camera.orientation) - 1.0);
    // Tiny drift from repeated quaternion products is renormalised silently;
    // the threshold keeps an already-unit quaternion bit-for-bit unchanged.
    if (deviation > 1e-12) camera.orientation = glm::normalize(camera.orientation);
    if (deviation > 1e-3) append(message, "orientation renormalised");
}

void fixDistance(Camera& camera, double planetRadiusM, std::string& message) {
    const double r = glm::length(camera.position);
    const glm::dvec3 direction = r > 0.0 ? camera.position / r : glm::dvec3(0.0, 0.0, 1.0);
    const double minRadius = planetRadiusM + kCameraMinAltitudeM;
    if (r < minRadius) {
        camera.position = direction * minRadius;
        append(message, "camera below the ground lifted to 0.1 m altitude");
    } else if (r > kCameraMaxDistanceM) {
        camera.position = direction * kCameraMaxDistanceM;
        append(message, "camera beyond the supported range pulled back to 1e9 m from the centre");
    }
}

}  // namespace

std::string sanitizeCamera(Camera& camera, double planetRadiusM) {
    std::string message;
    fixNonFinitePose(camera, planetRadiusM, message);
    fixProjection(camera, message);
    fixOrientationLength(camera, message);
    fixDistance(camera, planetRadiusM, message);
    return message;
}

}  // namespace planet
