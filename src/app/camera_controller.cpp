// Fly and orbit camera controls (see camera_controller.h).
//
// Fly mode works on a "level pose": a horizontal right vector plus a pitch
// above the local horizon. Mouse look yaws the right vector about the local
// up and adds to the pitch; the orientation is then rebuilt from the level
// pose. A move first carries the orientation with the turn of the local up
// (so heading and pitch relative to the ground are kept), then the level
// pose is rebuilt again, which removes any roll left by rounding or by a
// rolled start.
#include "app/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace planet {

namespace {

double finiteOr0(double v) { return std::isfinite(v) ? v : 0.0; }

ControlInput finiteInput(ControlInput input) {
    input.lookDx = finiteOr0(input.lookDx);
    input.lookDy = finiteOr0(input.lookDy);
    input.orbitDx = finiteOr0(input.orbitDx);
    input.orbitDy = finiteOr0(input.orbitDy);
    input.scroll = finiteOr0(input.scroll);
    return input;
}

double axis(bool positive, bool negative) { return (positive ? 1.0 : 0.0) - (negative ? 1.0 : 0.0); }

// --- Level pose --------------------------------------------------------------

struct LevelPose {
    glm::dvec3 right;  // unit, perpendicular to the local up
    double pitch;      // rad above the local horizon
};

LevelPose levelPoseOf(const Camera& camera, const glm::dvec3& localUp) {
    // Project the camera right onto the horizontal plane: well defined even
    // when looking straight up or down, as long as the camera is not rolled 90 deg.
    glm::dvec3 right = camera.right() - glm::dot(camera.right(), localUp) * localUp;
    if (glm::length(right) < 1e-9) right = glm::cross(camera.forward(), localUp);
    right = glm::normalize(right);
    const glm::dvec3 level = glm::cross(localUp, right);  // horizontal forward
    const glm::dvec3 f = camera.forward();
    return {right, std::atan2(glm::dot(f, localUp), glm::dot(f, level))};
}

// The pitch is clamped only where the user turns the camera (applyLook): a view
// placed straight down (the space bookmark) stays exactly as placed.
glm::dquat orientationOf(const LevelPose& pose, const glm::dvec3& localUp, bool clampPitch) {
    const double maxPitch = glm::radians(kMaxPitchDeg);
    const double pitch = clampPitch ? std::clamp(pose.pitch, -maxPitch, maxPitch) : pose.pitch;
    const glm::dvec3 level = glm::cross(localUp, pose.right);
    const glm::dvec3 forward = level * std::cos(pitch) + localUp * std::sin(pitch);
    return orientationFromAxes(pose.right, glm::cross(pose.right, forward), forward);
}

// Mouse look: x right turns right, y down looks down.
void applyLook(Camera& camera, const ControlInput& input, double sensitivity) {
    const glm::dvec3 localUp = localFrameAt(camera.position).up;
    LevelPose pose = levelPoseOf(camera, localUp);
    const double yaw = -input.lookDx * sensitivity;  // positive angle about up turns left
    pose.right = glm::normalize(glm::angleAxis(yaw, localUp) * pose.right);
    pose.pitch -= input.lookDy * sensitivity;
    camera.orientation = orientationOf(pose, localUp, true);
}

// Carries the orientation along with a move over the curved surface: the
// smallest rotation taking the old local up to the new one. Without it a
// level camera would keep its world direction, so its pitch relative to the
// horizon would drift as it flew around the planet.
void transportOrientation(Camera& camera, const glm::dvec3& oldUp, const glm::dvec3& newUp) {
    const glm::dvec3 axis = glm::cross(oldUp, newUp);
    const double sinAngle = glm::length(axis);
    if (sinAngle < 1e-15) return;  // no turn (or an antipodal jump, which the ground check prevents)
    const double angle = std::atan2(sinAngle, glm::dot(oldUp, newUp));
    camera.orientation = glm::normalize(glm::angleAxis(angle, axis / sinAngle) * camera.orientation);
}

// Roll correction: rebuild the orientation level w.r.t. the current local up.
void relevel(Camera& camera) {
    const glm::dvec3 localUp = localFrameAt(camera.position).up;
    camera.orientation = orientationOf(levelPoseOf(camera, localUp), localUp, false);
}

// --- Collision with the ground sphere ---------------------------------------

// Smallest t in [0, 1] where p + t * d enters the sphere of radius r, or -1.
double sphereEntry(const glm::dvec3& p, const glm::dvec3& d, double r) {
    const double a = glm::dot(d, d);
    const double b = glm::dot(p, d);
    const double pLength = glm::length(p);
    const double c = (pLength - r) * (pLength + r);  // factored: |p|^2 - r^2 without cancellation
    if (a <= 0.0 || c <= 0.0 || b >= 0.0) return -1.0;  // no motion, already inside, or moving away
    const double disc = b * b - a * c;
    if (disc < 0.0) return -1.0;
    const double t = c / (-b + std::sqrt(disc));  // stable form of (-b - sqrt(disc)) / a
    return t <= 1.0 ? t : -1.0;
}

// Moves from p by step without entering the sphere of radius minRadius. A
// step that would hit the sphere from above stops on it; the rest of that
// step is dropped, because speed scales with altitude and the remainder of a
// high-altitude step would fling the camera along the ground. From the
// surface itself (within rounding) the camera slides: it moves, then is
// lifted radially, which is safe because the speed there is tiny.
glm::dvec3 stepAboveGround(const glm::dvec3& p, const glm::dvec3& step, double minRadius) {
    constexpr double kOnSurfaceToleranceM = 1e-4;  // >> double rounding at planetary radii (~1e-8 m)
    glm::dvec3 q = p + step;
    if (glm::length(p) > minRadius + kOnSurfaceToleranceM) {
        const double t = sphereEntry(p, step, minRadius);
        if (t >= 0.0) q = p + t * step;
    }
    const double r = glm::length(q);
    if (r < minRadius && r > 0.0) q *= minRadius / r;
    return q;
}

// --- Orbit -------------------------------------------------------------------

// Trackball drag: the planet follows the mouse (drag right turns its near side
// right), so the camera turns the other way about its own up and right axes
// through the centre. The rate is scaled by altitude / distance so the ground
// moves at a similar speed under the cursor from orbit down to a few metres.
void applyOrbitDrag(Camera& camera, const ControlInput& input, double sensitivity, double planetRadiusM) {
    const double distance = glm::length(camera.position);
    if (distance <= 0.0) return;
    const double altitude = std::max(distance - planetRadiusM, kCameraMinAltitudeM);
    const double rate = sensitivity * std::min(altitude / distance, 1.0);
    const glm::dquat turn = glm::angleAxis(-input.orbitDx * rate, camera.up()) *
                            glm::angleAxis(-input.orbitDy * rate, camera.right());
    camera.position = turn * camera.position;
    camera.orientation = glm::normalize(turn * camera.orientation);
}

void applyOrbitZoom(Camera& camera, double scroll, double planetRadiusM) {
    const double distance = glm::length(camera.position);
    if (distance <= 0.0) return;
    const double altitude = (distance - planetRadiusM) * std::pow(kOrbitZoomFactor, scroll);
    const double maxAltitude = kCameraMaxDistanceM - planetRadiusM;
    const double clamped = std::clamp(altitude, kOrbitMinAltitudeM, std::max(maxAltitude, kOrbitMinAltitudeM));
    camera.position *= (planetRadiusM + clamped) / distance;
}

}  // namespace

void CameraController::update(Camera& camera, const ControlInput& rawInput, double dtSeconds, double planetRadiusM) {
    const ControlInput input = finiteInput(rawInput);
    const double dt = std::isfinite(dtSeconds) ? std::clamp(dtSeconds, 0.0, kMaxControlDtS) : 0.0;
    if (!std::isfinite(speedScale)) speedScale = 1.0;
    // Start from a valid pose so the mode code never works on NaN or a camera inside the planet.
    lastCorrection = sanitizeCamera(camera, planetRadiusM);
    if (mode == CameraMode::Fly) {
        updateFly(camera, input, dt, planetRadiusM);
    } else {
        updateOrbit(camera, input, planetRadiusM);
    }
    const std::string after = sanitizeCamera(camera, planetRadiusM);
    if (!after.empty()) lastCorrection += (lastCorrection.empty() ? "" : "; ") + after;
}

void CameraController::updateFly(Camera& camera, const ControlInput& input, double dt, double planetRadiusM) {
    speedScale = std::clamp(speedScale * std::pow(kScrollSpeedFactor, input.scroll), kMinSpeedScale, kMaxSpeedScale);
    if (input.lookDx != 0.0 || input.lookDy != 0.0) applyLook(camera, input, lookSensitivity);

    const glm::dvec3 localUp = localFrameAt(camera.position).up;
    glm::dvec3 direction = camera.forward() * axis(input.forward, input.back) +
                           camera.right() * axis(input.right, input.left) + localUp * axis(input.up, input.down);
    if (glm::length(direction) > 0.0) {
        direction = glm::normalize(direction);  // diagonals are not faster
        double speed = speedScale * std::max(camera.altitude(planetRadiusM), kFlyMinSpeedAltitudeM);
        if (input.fast) speed *= kFlyFastFactor;
        if (input.slow) speed *= kFlySlowFactor;
        camera.position =
            stepAboveGround(camera.position, direction * (speed * dt), planetRadiusM + kCameraMinAltitudeM);
        transportOrientation(camera, localUp, localFrameAt(camera.position).up);
    }
    relevel(camera);  // remove any roll w.r.t. the (new) local up
}

void CameraController::updateOrbit(Camera& camera, const ControlInput& input, double planetRadiusM) const {
    if (input.orbitDx != 0.0 || input.orbitDy != 0.0) applyOrbitDrag(camera, input, lookSensitivity, planetRadiusM);
    if (input.scroll != 0.0) applyOrbitZoom(camera, input.scroll, planetRadiusM);
}

}  // namespace planet
