// Tests for the camera (projection, precision, geographic placement,
// sanitising) and the fly/orbit controller. CPU only, analytic expectations.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "scene/camera.h"
#include "app/camera_controller.h"
#include "scene/scene.h"

namespace planet {
namespace {

constexpr double kRadiusM = 6.36e6;

// Projects a view-space point and returns NDC (after the perspective divide).
glm::dvec3 ndcOf(const glm::dmat4& clipFromView, const glm::dvec3& viewPoint) {
    const glm::dvec4 clip = clipFromView * glm::dvec4(viewPoint, 1.0);
    return glm::dvec3(clip) / clip.w;
}

double horizonTilt(const Camera& camera) {  // |right . localUp|, 0 when level
    return std::abs(glm::dot(camera.right(), localFrameAt(camera.position).up));
}

double pitchDeg(const Camera& camera) {
    return glm::degrees(std::asin(glm::dot(camera.forward(), localFrameAt(camera.position).up)));
}

void expectOrthonormal(const Camera& camera) {
    const glm::dmat3 m = camera.worldFromView();
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(glm::length(m[i]), 1.0, 1e-12);
        for (int j = i + 1; j < 3; ++j) EXPECT_NEAR(glm::dot(m[i], m[j]), 0.0, 1e-12);
    }
    EXPECT_NEAR(glm::determinant(m), 1.0, 1e-12);  // a rotation, not a reflection
}

bool isFinite(const Camera& c) {
    return std::isfinite(c.position.x) && std::isfinite(c.position.y) && std::isfinite(c.position.z) &&
           std::isfinite(c.orientation.w) && std::isfinite(c.orientation.x) && std::isfinite(c.orientation.y) &&
           std::isfinite(c.orientation.z);
}

// --- Projection ----------------------------------------------------------------

TEST(CameraReversedZ, NearMapsToOneInfinityToZero) {
    const double near = 0.1;
    const glm::dmat4 m = reversedZInfinitePerspective(glm::radians(60.0), 16.0 / 9.0, near);
    EXPECT_NEAR(ndcOf(m, {0.0, 0.0, -near}).z, 1.0, 1e-15);
    const glm::dvec4 atInfinity = m * glm::dvec4(0.0, 0.0, -1.0, 0.0);  // direction = point at infinity
    EXPECT_EQ(atInfinity.z / atInfinity.w, 0.0);
    EXPECT_NEAR(ndcOf(m, {0.0, 0.0, -1e12}).z, 0.0, 1e-12);
}

TEST(CameraReversedZ, DepthIsNearOverDistanceAndMatchesHelper) {
    const double near = 0.25;
    const glm::dmat4 m = reversedZInfinitePerspective(glm::radians(45.0), 1.5, near);
    for (double d : {0.25, 1.0, 3.7, 1e3, 6.36e6, 1e9}) {
        const glm::dvec3 p(0.3 * d, -0.2 * d, -d);
        EXPECT_NEAR(ndcOf(m, p).z, near / d, 1e-15 * near / d + 1e-300) << d;
        EXPECT_DOUBLE_EQ(ndcOf(m, p).z, depthFromViewZ(-d, near)) << d;
    }
}

TEST(CameraReversedZ, XYMapLikeStandardPerspective) {
    const double fovY = glm::radians(60.0), aspect = 2.0;
    const glm::dmat4 m = reversedZInfinitePerspective(fovY, aspect, 0.1);
    const double d = 7.0, halfH = d * std::tan(0.5 * fovY);
    EXPECT_NEAR(ndcOf(m, {0.0, halfH, -d}).y, 1.0, 1e-12);    // top edge
    EXPECT_NEAR(ndcOf(m, {0.0, -halfH, -d}).y, -1.0, 1e-12);  // bottom edge
    EXPECT_NEAR(ndcOf(m, {halfH * aspect, 0.0, -d}).x, 1.0, 1e-12);  // right edge
    EXPECT_NEAR(ndcOf(m, {0.0, 0.0, -d}).x, 0.0, 1e-15);
}

TEST(CameraReversedZ, CameraClipFromViewUsesItsFovAndNear) {
    Camera camera;
    camera.fovY_rad = glm::radians(30.0);
    camera.near_m = 0.5;
    const glm::dmat4 m = camera.clipFromView(1.0);
    EXPECT_NEAR(ndcOf(m, {0.0, 0.0, -0.5}).z, 1.0, 1e-15);
    EXPECT_NEAR(ndcOf(m, {0.0, 3.0 * std::tan(glm::radians(15.0)), -3.0}).y, 1.0, 1e-12);
}

// A 32-bit float depth buffer separates surfaces 0.001% apart from 0.1 m to 1e9 m.
TEST(CameraDepthPrecision, FloatSeparatesRelativeGapsEverywhere) {
    const double near = 0.1;
    int samples = 0;
    for (double logD = -1.0; logD <= 9.0 + 1e-9; logD += 0.01, ++samples) {
        const double d = std::pow(10.0, logD);
        const float front = static_cast<float>(depthFromViewZ(-d, near));
        const float back = static_cast<float>(depthFromViewZ(-d * (1.0 + 1e-5), near));
        ASSERT_GT(front, back) << "d = " << d;
    }
    EXPECT_GT(samples, 1000);
}

TEST(CameraDepthPrecision, RoundTrip) {
    for (double near : {0.1, 1.0}) {
        for (double z : {-0.1, -1.0, -2.5, -1e4, -6.36e6, -1e9}) {
            EXPECT_NEAR(viewZFromDepth(depthFromViewZ(z, near), near), z, 1e-14 * std::abs(z));
        }
    }
    EXPECT_DOUBLE_EQ(depthFromViewZ(-0.2, 0.1), 0.5);
}

// --- Camera-relative precision ------------------------------------------------

// Why rendering is camera-relative: at 6.36e6 m floats are spaced 0.5 m apart,
// so world positions in float are off by up to ~0.25 m per component and two
// points 1 cm apart either collapse or jump half a metre apart.
TEST(CameraRelative, DoubleSubtractionKeepsCentimetres) {
    double worstRelative = 0.0, worstNaivePosition = 0.0, bestNaiveGap = 1e30;
    for (int i = 0; i < 20; ++i) {
        const glm::dvec3 up = directionFromLatLon(-40.0 + 4.1 * i, 3.7 + 13.3 * i);
        const LocalFrame local = localFrameAt(up);
        Camera camera;
        camera.position = up * (kRadiusM + 2.0);
        const glm::dvec3 a = up * kRadiusM + local.east * 3.0 + local.north * 1.5;
        const glm::dvec3 b = a + local.east * 0.01;  // 1 cm further east

        const glm::vec3 gap = camera.relativePosition(b) - camera.relativePosition(a);
        worstRelative = std::max(worstRelative, glm::length(glm::dvec3(gap) - (b - a)));
        worstRelative = std::max(worstRelative, glm::length(glm::dvec3(camera.relativePosition(a)) - (a - camera.position)));

        // Naive: world positions in float on the GPU, subtracted there.
        const glm::vec3 camF(camera.position);
        const glm::vec3 naiveA = glm::vec3(a) - camF, naiveB = glm::vec3(b) - camF;
        worstNaivePosition = std::max(worstNaivePosition, glm::length(glm::dvec3(naiveA) - (a - camera.position)));
        bestNaiveGap = std::min(bestNaiveGap, glm::length(glm::dvec3(naiveB - naiveA) - (b - a)));
    }
    EXPECT_LT(worstRelative, 1e-4);
    EXPECT_GT(worstNaivePosition, 0.1);  // of the order of 0.25 m (half the float spacing)
    EXPECT_GT(bestNaiveGap, 0.005);      // the 1 cm gap is never resolved in float world space
}

TEST(CameraRelative, RotationOnlyViewMatchesDoubleView) {
    const Camera camera = cameraAtGeographic(12.0, 34.0, 2.0, 56.0, -10.0, 60.0, kRadiusM);
    const glm::dvec3 target = directionFromLatLon(12.0001, 34.0001) * kRadiusM;
    const glm::dvec3 expected = glm::transpose(camera.worldFromView()) * (target - camera.position);
    const glm::vec4 got = camera.viewFromWorldRotation() * glm::vec4(camera.relativePosition(target), 1.0f);
    EXPECT_NEAR(glm::length(glm::dvec3(got) - expected), 0.0, 1e-3);
    EXPECT_EQ(camera.viewFromWorldRotation()[3], glm::vec4(0, 0, 0, 1));  // no translation
}

// --- Geographic placement -------------------------------------------------------

TEST(CameraAtGeographic, PositionAtRadiusAndLatLon) {
    const Camera c = cameraAtGeographic(30.0, 45.0, 1000.0, 0.0, 0.0, 50.0, kRadiusM);
    EXPECT_NEAR(glm::length(c.position), kRadiusM + 1000.0, 1e-6);
    EXPECT_NEAR(c.altitude(kRadiusM), 1000.0, 1e-6);
    EXPECT_NEAR(glm::degrees(std::asin(c.position.z / glm::length(c.position))), 30.0, 1e-9);
    EXPECT_NEAR(glm::degrees(std::atan2(c.position.y, c.position.x)), 45.0, 1e-9);
    EXPECT_NEAR(c.fovY_rad, glm::radians(50.0), 1e-15);
}

TEST(CameraAtGeographic, HeadingAndPitch) {
    const Camera north = cameraAtGeographic(10.0, 20.0, 100.0, 0.0, 0.0, 60.0, kRadiusM);
    const LocalFrame local = localFrameAt(north.position);
    EXPECT_NEAR(glm::dot(north.forward(), local.north), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(north.right(), local.east), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(north.up(), local.up), 1.0, 1e-12);

    const Camera east = cameraAtGeographic(10.0, 20.0, 100.0, 90.0, 0.0, 60.0, kRadiusM);
    EXPECT_NEAR(glm::dot(east.forward(), local.east), 1.0, 1e-12);

    const Camera down = cameraAtGeographic(10.0, 20.0, 100.0, 33.0, -90.0, 60.0, kRadiusM);
    EXPECT_NEAR(glm::dot(down.forward(), -glm::normalize(down.position)), 1.0, 1e-12);

    const Camera up30 = cameraAtGeographic(10.0, 20.0, 100.0, 200.0, 30.0, 60.0, kRadiusM);
    EXPECT_NEAR(pitchDeg(up30), 30.0, 1e-9);
}

TEST(CameraAtGeographic, LevelAndOrthonormal) {
    for (double heading : {0.0, 45.0, 170.0, 300.0}) {
        for (double pitch : {-90.0, -45.0, 0.0, 60.0}) {
            const Camera c = cameraAtGeographic(-35.0, 150.0, 2.0, heading, pitch, 60.0, kRadiusM);
            EXPECT_NEAR(horizonTilt(c), 0.0, 1e-12) << heading << " " << pitch;
            EXPECT_NEAR(glm::length(c.orientation), 1.0, 1e-12);
            expectOrthonormal(c);
            EXPECT_NEAR(glm::length(glm::cross(c.right(), c.up()) + c.forward()), 0.0, 1e-12);
        }
    }
}

TEST(CameraLocalFrame, OrthonormalEverywhereIncludingPoles) {
    for (const glm::dvec3& p : {glm::dvec3(0, 0, kRadiusM), glm::dvec3(0, 0, -kRadiusM), glm::dvec3(0.0),
                                glm::dvec3(1e-9, 0, kRadiusM), directionFromLatLon(45, -120) * kRadiusM}) {
        const LocalFrame f = localFrameAt(p);
        for (const glm::dvec3& v : {f.east, f.north, f.up}) {
            ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
            EXPECT_NEAR(glm::length(v), 1.0, 1e-12);
        }
        EXPECT_NEAR(glm::dot(f.east, f.north), 0.0, 1e-12);
        EXPECT_NEAR(glm::dot(f.east, f.up), 0.0, 1e-12);
        EXPECT_NEAR(glm::dot(f.north, f.up), 0.0, 1e-12);
        EXPECT_NEAR(glm::dot(glm::cross(f.east, f.north), f.up), 1.0, 1e-12);  // right-handed ENU
    }
    const LocalFrame equator = localFrameAt({kRadiusM, 0.0, 0.0});
    EXPECT_NEAR(equator.east.y, 1.0, 1e-15);
    EXPECT_NEAR(equator.north.z, 1.0, 1e-15);
}

// --- Sanitising ------------------------------------------------------------------

TEST(CameraSanitize, InsidePlanetLiftedKeepingDirection) {
    Camera c;
    const glm::dvec3 dir = glm::normalize(glm::dvec3(1.0, 2.0, 3.0));
    c.position = dir * (kRadiusM - 500.0);
    EXPECT_FALSE(sanitizeCamera(c, kRadiusM).empty());
    EXPECT_NEAR(glm::length(c.position), kRadiusM + 0.1, 1e-6);
    EXPECT_NEAR(glm::dot(glm::normalize(c.position), dir), 1.0, 1e-15);
}

TEST(CameraSanitize, LightYearPulledBackTo1e9) {
    Camera c;
    const glm::dvec3 dir = glm::normalize(glm::dvec3(-3.0, 1.0, 0.5));
    c.position = dir * 9.46e15;
    EXPECT_FALSE(sanitizeCamera(c, kRadiusM).empty());
    EXPECT_NEAR(glm::length(c.position), 1e9, 1e-3);
    EXPECT_NEAR(glm::dot(glm::normalize(c.position), dir), 1.0, 1e-15);
}

TEST(CameraSanitize, NaNBecomesFiniteOrbitView) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Camera a, b, d;
    a.position.y = nan;
    b.orientation.x = std::numeric_limits<double>::infinity();
    d.fovY_rad = nan;
    d.near_m = -1.0;
    for (Camera* c : {&a, &b, &d}) {
        EXPECT_FALSE(sanitizeCamera(*c, kRadiusM).empty());
        EXPECT_TRUE(isFinite(*c));
        EXPECT_GT(c->altitude(kRadiusM), 0.0);
        EXPECT_TRUE(std::isfinite(c->fovY_rad) && c->fovY_rad > 0.0);
        EXPECT_GT(c->near_m, 0.0);
        expectOrthonormal(*c);
    }
    // The default orbit view looks at the planet centre.
    EXPECT_NEAR(glm::dot(a.forward(), -glm::normalize(a.position)), 1.0, 1e-12);
}

TEST(CameraSanitize, OrientationRenormalised) {
    Camera c = cameraAtGeographic(10.0, 10.0, 100.0, 0.0, 0.0, 60.0, kRadiusM);
    Camera drifted = c;
    drifted.orientation *= 1.0 + 1e-9;  // rounding drift: fixed silently
    EXPECT_EQ(sanitizeCamera(drifted, kRadiusM), "");
    EXPECT_NEAR(glm::length(drifted.orientation), 1.0, 1e-15);
    c.orientation *= 1.5;  // a real error: fixed and reported
    EXPECT_FALSE(sanitizeCamera(c, kRadiusM).empty());
    EXPECT_NEAR(glm::length(c.orientation), 1.0, 1e-15);
}

TEST(CameraSanitize, ValidCameraUnchanged) {
    Camera c = cameraAtGeographic(51.0, -1.0, 2.0, 270.0, 5.0, 70.0, kRadiusM);
    const Camera before = c;
    EXPECT_EQ(sanitizeCamera(c, kRadiusM), "");
    EXPECT_EQ(c.position, before.position);
    EXPECT_EQ(c.orientation, before.orientation);
    EXPECT_EQ(c.fovY_rad, before.fovY_rad);
    EXPECT_EQ(c.near_m, before.near_m);
}

// --- Controller: fly -----------------------------------------------------------------

double flyDistance(double altitudeM, double dt, ControlInput input = {}) {
    Camera c = cameraAtGeographic(0.0, 0.0, altitudeM, 0.0, 0.0, 60.0, kRadiusM);
    const glm::dvec3 start = c.position;
    CameraController controller;
    input.forward = true;
    controller.update(c, input, dt, kRadiusM);
    return glm::length(c.position - start);
}

TEST(CameraFly, SpeedProportionalToAltitude) {
    const double d1 = flyDistance(1000.0, 0.01), d2 = flyDistance(2000.0, 0.01);
    EXPECT_NEAR(d1, 1000.0 * 0.01, 1e-9);
    EXPECT_NEAR(d2 / d1, 2.0, 1e-9);
    EXPECT_NEAR(flyDistance(0.2, 0.1), 1.0 * 0.1, 1e-9);  // floor at 1 m/s near the ground
    ControlInput fast, slow;
    fast.fast = true;
    slow.slow = true;
    EXPECT_NEAR(flyDistance(1000.0, 0.01, fast) / d1, 5.0, 1e-9);
    EXPECT_NEAR(flyDistance(1000.0, 0.01, slow) / d1, 0.2, 1e-9);
}

TEST(CameraFly, DiagonalIsNotFaster) {
    ControlInput diagonal;
    diagonal.right = true;
    diagonal.up = true;
    EXPECT_NEAR(flyDistance(1000.0, 0.01, diagonal), flyDistance(1000.0, 0.01), 1e-9);
}

TEST(CameraFly, HugeDtClampedToQuarterSecond) {
    EXPECT_NEAR(flyDistance(1000.0, 1000.0), flyDistance(1000.0, 0.25), 1e-9);
    EXPECT_NEAR(flyDistance(1000.0, 0.25), 250.0, 1e-9);
    EXPECT_EQ(flyDistance(1000.0, -5.0), 0.0);
}

TEST(CameraFly, ScrollScalesSpeedWithinBounds) {
    CameraController controller;
    Camera c = cameraAtGeographic(0.0, 0.0, 100.0, 0.0, 0.0, 60.0, kRadiusM);
    ControlInput in;
    in.scroll = 1.0;
    controller.update(c, in, 0.0, kRadiusM);
    EXPECT_NEAR(controller.speedScale, 1.2, 1e-12);
    in.scroll = -2.0;
    controller.update(c, in, 0.0, kRadiusM);
    EXPECT_NEAR(controller.speedScale, 1.0 / 1.2, 1e-12);
    in.scroll = 1000.0;
    controller.update(c, in, 0.0, kRadiusM);
    EXPECT_EQ(controller.speedScale, 1e3);
    in.scroll = -1e5;
    controller.update(c, in, 0.0, kRadiusM);
    EXPECT_EQ(controller.speedScale, 1e-3);
}

TEST(CameraFly, YawKeepsHorizonLevelAndTurnsRight) {
    CameraController controller;
    Camera c = cameraAtGeographic(20.0, 10.0, 50.0, 0.0, -20.0, 60.0, kRadiusM);
    const LocalFrame local = localFrameAt(c.position);
    ControlInput in;
    in.lookDx = 100.0;  // 0.3 rad to the right
    controller.update(c, in, 0.016, kRadiusM);
    EXPECT_NEAR(horizonTilt(c), 0.0, 1e-12);
    expectOrthonormal(c);
    EXPECT_NEAR(pitchDeg(c), -20.0, 1e-9);  // yaw alone leaves the pitch
    const glm::dvec3 level = glm::normalize(c.forward() - glm::dot(c.forward(), local.up) * local.up);
    EXPECT_NEAR(std::atan2(glm::dot(level, local.east), glm::dot(level, local.north)), 0.3, 1e-9);
}

TEST(CameraFly, PitchClampedAt89_5Degrees) {
    CameraController controller;
    Camera c = cameraAtGeographic(-60.0, 100.0, 10.0, 45.0, 0.0, 60.0, kRadiusM);
    ControlInput in;
    in.lookDy = -1e4;  // mouse far up: look up
    controller.update(c, in, 0.016, kRadiusM);
    EXPECT_NEAR(pitchDeg(c), 89.5, 1e-9);
    EXPECT_NEAR(horizonTilt(c), 0.0, 1e-12);
    in.lookDy = 3e4;  // far down
    controller.update(c, in, 0.016, kRadiusM);
    EXPECT_NEAR(pitchDeg(c), -89.5, 1e-9);
    in.lookDy = 10.0;  // further down stays clamped
    controller.update(c, in, 0.016, kRadiusM);
    EXPECT_NEAR(pitchDeg(c), -89.5, 1e-9);
    expectOrthonormal(c);
}

TEST(CameraFly, RolledCameraIsLevelledOnUpdate) {
    CameraController controller;
    Camera c = cameraAtGeographic(0.0, 0.0, 100.0, 0.0, 0.0, 60.0, kRadiusM);
    c.orientation = glm::angleAxis(0.4, c.forward()) * c.orientation;  // roll 0.4 rad
    ASSERT_GT(horizonTilt(c), 0.1);
    const glm::dvec3 forwardBefore = c.forward();
    controller.update(c, {}, 0.016, kRadiusM);
    EXPECT_NEAR(horizonTilt(c), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(c.forward(), forwardBefore), 1.0, 1e-12);  // only the roll was removed
}

TEST(CameraFly, LongMoveAroundSphereKeepsHorizonLevel) {
    CameraController controller;
    Camera c = cameraAtGeographic(10.0, 0.0, 1e5, 30.0, -5.0, 60.0, kRadiusM);
    const glm::dvec3 start = c.position;
    ControlInput in;
    in.forward = true;
    in.right = true;  // strafing tilts the local up about the camera's forward axis: a roll to undo
    int steps = 0;
    for (; steps < 1000 && glm::length(c.position - start) < 1e6; ++steps) {
        controller.update(c, in, 0.25, kRadiusM);
        ASSERT_NEAR(horizonTilt(c), 0.0, 1e-9) << steps;
        ASSERT_NEAR(pitchDeg(c), -5.0, 1e-6) << steps;  // the view follows the curved horizon
    }
    EXPECT_GT(steps, 10);  // many small moves, each re-levelled
    EXPECT_GT(glm::length(c.position - start), 1e6);
    expectOrthonormal(c);
}

TEST(CameraFly, NeverEntersThePlanet) {
    CameraController controller;
    controller.speedScale = 1e3;
    Camera c = cameraAtGeographic(5.0, 5.0, 1e6, 0.0, -89.0, 60.0, kRadiusM);
    ControlInput in;
    in.forward = true;
    in.fast = true;
    in.down = true;
    const glm::dvec3 dir = glm::normalize(c.position);
    controller.update(c, in, 0.25, kRadiusM);  // a step far longer than the planet is wide
    EXPECT_NEAR(c.altitude(kRadiusM), 0.1, 1e-6);
    EXPECT_GT(glm::dot(glm::normalize(c.position), dir), 0.99);  // stopped at the near side, not through
    for (int i = 0; i < 10; ++i) controller.update(c, in, 0.25, kRadiusM);
    EXPECT_GE(c.altitude(kRadiusM), 0.1 - 1e-6);
}

TEST(CameraFly, NaNInputNeverProducesNaN) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CameraController controller;
    Camera c = cameraAtGeographic(0.0, 0.0, 10.0, 0.0, 0.0, 60.0, kRadiusM);
    ControlInput in;
    in.forward = true;
    in.lookDx = nan;
    in.lookDy = std::numeric_limits<double>::infinity();
    in.scroll = nan;
    controller.update(c, in, nan, kRadiusM);
    EXPECT_TRUE(isFinite(c));
    EXPECT_TRUE(std::isfinite(controller.speedScale));
    c.position.x = nan;
    controller.update(c, {}, 0.016, kRadiusM);
    EXPECT_TRUE(isFinite(c));
    EXPECT_FALSE(controller.lastCorrection.empty());  // the reset is reported
    controller.update(c, {}, 0.016, kRadiusM);
    EXPECT_EQ(controller.lastCorrection, "");
}

// --- Controller: orbit ---------------------------------------------------------------

TEST(CameraOrbit, DragKeepsDistanceAndCentreInView) {
    CameraController controller;
    controller.mode = CameraMode::Orbit;
    Camera c = cameraAtGeographic(30.0, 40.0, 2e6, 20.0, -50.0, 60.0, kRadiusM);
    const double distance = glm::length(c.position);
    const glm::dvec3 centreInView = glm::transpose(c.worldFromView()) * -c.position;
    const glm::dvec3 startPosition = c.position;
    ControlInput in;
    in.orbitDx = 120.0;
    in.orbitDy = -45.0;
    for (int i = 0; i < 5; ++i) controller.update(c, in, 0.016, kRadiusM);
    EXPECT_GT(glm::length(c.position - startPosition), 1e5);  // it did move
    EXPECT_NEAR(glm::length(c.position) / distance, 1.0, 1e-6);
    const glm::dvec3 centreInViewAfter = glm::transpose(c.worldFromView()) * -c.position;
    EXPECT_NEAR(glm::length(centreInViewAfter - centreInView) / distance, 0.0, 1e-9);
    expectOrthonormal(c);
}

TEST(CameraOrbit, DragRightTurnsThePlanetRight) {
    CameraController controller;
    controller.mode = CameraMode::Orbit;
    Camera c = cameraAtGeographic(0.0, 0.0, 2e7, 0.0, -90.0, 60.0, kRadiusM);
    const glm::dvec3 subCamera = glm::normalize(c.position) * kRadiusM;  // ground point under the camera
    ControlInput in;
    in.orbitDx = 50.0;
    controller.update(c, in, 0.016, kRadiusM);
    const glm::dvec3 inView = glm::transpose(c.worldFromView()) * (subCamera - c.position);
    EXPECT_GT(inView.x, 1e5);  // the point that was under the camera moved to the right of the view
    in.orbitDx = 0.0;
    in.orbitDy = 50.0;  // drag down
    const glm::dvec3 nowUnder = glm::normalize(c.position) * kRadiusM;
    controller.update(c, in, 0.016, kRadiusM);
    EXPECT_LT((glm::transpose(c.worldFromView()) * (nowUnder - c.position)).y, -1e5);
}

TEST(CameraOrbit, ScrollZoomsExponentiallyAndStopsAt1m) {
    CameraController controller;
    controller.mode = CameraMode::Orbit;
    Camera c = cameraAtGeographic(0.0, 0.0, 1000.0, 0.0, -30.0, 60.0, kRadiusM);
    const glm::dvec3 dir = glm::normalize(c.position);
    ControlInput in;
    in.scroll = 1.0;
    controller.update(c, in, 0.016, kRadiusM);
    EXPECT_NEAR(c.altitude(kRadiusM), 850.0, 1e-6);
    EXPECT_NEAR(glm::dot(glm::normalize(c.position), dir), 1.0, 1e-15);
    in.scroll = 200.0;
    controller.update(c, in, 0.016, kRadiusM);
    EXPECT_NEAR(c.altitude(kRadiusM), 1.0, 1e-6);
    in.scroll = 3.0;
    controller.update(c, in, 0.016, kRadiusM);
    EXPECT_GE(c.altitude(kRadiusM), 1.0 - 1e-6);
    in.scroll = -1e4;  // far out: capped at the supported range
    controller.update(c, in, 0.016, kRadiusM);
    EXPECT_NEAR(glm::length(c.position), 1e9, 1e-3);
    EXPECT_TRUE(isFinite(c));
}

TEST(CameraOrbit, HugeDtAndNaNAreHarmless) {
    CameraController controller;
    controller.mode = CameraMode::Orbit;
    Camera c = cameraAtGeographic(0.0, 0.0, 1e6, 0.0, -90.0, 60.0, kRadiusM);
    const Camera before = c;
    ControlInput in;
    in.forward = true;  // keys do nothing in orbit mode
    controller.update(c, in, 1e9, kRadiusM);
    EXPECT_EQ(c.position, before.position);
    in.orbitDx = std::numeric_limits<double>::quiet_NaN();
    in.scroll = std::numeric_limits<double>::infinity();
    controller.update(c, in, 0.016, kRadiusM);
    EXPECT_TRUE(isFinite(c));
}

}  // namespace
}  // namespace planet
