// Tests for the projected grid's CPU math (src/grid/projected_grid.h,
// Michelic §3 Eq. 1-4): worked values of Eq. 2 and Eq. 3, the coverage of
// everything a camera can see (by ray casting against the projected grid's
// actual boundary), the continuity of the grid frame through the pole of the
// reference vector, and the projection camera's hysteresis. CPU only.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "grid/projected_grid.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace planet {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadiusM = 6.36e6;
constexpr double kMaxHeightM = 10e3;  // above Everest: the peak sphere is 6370 km

double frobenius(const glm::dmat3& m) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) sum += glm::dot(m[c], m[c]);
    return std::sqrt(sum);
}

void expectRotation(const glm::dmat3& m, double tol) {
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(glm::length(m[i]), 1.0, tol);
        for (int j = i + 1; j < 3; ++j) EXPECT_NEAR(glm::dot(m[i], m[j]), 0.0, tol);
    }
    EXPECT_NEAR(glm::determinant(m), 1.0, tol);
}

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// --- Eq. 2 and the grid coordinates -----------------------------------------

TEST(ProjectedGrid, GridCoordinatesSpanMinusOneToOneSymmetrically) {
    EXPECT_EQ(gridCoordinate(0, 0, 5), glm::dvec2(-1.0, -1.0));
    EXPECT_EQ(gridCoordinate(4, 4, 5), glm::dvec2(1.0, 1.0));
    EXPECT_EQ(gridCoordinate(2, 1, 5), glm::dvec2(0.0, -0.5));
    EXPECT_EQ(gridCoordinate(3, 0, 5), glm::dvec2(0.5, -1.0));
    // Exactly antisymmetric for an even N too (so 90-degree turns map the vertex set onto itself).
    for (int i = 0; i < 100; ++i) EXPECT_EQ(gridCoordinate(i, 0, 100).x, -gridCoordinate(99 - i, 0, 100).x);
    EXPECT_EQ(gridCoordinate(99, 0, 100).x, 1.0);
}

TEST(ProjectedGrid, HemisphereDisplacementEq2WorkedValues) {
    // n = 4: (1 - gx^4)(1 - gy^4).
    EXPECT_DOUBLE_EQ(hemisphereHeight({0.0, 0.0}, 4), 1.0);            // centre
    EXPECT_DOUBLE_EQ(hemisphereHeight({1.0, 0.0}, 4), 0.0);            // edge midpoint
    EXPECT_DOUBLE_EQ(hemisphereHeight({0.3, -1.0}, 4), 0.0);           // anywhere on an edge
    EXPECT_DOUBLE_EQ(hemisphereHeight({-1.0, 1.0}, 4), 0.0);           // corner
    EXPECT_DOUBLE_EQ(hemisphereHeight({0.5, 0.0}, 4), 0.9375);         // 1 - 1/16
    EXPECT_DOUBLE_EQ(hemisphereHeight({-0.5, 0.5}, 4), 0.87890625);    // (15/16)^2
    // n = 2: (1 - gx^2)(1 - gy^2).
    EXPECT_DOUBLE_EQ(hemisphereHeight({0.0, 0.0}, 2), 1.0);
    EXPECT_DOUBLE_EQ(hemisphereHeight({1.0, 0.0}, 2), 0.0);
    EXPECT_DOUBLE_EQ(hemisphereHeight({1.0, -1.0}, 2), 0.0);
    EXPECT_DOUBLE_EQ(hemisphereHeight({0.5, 0.0}, 2), 0.75);
    EXPECT_DOUBLE_EQ(hemisphereHeight({0.5, -0.5}, 2), 0.5625);
    // Odd n uses |g|: symmetric.
    EXPECT_DOUBLE_EQ(hemisphereHeight({-0.5, 0.0}, 3), 0.875);
    // The shift z_s is added after (Eq. 3 applies to the pre-displaced grid).
    const glm::dvec3 p = predisplaced({0.5, 0.5}, 4, -0.25);
    EXPECT_DOUBLE_EQ(p.x, 0.5);
    EXPECT_DOUBLE_EQ(p.y, 0.5);
    EXPECT_DOUBLE_EQ(p.z, 0.87890625 - 0.25);
}

// --- Eq. 3 ---------------------------------------------------------------------

TEST(ProjectedGrid, ZShiftEq3MatchesHandWorkedTriangles) {
    // 3-4-5 triangles. r = 3, d = 5: h = sqrt(25 - 9) = 4. Peak sphere R = 5:
    // s = sqrt(25 - 9) = 4, |CP| = h + s = 8. Law of cosines in (O, C, P):
    // cos(phi) = (25 + 25 - 64) / (2 * 5 * 5) = -0.28; law of sines:
    // sin(phi) = 8 * 3 / (5 * 5) = 0.96 (0.28^2 + 0.96^2 = 1); phi = 2 acos(3/5)
    // = 106.26 deg (tangent point at acos(3/5) from both C and P).
    // z_s = cot(phi) = -0.28 / 0.96 = -7/24, and Eq. 3: (25 + 25 - 64) / (2 * 3 * 8) = -14/48.
    EXPECT_NEAR(zShift(5.0, 5.0, 4.0, 4.0, 3.0), -7.0 / 24.0, 1e-15);
    EXPECT_NEAR(horizonAngle(5.0, 3.0, 5.0), 2.0 * std::acos(0.6), 1e-15);
    EXPECT_NEAR(std::cos(horizonAngle(5.0, 3.0, 5.0)), -0.28, 1e-15);
    // No terrain (R = r = 3, s = 0): the edge sits on the horizon itself,
    // z_s = cot(acos(3/5)) = (3/5) / (4/5) = 0.75; Eq. 3: (9 + 25 - 16) / (2 * 3 * 4) = 18/24.
    EXPECT_NEAR(zShift(3.0, 5.0, 4.0, 0.0, 3.0), 0.75, 1e-15);
    // Earth-sized: r = 6360 km, R = 6370 km, camera 40 km up (d = 6400 km):
    // h = sqrt(40 * 12760) = 714.4228 km, s = sqrt(10 * 12730) = 356.7913 km,
    // phi = acos(6360/6400) + acos(6360/6370) = 0.1118617 + 0.0560405 = 0.1679022 rad,
    // z_s = cot(phi) = 5.89977.
    const double r = 6360e3, R = 6370e3, d = 6400e3;
    const double h = std::sqrt(d * d - r * r), s = std::sqrt(R * R - r * r);
    const double phi = std::acos(r / d) + std::acos(r / R);
    EXPECT_NEAR(zShift(R, d, h, s, r), 1.0 / std::tan(phi), 1e-12);
    EXPECT_NEAR(zShift(R, d, h, s, r), 5.89977, 1e-5);
    // With no roaming and a positive shift the grid uses Eq. 3 unchanged.
    EXPECT_NEAR(zShiftForCoverage(coverageAngle(d, r, R, 0.0)), zShift(R, d, h, s, r), 1e-12);
    // The edge midpoint (1, 0, 0 + z_s) lands exactly at phi from the axis.
    EXPECT_NEAR(std::atan2(1.0, zShift(R, d, h, s, r)), phi, 1e-14);
}

TEST(ProjectedGrid, Eq3CornersFallShortWhenShiftIsNegativeSoCornersAreMadeTight) {
    // Camera 1e9 m up: phi > 90 deg, Eq. 3 gives z_s < 0 and the boundary's
    // corners come nearer the centre than phi: Eq. 3 alone leaves the limb
    // uncovered at the corner azimuths. zShiftForCoverage puts the corners on phi.
    const double d = kRadiusM + 1e9, R = kRadiusM + kMaxHeightM;
    const double h = std::sqrt(d * d - kRadiusM * kRadiusM), s = std::sqrt(R * R - kRadiusM * kRadiusM);
    const double eq3 = zShift(R, d, h, s, kRadiusM);
    const double phi = horizonAngle(d, kRadiusM, R);
    ASSERT_LT(eq3, 0.0);
    EXPECT_NEAR(boundaryAngle(eq3, 0.0), phi, 1e-12);            // edge midpoint: on phi
    EXPECT_LT(boundaryAngle(eq3, kPi / 4), phi - 1e-3);          // corner: short by > 1 mrad
    const double fixed = zShiftForCoverage(phi);
    EXPECT_NEAR(boundaryAngle(fixed, kPi / 4), phi, 1e-12);       // corner: on phi
    for (int k = 0; k <= 360; ++k) EXPECT_GE(boundaryAngle(fixed, glm::radians(double(k))), phi - 1e-12);
    // Continuous through 90 degrees.
    EXPECT_NEAR(zShiftForCoverage(kPi / 2 - 1e-9), zShiftForCoverage(kPi / 2 + 1e-9), 1e-8);
}

TEST(ProjectedGrid, CoverageAngleWidensForTheRoamingCamera) {
    const double d = kRadiusM + 1000.0, R = kRadiusM + kMaxHeightM;
    EXPECT_DOUBLE_EQ(coverageAngle(d, kRadiusM, R, 0.0), horizonAngle(d, kRadiusM, R));
    const double roam = 50.0;
    EXPECT_NEAR(coverageAngle(d, kRadiusM, R, roam),
                horizonAngle(d + roam, kRadiusM, R) + std::asin(roam / d), 1e-15);
    EXPECT_GT(coverageAngle(d, kRadiusM, R, roam), horizonAngle(d, kRadiusM, R));
    EXPECT_LE(coverageAngle(10.0 * d, kRadiusM, 2.0 * kRadiusM, 1e9), kMaxCoverageAngleRad);
}

// --- Coverage by ray casting ----------------------------------------------------

// The projected grid's boundary, as a function of azimuth around the grid's
// centre direction c. Its edges are great-circle arcs (a grid edge is a line
// segment in grid space: g_z = 0 + z_s along it, and a segment not through the
// origin projects onto a great-circle arc; the tessellator's interpolated
// points lie on the same segment). Built from projectedGridVertices' output.
//
// Why "inside the boundary" means "covered": the grid is a continuous map of
// the square onto the sphere minus -c (the grid never reaches -c), and its
// boundary winds once around c (checked: the azimuth increases monotonically
// along the boundary loop). By the degree argument every direction the loop
// encloses is the image of some point of the square, folds or not.
class BoundaryByAzimuth {
public:
    BoundaryByAzimuth(const std::vector<glm::dvec3>& vertices, int N, const glm::dvec3& centre)
        : c_(glm::normalize(centre)) {
        const glm::dvec3 helper = std::abs(c_.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        e1_ = glm::normalize(glm::cross(helper, c_));
        e2_ = glm::cross(c_, e1_);
        std::vector<glm::dvec3> loop;
        for (int i = 0; i < N - 1; ++i) loop.push_back(vertices[static_cast<size_t>(i)]);                  // j = 0
        for (int j = 0; j < N - 1; ++j) loop.push_back(vertices[static_cast<size_t>(j * N + N - 1)]);      // i = N-1
        for (int i = N - 1; i > 0; --i) loop.push_back(vertices[static_cast<size_t>((N - 1) * N + i)]);    // j = N-1
        for (int j = N - 1; j > 0; --j) loop.push_back(vertices[static_cast<size_t>(j * N)]);              // i = 0
        if (wrap(azimuth(loop[1]) - azimuth(loop[0])) < 0.0) std::reverse(loop.begin(), loop.end());
        const size_t start = static_cast<size_t>(
            std::min_element(loop.begin(), loop.end(),
                             [&](const auto& a, const auto& b) { return azimuth(a) < azimuth(b); }) -
            loop.begin());
        std::rotate(loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(start), loop.end());
        points_ = loop;
        double previous = azimuth(loop[0]);
        azimuths_.push_back(previous);
        for (size_t k = 1; k < loop.size(); ++k) {
            const double step = wrap(azimuth(loop[k]) - azimuth(loop[k - 1]));
            if (!(step > 0.0)) monotonic_ = false;
            previous += step;
            azimuths_.push_back(previous);
        }
        const double closing = wrap(azimuths_.front() - azimuth(loop.back()));
        if (!(closing > 0.0) || std::abs(previous + closing - azimuths_.front() - 2.0 * kPi) > 1e-9) monotonic_ = false;
    }

    bool monotonic() const { return monotonic_; }

    // Angle of the boundary from c minus the angle of q from c, rad: >= 0 when covered.
    double margin(const glm::dvec3& q) const {
        const glm::dvec3 qn = glm::normalize(q);
        const double psiQ = angleBetween(c_, qn);
        const glm::dvec3 inPlane = qn - c_ * glm::dot(qn, c_);
        if (glm::length(inPlane) < 1e-14) return kPi;  // at the centre
        const glm::dvec3 t = glm::normalize(inPlane);
        const glm::dvec3 n = glm::cross(c_, t);  // normal of the great circle through c and q
        double a = azimuth(qn);
        while (a < azimuths_.front()) a += 2.0 * kPi;
        while (a >= azimuths_.front() + 2.0 * kPi) a -= 2.0 * kPi;
        const size_t k = static_cast<size_t>(std::upper_bound(azimuths_.begin(), azimuths_.end(), a) -
                                             azimuths_.begin()) - 1;
        const glm::dvec3& b0 = points_[k];
        const glm::dvec3& b1 = points_[(k + 1) % points_.size()];
        glm::dvec3 x = glm::normalize(glm::cross(glm::cross(b0, b1), n));
        if (glm::dot(x, t) < 0.0) x = -x;  // on q's half of the great circle
        const double psiB = std::atan2(glm::dot(x, t), glm::dot(x, c_));
        return psiB - psiQ;
    }

private:
    static double wrap(double a) { return std::remainder(a, 2.0 * kPi); }
    double azimuth(const glm::dvec3& p) const { return std::atan2(glm::dot(p, e2_), glm::dot(p, e1_)); }

    glm::dvec3 c_, e1_, e2_;
    std::vector<glm::dvec3> points_;
    std::vector<double> azimuths_;
    bool monotonic_ = true;
};

// Ray parameters where |o + t dir| = radius (dir unit), nearest first; computed
// from the closest-approach point so nothing cancels at 1e9 m.
std::optional<std::pair<double, double>> raySphere(const glm::dvec3& o, const glm::dvec3& dir, double radius) {
    const double tc = -glm::dot(o, dir);
    const glm::dvec3 closest = o + dir * tc;
    const double disc = radius * radius - glm::dot(closest, closest);
    if (disc < 0.0) return std::nullopt;
    const double half = std::sqrt(disc);
    return std::make_pair(tc - half, tc + half);
}

// The part of the ray where terrain between r and R may be hit first: from
// where it enters the peak sphere (or the camera, if inside) to the ground
// or to where it leaves the peak sphere. Empty when it misses the peak sphere.
std::optional<std::pair<double, double>> terrainSegment(const glm::dvec3& o, const glm::dvec3& dir, double r,
                                                        double R) {
    const auto peak = raySphere(o, dir, R);
    if (!peak || peak->second <= 0.0) return std::nullopt;
    const double t0 = std::max(peak->first, 0.0);
    double t1 = peak->second;
    if (const auto ground = raySphere(o, dir, r); ground && ground->first > 0.0) t1 = ground->first;
    return std::make_pair(t0, t1);
}

struct CoverageStats {
    int rays = 0;           // rays that reach the terrain shell
    double minMargin = kPi; // rad
};

// Casts rays over a square 90-degree frustum, a fan of rays grazing the ground
// all around (the farthest-reaching ones, whatever the view), and (for far
// cameras, where the planet is a small disc) a dense fan over the planet's
// disc within the frustum, and checks K+1
// points along each ray's terrain segment against the grid boundary.
void checkCoverage(const Camera& camera, const BoundaryByAzimuth& boundary, double r, double R,
                   CoverageStats& stats) {
    const glm::dmat3 worldFromView = camera.worldFromView();
    auto castRay = [&](const glm::dvec3& dir) {
        const auto segment = terrainSegment(camera.position, dir, r, R);
        if (!segment) return;
        ++stats.rays;
        constexpr int K = 8;
        for (int k = 0; k <= K; ++k) {
            const double t = segment->first + (segment->second - segment->first) * double(k) / K;
            stats.minMargin = std::min(stats.minMargin, boundary.margin(camera.position + dir * t));
        }
    };
    constexpr int kFrustum = 61;
    for (int y = 0; y < kFrustum; ++y) {
        for (int x = 0; x < kFrustum; ++x) {
            const glm::dvec3 view(-1.0 + 2.0 * x / (kFrustum - 1), -1.0 + 2.0 * y / (kFrustum - 1), -1.0);
            castRay(glm::normalize(worldFromView * view));
        }
    }
    // The critical rays: just below and just above the tangent to the ground
    // sphere, all around; they reach the horizon (angle acos(r/d) from the
    // camera) and leave the peak sphere at horizonAngle, the farthest possible.
    const double dCam = glm::length(camera.position);
    {
        const glm::dvec3 down = -camera.position / dCam;
        const glm::dvec3 helper = std::abs(down.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec3 a1 = glm::normalize(glm::cross(helper, down)), a2 = glm::cross(down, a1);
        const double tangent = std::asin(std::min(1.0, r / dCam));
        constexpr int kFan = 1440;
        for (double beta : {tangent - 1e-9, tangent + 1e-9}) {  // hits the ground at the horizon; grazes past it
            for (int k = 0; k < kFan; ++k) {
                const double az = 2.0 * kPi * k / kFan;
                castRay(glm::normalize(down * std::cos(beta) +
                                       (a1 * std::cos(az) + a2 * std::sin(az)) * std::sin(beta)));
            }
        }
    }
    // The planet's disc: directions within asin(R/d) of the nadir (slightly
    // more), kept when inside the frustum (|x|, |y| <= |z| in view space).
    const glm::dvec3 nadir = -camera.position / dCam;
    const double discRadius = std::asin(std::min(1.0, R / dCam)) * 1.02;
    const glm::dvec3 helper = std::abs(nadir.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 a1 = glm::normalize(glm::cross(helper, nadir)), a2 = glm::cross(nadir, a1);
    const double extent = std::tan(std::min(discRadius, 1.4));
    constexpr int kDisc = 97;
    for (int y = 0; y < kDisc; ++y) {
        for (int x = 0; x < kDisc; ++x) {
            const double u = extent * (-1.0 + 2.0 * x / (kDisc - 1)), v = extent * (-1.0 + 2.0 * y / (kDisc - 1));
            const glm::dvec3 dir = glm::normalize(nadir + a1 * u + a2 * v);
            const glm::dvec3 view = glm::transpose(worldFromView) * dir;
            if (view.z >= 0.0 || std::abs(view.x) > -view.z || std::abs(view.y) > -view.z) continue;
            castRay(dir);
        }
    }
}

struct ViewCase {
    const char* name;
    double headingDeg, pitchDeg;
};

TEST(ProjectedGrid, CoversEverythingTheCameraCanSeeFromTwoMetresToAMillionKilometres) {
    const double altitudes[] = {2.0, 1e3, 1e5, 1e7, 1e9};
    const ViewCase views[] = {{"down", 0.0, -90.0}, {"horizon", 30.0, 0.0}, {"up45", 200.0, 45.0},
                              {"oblique", 60.0, -30.0}};
    const double maxHeights[] = {kMaxHeightM, 0.0};  // terrain; ocean at sea level
    GridParams params;
    for (double maxHeight : maxHeights) {
        const double R = kRadiusM + maxHeight;
        for (int exponent : {4, 2}) {
            params.exponent = exponent;
            for (double altitude : altitudes) {
                double worstMargin = kPi;
                int rays = 0;
                for (const ViewCase& view : views) {
                    const Camera anchorCamera =
                        cameraAtGeographic(40.0, 10.0, altitude, view.headingDeg, view.pitchDeg, 90.0, kRadiusM);
                    GridAnchor anchor;
                    const double threshold = anchorThresholdM(params, altitude);
                    ASSERT_TRUE(updateAnchor(anchor, anchorCamera, threshold, false));
                    const std::vector<glm::dvec3> vertices = projectedGridVertices(params, anchor, kRadiusM, maxHeight);
                    const BoundaryByAzimuth boundary(vertices, params.size, anchor.position);
                    ASSERT_TRUE(boundary.monotonic()) << altitude << " m " << view.name;
                    // The real camera at the anchor, and displaced by just under
                    // the threshold (outwards; towards its view; sideways): the
                    // anchor does not move for any of them.
                    const LocalFrame local = localFrameAt(anchorCamera.position);
                    const glm::dvec3 offsets[] = {glm::dvec3(0.0), local.up, anchorCamera.forward(),
                                                  anchorCamera.right()};
                    for (const glm::dvec3& offset : offsets) {
                        Camera camera = anchorCamera;
                        camera.position += offset * (0.999 * threshold);
                        GridAnchor copy = anchor;
                        ASSERT_FALSE(updateAnchor(copy, camera, threshold, false));
                        CoverageStats stats;
                        checkCoverage(camera, boundary, kRadiusM, R, stats);
                        EXPECT_GE(stats.minMargin, -1e-9)
                            << "uncovered terrain: altitude " << altitude << " m, view " << view.name
                            << ", max height " << maxHeight << " m, n = " << exponent;
                        worstMargin = std::min(worstMargin, stats.minMargin);
                        rays += stats.rays;
                    }
                }
                std::printf("coverage: max height %6.0f m, n %d, altitude %8.0e m: %6d rays, min margin %.3e rad\n",
                            maxHeight, exponent, altitude, rays, worstMargin);
                EXPECT_GT(rays, 0);
            }
        }
    }
}

TEST(ProjectedGrid, CoverageCheckCatchesGridsThatFallShort) {
    // The same check fails (negative margin) for a grid built as if the
    // camera could not roam (paper's Eq. 3 for the anchor alone) when the real
    // camera sits just inside the threshold, outwards: it then sees past the
    // grid's edge. Shows the coverage test can fail, and why coverageAngle widens.
    GridParams params;
    for (double altitude : {1e3, 1e9}) {
        const Camera anchorCamera = cameraAtGeographic(40.0, 10.0, altitude, 0.0, 0.0, 90.0, kRadiusM);
        GridAnchor anchor;
        const double threshold = anchorThresholdM(params, altitude);
        updateAnchor(anchor, anchorCamera, threshold, false);
        GridAnchor fixedAnchor = anchor;
        fixedAnchor.roamRadiusM = 0.0;
        const std::vector<glm::dvec3> vertices = projectedGridVertices(params, fixedAnchor, kRadiusM, kMaxHeightM);
        const BoundaryByAzimuth boundary(vertices, params.size, anchor.position);
        Camera camera = anchorCamera;
        camera.position += localFrameAt(camera.position).up * (0.999 * threshold);
        CoverageStats stats;
        checkCoverage(camera, boundary, kRadiusM, kRadiusM + kMaxHeightM, stats);
        EXPECT_LT(stats.minMargin, -1e-5) << altitude;
        std::printf("unwidened grid, camera %.0f m outwards at %.0e m: min margin %.3e rad\n", 0.999 * threshold,
                    altitude, stats.minMargin);
    }
}

TEST(ProjectedGrid, StaysOnTheCameraSideAndNeverFolds) {
    // Every vertex is within the boundary's farthest angle of the anchor
    // direction (the corners for z_s >= 0, the edge midpoints for z_s < 0),
    // which stays below 180 deg: nothing wraps to the far side. Every grid
    // triangle inside the covered cap faces outwards (positive orientation
    // against the outward normal): no fold-back there (paper figure 3d).
    GridParams params;
    for (int exponent : {4, 2}) {
        params.exponent = exponent;
        for (double altitude : {2.0, 1e3, 1e5, 1e7, 1e9}) {
            const glm::dvec3 position = directionFromLatLon(-20.0, 130.0) * (kRadiusM + altitude);
            GridAnchor anchor;
            Camera camera;
            camera.position = position;
            updateAnchor(anchor, camera, anchorThresholdM(params, altitude), false);
            const GridProjection projection = gridProjection(anchor, kRadiusM, kMaxHeightM);
            const std::vector<glm::dvec3> v = projectedGridVertices(params, anchor, kRadiusM, kMaxHeightM);
            const double farthest = std::max(boundaryAngle(projection.zShift, 0.0), boundaryAngle(projection.zShift, kPi / 4));
            ASSERT_LT(farthest, kPi);
            const glm::dvec3 c = glm::normalize(position);
            double maxAngle = 0.0;
            for (const glm::dvec3& p : v) {
                EXPECT_NEAR(glm::length(p), kRadiusM, 1e-8 * kRadiusM);
                maxAngle = std::max(maxAngle, angleBetween(c, p));
            }
            EXPECT_LE(maxAngle, farthest + 1e-12) << altitude;
            const int N = params.size;
            int backFacing = 0;
            double nearestBackFacing = kPi;  // rad from c, over the vertices of back-facing triangles
            auto checkTriangle = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& e) {
                if (glm::dot(glm::cross(b - a, e - a), a + b + e) > 0.0) return;
                ++backFacing;
                for (const glm::dvec3* p : {&a, &b, &e}) nearestBackFacing = std::min(nearestBackFacing, angleBetween(c, *p));
            };
            for (int j = 0; j + 1 < N; ++j) {
                for (int i = 0; i + 1 < N; ++i) {
                    const glm::dvec3& p00 = v[static_cast<size_t>(j * N + i)];
                    const glm::dvec3& p10 = v[static_cast<size_t>(j * N + i + 1)];
                    const glm::dvec3& p01 = v[static_cast<size_t>((j + 1) * N + i)];
                    const glm::dvec3& p11 = v[static_cast<size_t>((j + 1) * N + i + 1)];
                    checkTriangle(p00, p10, p11);
                    checkTriangle(p00, p11, p01);
                }
            }
            // For z_s < 0, Eq. 2's zero gradient along the diagonals at the
            // corners makes the last cells there fold back beyond the corner
            // (n = 2 more than n = 4, as the paper notes). Harmless if they stay
            // outside the covered cap, which no roaming camera can see: all their
            // vertices at >= the cap's angle (> 90 deg here, so the cap's
            // complement is convex and holds the whole triangles). The corner
            // vertex itself sits exactly on the cap, hence the 1e-12.
            if (projection.zShift >= 0.0) {
                EXPECT_EQ(backFacing, 0) << "altitude " << altitude << " m, n = " << exponent;
            } else {
                ASSERT_GT(projection.coverageAngle_rad, kPi / 2);
                EXPECT_GE(nearestBackFacing, projection.coverageAngle_rad - 1e-12)
                    << "altitude " << altitude << " m, n = " << exponent << ", z_s = " << projection.zShift;
            }
            std::printf("folds: n %d, altitude %8.0e m: %d back-facing triangles, nearest at %.4f deg\n", exponent,
                        altitude, backFacing, glm::degrees(nearestBackFacing));
            std::printf("extent: n %d, altitude %8.0e m: z_s %+.5f, covered cap %.4f deg, farthest vertex %.4f deg\n",
                        exponent, altitude, projection.zShift, glm::degrees(projection.coverageAngle_rad),
                        glm::degrees(maxAngle));
        }
    }
}

TEST(ProjectedGrid, VerticesAreEq1OfTheRotatedShiftedGrid) {
    GridParams params;
    params.size = 9;
    const glm::dvec3 position = directionFromLatLon(10.0, -50.0) * (kRadiusM + 2e5);
    const std::vector<glm::dvec3> v = projectedGridVertices(params, position, kRadiusM, kMaxHeightM);
    ASSERT_EQ(v.size(), 81u);
    // The centre vertex (odd N) is straight below the anchor.
    EXPECT_LT(angleBetween(v[40], position), 1e-15);
    // A vertex by hand: Eq. 2, shift, Eq. 4, Eq. 1.
    const double phi = horizonAngle(glm::length(position), kRadiusM, kRadiusM + kMaxHeightM);
    const double z_s = 1.0 / std::tan(phi);
    const glm::dmat3 worldFromGrid = gridRotation(position);
    // i = 6, j = 1: g = (0.5, -0.75), |g|_inf = 0.75, moved to g (a + (1 - a) m (2 - m)).
    const double scale = kGridCentreDensity + (1.0 - kGridCentreDensity) * 0.75 * 1.25;
    const glm::dvec2 w = glm::dvec2(0.5, -0.75) * scale;
    const glm::dvec3 g(w.x, w.y, (1.0 - std::pow(w.x, 4)) * (1.0 - std::pow(w.y, 4)) + z_s);
    const glm::dvec3 expected = glm::normalize(worldFromGrid * g) * kRadiusM;
    EXPECT_LT(glm::length(v[1 * 9 + 6] - expected), 1e-6);
    // Edge midpoint i = 8, j = 4 sits at exactly phi from the anchor.
    EXPECT_NEAR(angleBetween(v[4 * 9 + 8], position), phi, 1e-12);
}

// --- Rotation (Eq. 4) and its transport -------------------------------------------

TEST(ProjectedGrid, GridRotationIsEq4WithAProperRotation) {
    const glm::dvec3 w = glm::normalize(glm::dvec3(1.0, 2.0, 0.5));
    const glm::dmat3 m = gridRotation(w * 7e6);
    expectRotation(m, 1e-14);
    EXPECT_LT(glm::length(m[2] - w), 1e-15);                                          // grid z -> camera
    EXPECT_LT(glm::length(m[1] - glm::normalize(glm::cross(w, glm::dvec3(0, 0, 1)))), 1e-15);  // v = w x b
    // At (and next to) the pole of b the fallback still gives a rotation with z -> w.
    for (const glm::dvec3& p : {glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -3), glm::dvec3(1e-9, 0, 1)}) {
        const glm::dmat3 pole = gridRotation(p);
        expectRotation(pole, 1e-14);
        EXPECT_LT(glm::length(pole[2] - glm::normalize(p)), 1e-15);
    }
}

TEST(ProjectedGrid, RotationIsContinuousAlongPathsThroughAndAroundThePole) {
    // Paths (directions, 0.5 mrad per step): a meridian through the north
    // pole (the pole of b = +Z); a small circle 0.01 deg around it; a tiny
    // circle of 1e-7 rad; a meridian through the south pole. The anchor is
    // updated at every step (threshold 0). Minimal-rotation transport changes
    // the frame by a rotation of the step angle delta, whose Frobenius norm is
    // 2 sqrt(2) sin(delta / 2) <= sqrt(2) delta: bound it at 1.0001 sqrt(2) delta.
    // Eq. 4 evaluated afresh at each position flips by ~2.8 (Frobenius of a
    // 180 deg turn about w) when crossing the pole: shown as the contrast.
    std::vector<glm::dvec3> path;
    const double step = 5e-4;
    for (double colat = -0.2; colat <= 0.2; colat += step)  // through +Z, lon 30 deg
        path.push_back({std::sin(colat) * std::cos(0.5236), std::sin(colat) * std::sin(0.5236), std::cos(colat)});
    for (double colatitude : {glm::radians(0.01), 1e-7}) {
        const int steps = std::max(16, int(2.0 * kPi * colatitude / step) + 1);
        for (int k = 0; k <= steps; ++k) {
            const double lon = 2.0 * kPi * k / steps;
            path.push_back({std::sin(colatitude) * std::cos(lon), std::sin(colatitude) * std::sin(lon),
                            std::cos(colatitude)});
        }
    }
    for (double colat = -0.2; colat <= 0.2; colat += step)  // through -Z
        path.push_back({std::sin(colat), 0.0, -std::cos(colat)});

    GridAnchor anchor;
    double worstRatio = 0.0, eq4Jump = 0.0;
    glm::dmat3 previous(1.0), previousEq4(1.0);
    glm::dvec3 previousDir(0.0);
    int jumps = 0;
    for (size_t k = 0; k < path.size(); ++k) {
        Camera camera;
        camera.position = path[k] * (kRadiusM + 1e5);
        const bool first = !anchor.valid;
        const glm::dmat3 eq4 = gridRotation(camera.position);
        if (!first && angleBetween(previousDir, path[k]) > 10.0 * step) {
            // The path jumped between its pieces: transport across the jump, no check.
            ++jumps;
        }
        updateAnchor(anchor, camera, 0.0, false);
        const glm::dmat3& m = anchor.worldFromGrid;
        EXPECT_LT(glm::length(m[2] - glm::normalize(path[k])), 1e-14);
        if (!first) {
            const double delta = angleBetween(previousDir, path[k]);
            if (delta <= 10.0 * step && delta > 0.0) {
                const double change = frobenius(m - previous);
                EXPECT_LE(change, 1.0001 * std::sqrt(2.0) * delta + 1e-13) << "step " << k;
                worstRatio = std::max(worstRatio, change / (std::sqrt(2.0) * delta));
                eq4Jump = std::max(eq4Jump, frobenius(eq4 - previousEq4));
            }
        }
        previous = m;
        previousEq4 = eq4;
        previousDir = path[k];
    }
    expectRotation(anchor.worldFromGrid, 1e-13);  // no drift after ~2000 transports
    EXPECT_EQ(jumps, 2);  // meridian -> small circle, tiny circle -> south meridian
    EXPECT_LE(worstRatio, 1.0001);
    EXPECT_GT(eq4Jump, 1.0);  // the stateless Eq. 4 frame does flip at the pole
    std::printf("rotation: transported change / (sqrt2 * step) <= %.6f; stateless Eq. 4 max step change %.3f\n",
                worstRatio, eq4Jump);
}

TEST(ProjectedGrid, TransportIsTheMinimalRotation) {
    const glm::dmat3 start = gridRotation(glm::dvec3(1.0, 0.2, 0.3));
    const glm::dvec3 to = glm::normalize(glm::dvec3(0.2, 1.0, -0.4));
    const glm::dmat3 moved = transportGridRotation(start, to);
    expectRotation(moved, 1e-14);
    EXPECT_LT(glm::length(moved[2] - to), 1e-15);
    // The axis a x b is left fixed by the minimal rotation.
    const glm::dvec3 axis = glm::normalize(glm::cross(start[2], to));
    const glm::dmat3 delta = moved * glm::transpose(start);
    EXPECT_LT(glm::length(delta * axis - axis), 1e-14);
    // Antipodal: restarts from Eq. 4 instead of dividing by zero.
    const glm::dmat3 flipped = transportGridRotation(start, -start[2]);
    expectRotation(flipped, 1e-14);
    EXPECT_LT(glm::length(flipped[2] + start[2]), 1e-15);
}

// --- Hysteresis -------------------------------------------------------------------------

TEST(ProjectedGrid, AnchorMovesOnlyPastTheThresholdOrWhenForced) {
    GridParams params;
    const double altitude = 1000.0;
    const double threshold = anchorThresholdM(params, altitude);
    EXPECT_DOUBLE_EQ(threshold, 50.0);                                  // 5% of 1 km
    EXPECT_DOUBLE_EQ(anchorThresholdM(params, 0.5), params.hysteresisMinM);  // floor near the ground

    Camera camera = cameraAtGeographic(12.0, 34.0, altitude, 0.0, -10.0, 60.0, kRadiusM);
    const glm::dvec3 start = camera.position;
    const glm::dvec3 east = localFrameAt(start).east;
    GridAnchor anchor;
    EXPECT_TRUE(updateAnchor(anchor, camera, threshold, false));        // first call initialises
    EXPECT_EQ(anchor.position, start);
    EXPECT_DOUBLE_EQ(anchor.roamRadiusM, threshold);

    camera.position = start + east * 30.0;
    EXPECT_FALSE(updateAnchor(anchor, camera, threshold, false));
    camera.position = start + east * 49.9;
    EXPECT_FALSE(updateAnchor(anchor, camera, threshold, false));
    camera.orientation = glm::angleAxis(1.0, glm::dvec3(0, 0, 1)) * camera.orientation;  // turning never moves it
    EXPECT_FALSE(updateAnchor(anchor, camera, threshold, false));
    EXPECT_EQ(anchor.position, start);

    camera.position = start + east * 50.1;
    EXPECT_TRUE(updateAnchor(anchor, camera, threshold, false));
    EXPECT_EQ(anchor.position, camera.position);
    expectRotation(anchor.worldFromGrid, 1e-14);
    EXPECT_LT(glm::length(anchor.worldFromGrid[2] - glm::normalize(camera.position)), 1e-15);

    // Forced (terrain out of view): any move updates; no move does not.
    const glm::dvec3 here = camera.position;
    camera.position = here + east * 1.0;
    EXPECT_TRUE(updateAnchor(anchor, camera, threshold, true));
    EXPECT_EQ(anchor.position, camera.position);
    EXPECT_FALSE(updateAnchor(anchor, camera, threshold, true));

    // A threshold larger than the one the grid was built for does not let the
    // camera roam beyond the grid's coverage.
    camera.position = anchor.position + east * 60.0;
    EXPECT_TRUE(updateAnchor(anchor, camera, 1000.0, false));
    EXPECT_DOUBLE_EQ(anchor.roamRadiusM, 1000.0);
}

TEST(ProjectedGrid, ParamsValidation) {
    EXPECT_EQ(validateGridParams(GridParams{}), "");
    GridParams p;
    p.size = 7;
    EXPECT_NE(validateGridParams(p), "");
    p = {};
    p.size = 1025;
    EXPECT_NE(validateGridParams(p), "");
    p = {};
    p.exponent = 0;
    EXPECT_NE(validateGridParams(p), "");
    p = {};
    p.hysteresisFraction = -0.1;
    EXPECT_NE(validateGridParams(p), "");
}

}  // namespace

TEST(ProjectedGrid, VerticesCrowdTowardsTheCentreAndKeepTheBoundary) {
    const int N = 101;
    // The boundary stays put (coverage is the boundary's projection), with its spacing.
    for (int i = 0; i < N; ++i) {
        EXPECT_EQ(gridVertexCoordinate(i, 0, N), gridCoordinate(i, 0, N));
        EXPECT_EQ(gridVertexCoordinate(N - 1, i, N), gridCoordinate(N - 1, i, N));
    }
    // Along a row through the centre: symmetric, strictly increasing, spacing growing from
    // a of it to at most 1.32 times the even spacing, and the even spacing at the edge.
    const double even = 2.0 / (N - 1);
    double first = 0.0, largest = 0.0;
    for (int i = 0; i + 1 < N; ++i) {
        const double x0 = gridVertexCoordinate(i, N / 2, N).x, x1 = gridVertexCoordinate(i + 1, N / 2, N).x;
        ASSERT_GT(x1, x0);
        EXPECT_EQ(x0, -gridVertexCoordinate(N - 1 - i, N / 2, N).x);
        if (i == N / 2) first = (x1 - x0) / even;
        largest = std::max(largest, (x1 - x0) / even);
    }
    const double last = (gridVertexCoordinate(N - 1, N / 2, N).x - gridVertexCoordinate(N - 2, N / 2, N).x) / even;
    EXPECT_LT(first, 0.1);  // next to the projection camera: 20 times denser than even
    EXPECT_LT(largest, 1.34);
    EXPECT_NEAR(last, 1.0, 0.02);
}

// angleOutsideVertexBox bounds from below how near the grid's centre (as an angle from grid z)
// anything outside a box of vertices comes, the patches' bilinear interiors included (the
// terrain's ground detail takes its program only on the patches inside: src/terrain/
// terrain_pass.cpp), and the bound is met where the nearest side crosses an axis. Checked
// against every vertex outside and 9 x 9 points of every patch outside, over grid sizes, both
// exponents, shifts from a 2 m camera's (~20) to far ones (negative), and boxes round the centre.
TEST(ProjectedGrid, AngleOutsideAVertexBoxIsALowerBoundMetOnTheAxis) {
    const auto angleAt = [](glm::dvec2 g, int n, double zs) {
        const glm::dvec3 p = predisplaced(g, n, zs);
        return std::atan2(std::hypot(p.x, p.y), p.z);
    };
    int checked = 0;
    for (const int N : {100, 33, 64}) {
        const int centre = (N - 1) / 2;
        for (const int n : {4, 2})
            for (const double zs : {20.0, 1.0, 0.05, -0.2})
                for (const glm::ivec4 box : {glm::ivec4(centre - 3, centre - 3, centre + 4, centre + 4),
                                             glm::ivec4(centre - 10, centre - 2, centre + 15, centre + 8),
                                             glm::ivec4(0, centre - 5, N - 1, centre + 12),
                                             glm::ivec4(1, 1, N - 2, N - 2)}) {
                    const glm::ivec2 low(box.x, box.y), high(box.z, box.w);
                    const double bound = angleOutsideVertexBox(low, high, N, n, zs);
                    double nearest = kPi;
                    for (int j = 0; j + 1 < N; ++j)
                        for (int i = 0; i + 1 < N; ++i) {
                            const bool inside = i >= low.x && i + 1 <= high.x && j >= low.y && j + 1 <= high.y;
                            if (inside) continue;
                            const glm::dvec2 c00 = gridVertexCoordinate(i, j, N), c10 = gridVertexCoordinate(i + 1, j, N);
                            const glm::dvec2 c01 = gridVertexCoordinate(i, j + 1, N), c11 = gridVertexCoordinate(i + 1, j + 1, N);
                            for (int b = 0; b <= 8; ++b)
                                for (int a = 0; a <= 8; ++a) {
                                    const double u = a / 8.0, v = b / 8.0;
                                    const glm::dvec2 g = glm::mix(glm::mix(c00, c10, u), glm::mix(c01, c11, u), v);
                                    nearest = std::min(nearest, angleAt(g, n, zs));
                                }
                        }
                    ASSERT_GE(nearest, bound - 1e-12) << "N " << N << " n " << n << " z_s " << zs << " box " << box.x;
                    // Met on the axis (sampled at eighths of a patch: within 2 % of the bound)
                    // where the projection is one-to-one (the angle under 90 degrees).
                    if (bound < 0.5 * kPi) {
                        EXPECT_LE(nearest, bound * 1.02 + 1e-9) << "N " << N << " z_s " << zs;
                    }
                    ++checked;
                }
    }
    EXPECT_EQ(checked, 3 * 2 * 4 * 4);
    // The whole grid leaves nothing outside; a box round the centre leaves a positive angle.
    EXPECT_EQ(angleOutsideVertexBox({0, 0}, {99, 99}, 100, 4, 20.0), kPi);
    EXPECT_GT(angleOutsideVertexBox({48, 48}, {56, 56}, 100, 4, 20.0), 0.0);
}

}  // namespace planet
