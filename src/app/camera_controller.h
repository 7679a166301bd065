// Camera controls: fly (WASD + mouse look) and orbit (trackball drag + zoom).
//
// Window-free so it can be unit tested: the app turns GLFW events into a
// ControlInput each frame and calls CameraController::update. Both modes keep
// the camera valid (sanitizeCamera) and clamp dt so a hitch cannot teleport it.
//
// Fly: speed = speedScale * max(altitude, 1 m) per second, so one second of
// flight covers about one altitude from the beach to deep space. The camera
// never rolls: its right vector stays horizontal w.r.t. the local up, which is
// re-applied after every update (also after long moves around the sphere).
// Orbit: the camera pose is rotated about the planet centre, keeping the
// distance; the wheel zooms exponentially in altitude.
#pragma once

#include <string>

#include "scene/camera.h"

namespace planet {

struct ControlInput {
    bool forward = false, back = false, left = false, right = false, up = false, down = false;  // W S A D E Q
    bool fast = false, slow = false;  // Shift x5, Ctrl /5
    // Mouse deltas in window pixels (x right, y down, as GLFW reports them).
    double lookDx = 0, lookDy = 0;    // while the look button (right mouse) is held, else 0
    double orbitDx = 0, orbitDy = 0;  // while the orbit button (left mouse) is held, else 0
    double scroll = 0;                // wheel notches this frame (+ = up/away from the user)
};

enum class CameraMode { Fly, Orbit };

class CameraController {
public:
    CameraMode mode = CameraMode::Fly;
    double speedScale = 1.0;         // fly speed = speedScale * max(altitude, 1 m) per second, [1e-3, 1e3]
    double lookSensitivity = 0.003;  // rad per pixel, also the orbit drag rate (scaled by altitude / distance)
    std::string lastCorrection;      // what sanitizeCamera fixed in the last update, "" if nothing

    // Advances the camera by one frame. dtSeconds is clamped to [0, 0.25].
    void update(Camera& camera, const ControlInput& input, double dtSeconds, double planetRadiusM);

private:
    void updateFly(Camera& camera, const ControlInput& input, double dtSeconds, double planetRadiusM);
    void updateOrbit(Camera& camera, const ControlInput& input, double planetRadiusM) const;
};

// Tunables shared by the implementation and the tests.
inline constexpr double kMaxControlDtS = 0.25;         // s, longest step one update integrates
inline constexpr double kFlyMinSpeedAltitudeM = 1.0;   // m, altitude below which fly speed stops shrinking
inline constexpr double kFlyFastFactor = 5.0;          // Shift
inline constexpr double kFlySlowFactor = 0.2;          // Ctrl
inline constexpr double kScrollSpeedFactor = 1.2;      // fly speedScale change per wheel notch
inline constexpr double kMinSpeedScale = 1e-3;
inline constexpr double kMaxSpeedScale = 1e3;
inline constexpr double kMaxPitchDeg = 89.5;           // deg from the local horizon, fly mode
inline constexpr double kOrbitZoomFactor = 0.85;       // altitude factor per wheel notch forward
inline constexpr double kOrbitMinAltitudeM = 1.0;      // m, closest orbit zoom

}  // namespace planet
