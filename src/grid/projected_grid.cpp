// Projected grid, CPU side: see projected_grid.h for the steps and for where
// and why this departs from Michelic §3.
#include "grid/projected_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace planet {

namespace {

constexpr double kPi = std::numbers::pi;

double clampUnit(double x) { return std::clamp(x, -1.0, 1.0); }

// Axis of the world frame least aligned with w (for the Eq. 4 fallback).
glm::dvec3 leastAlignedAxis(const glm::dvec3& w) {
    const glm::dvec3 a = glm::abs(w);
    if (a.x <= a.y && a.x <= a.z) return {1.0, 0.0, 0.0};
    if (a.y <= a.z) return {0.0, 1.0, 0.0};
    return {0.0, 0.0, 1.0};
}

// Columns (x, y = z cross x, z) with z exactly unit and x made orthogonal to it.
glm::dmat3 orthonormalised(const glm::dvec3& xApprox, const glm::dvec3& z) {
    const glm::dvec3 x = glm::normalize(xApprox - z * glm::dot(xApprox, z));
    return glm::dmat3(x, glm::cross(z, x), z);
}

}  // namespace

std::string validateGridParams(const GridParams& params) {
    if (params.size < 8 || params.size > 1024) return "grid size must be in [8, 1024]";
    if (params.exponent < 1 || params.exponent > 8) return "grid exponent must be in [1, 8] (the paper uses 4 or 2)";
    if (!(params.hysteresisFraction >= 0.0 && params.hysteresisFraction <= 1.0))
        return "grid hysteresis fraction must be in [0, 1]";
    if (!(params.hysteresisMinM >= 0.0 && params.hysteresisMinM <= 1e6))
        return "grid hysteresis minimum must be in [0, 1e6] m";
    return "";
}

double anchorThresholdM(const GridParams& params, double anchorAltitudeM) {
    return std::max(params.hysteresisMinM, params.hysteresisFraction * std::max(anchorAltitudeM, 0.0));
}

glm::dvec2 gridCoordinate(int i, int j, int N) {
    // Written as (2i - (N-1)) / (N-1) so that i and N-1-i give exactly opposite values.
    const double scale = 1.0 / static_cast<double>(N - 1);
    return {static_cast<double>(2 * i - (N - 1)) * scale, static_cast<double>(2 * j - (N - 1)) * scale};
}

namespace {

// f(m) / m = a + 2 (1 - a) m - (1 - a) m^2 of gridVertexCoordinate (no division at the centre).
double centreWarpScale(double m) {
    const double a = kGridCentreDensity;
    return a + (1.0 - a) * m * (2.0 - m);
}

}  // namespace

glm::dvec2 gridVertexCoordinate(int i, int j, int N) {
    const glm::dvec2 g = gridCoordinate(i, j, N);
    return g * centreWarpScale(std::max(std::abs(g.x), std::abs(g.y)));  // g * f(m) / m
}

// A patch outside the box lies wholly beyond one of its sides, say g_x >= x0 > 0 before the
// centre's warp (the sides are vertex lines). The warp g f(m) / m has f(m) / m increasing in
// m = |g|_inf (its derivative 2 (1 - a)(1 - m) >= 0) and m >= g_x >= x0, so every corner has a
// warped x >= f(x0), and so has every bilinear mix of them: the point's warped |g|_inf is at
// least M = f(x0) over the nearest side. There Eq. 2's height is at most 1 - M^n (one factor
// at most 1 - M^n, the other at most 1) and |g|_2 >= M, so the angle atan2(|g|_2, height + z_s)
// is at least atan2(M, 1 - M^n + z_s) while that denominator is positive, and at least 90 deg
// otherwise.
double angleOutsideVertexBox(glm::ivec2 boxMin, glm::ivec2 boxMax, int N, int n, double z_s) {
    double nearestSide = 2.0;  // |g| of the nearest side before the warp; beyond 1: no side
    if (boxMin.x > 0) nearestSide = std::min(nearestSide, -gridCoordinate(boxMin.x, 0, N).x);
    if (boxMin.y > 0) nearestSide = std::min(nearestSide, -gridCoordinate(0, boxMin.y, N).y);
    if (boxMax.x < N - 1) nearestSide = std::min(nearestSide, gridCoordinate(boxMax.x, 0, N).x);
    if (boxMax.y < N - 1) nearestSide = std::min(nearestSide, gridCoordinate(0, boxMax.y, N).y);
    if (nearestSide > 1.0) return std::numbers::pi;
    const double warped = std::max(0.0, nearestSide * centreWarpScale(nearestSide));
    const double height = 1.0 - std::pow(warped, n) + z_s;
    if (height <= 0.0) return 0.5 * std::numbers::pi;
    return std::atan2(warped, height);
}

double hemisphereHeight(glm::dvec2 g, int n) {
    return (1.0 - std::pow(std::abs(g.x), n)) * (1.0 - std::pow(std::abs(g.y), n));
}

glm::dvec3 predisplaced(glm::dvec2 g, int n, double z_s) { return {g.x, g.y, hemisphereHeight(g, n) + z_s}; }

// Derivation (paper figure 5). Camera C at distance d on the grid's z axis,
// centre O. The line from C tangent to the ground sphere (radius r) touches it
// at T, |CT| = h = sqrt(d^2 - r^2) (right angle at T), and continues past T to
// P on the peak sphere (radius R), |TP| = s = sqrt(R^2 - r^2) (right angle at
// T again). P is the farthest terrain C can possibly see: a peak of the
// highest height just beyond the horizon. In triangle O C P the sides are
// |OC| = d, |OP| = R, |CP| = h + s, so by the law of cosines the angle phi at
// O obeys cos(phi) = (R^2 + d^2 - (h+s)^2) / (2 R d); by the law of sines,
// with sin(angle at C) = r / d, sin(phi) = (h+s) r / (R d). The grid's edge
// midpoint (1, 0, 0 + z_s) (Eq. 2 is 0 on the boundary) projects to the
// angle atan(1 / z_s) from the axis; setting that to phi gives
// z_s = cos(phi) / sin(phi) = (R^2 + d^2 - (h+s)^2) / (2 r (h+s)).
double zShift(double R, double d, double h, double s, double r) {
    return (R * R + d * d - (h + s) * (h + s)) / (2.0 * r * (h + s));
}

// The same angle directly: angle(O; C, T) = acos(r / d) and angle(O; T, P) = acos(r / R).
double horizonAngle(double d, double r, double R) {
    const double toTangent = d > r ? std::acos(clampUnit(r / d)) : 0.0;
    return toTangent + std::acos(clampUnit(r / std::max(R, r)));
}

// A camera Q with |Q - A| <= roam: |Q| <= d + roam, so it sees at most
// horizonAngle(d + roam) around its own direction (horizonAngle grows with
// distance), and its direction is at most asin(roam / d) from A's (the
// tangent cone from O to the ball around A). The sum bounds what Q sees,
// measured from A's direction.
double coverageAngle(double d, double r, double R, double roamRadiusM) {
    const double roam = std::max(roamRadiusM, 0.0);
    const double offset = d > 0.0 ? std::asin(std::min(1.0, roam / d)) : kPi;
    return std::min(horizonAngle(d + roam, r, R) + offset, kMaxCoverageAngleRad);
}

// A boundary point at grid azimuth theta is (rho cos, rho sin, z_s) with
// rho in [1, sqrt 2] (1 at edge midpoints, sqrt 2 at corners); its angle from
// grid z is atan2(rho, z_s). For z_s >= 0 that grows with rho, so the edge
// midpoints are nearest (Eq. 3's choice); for z_s < 0 it shrinks with rho, so
// the corners are: atan2(sqrt 2, z_s) = angle  <=>  z_s = sqrt 2 cot(angle).
double zShiftForCoverage(double coverageAngleRad) {
    const double angle = std::clamp(coverageAngleRad, 1e-9, kMaxCoverageAngleRad);
    const double cot = std::cos(angle) / std::sin(angle);
    return angle <= 0.5 * kPi ? cot : std::numbers::sqrt2 * cot;
}

double boundaryAngle(double z_s, double azimuthRad) {
    const double rho = 1.0 / std::max(std::abs(std::cos(azimuthRad)), std::abs(std::sin(azimuthRad)));
    return std::atan2(rho, z_s);
}

glm::dmat3 gridRotation(glm::dvec3 cameraDirFromCentre, glm::dvec3 reference) {
    const glm::dvec3 w = glm::normalize(cameraDirFromCentre);
    glm::dvec3 b = glm::normalize(reference);
    // |w x b| = sin(angle); below 1e-3 (0.057 deg) v would lose ~3 digits; use another axis.
    if (glm::length(glm::cross(w, b)) < 1e-3) b = leastAlignedAxis(w);
    const glm::dvec3 v = glm::normalize(glm::cross(w, b));
    const glm::dvec3 u = glm::cross(v, w);
    return glm::dmat3(u, v, w);
}

glm::dmat3 transportGridRotation(const glm::dmat3& worldFromGrid, glm::dvec3 newDirFromCentre) {
    const glm::dvec3 a = glm::normalize(worldFromGrid[2]);
    const glm::dvec3 b = glm::normalize(newDirFromCentre);
    const double c = glm::dot(a, b);
    if (c < -1.0 + 1e-9) return gridRotation(b);  // antipodal: no unique minimal rotation
    // Rodrigues for the rotation taking a to b: I + K + K^2 / (1 + c), K = [a x b]_x.
    const glm::dvec3 k = glm::cross(a, b);
    const glm::dvec3 x = worldFromGrid[0];
    const glm::dvec3 kx = glm::cross(k, x);
    const glm::dvec3 rotatedX = x + kx + glm::cross(k, kx) / (1.0 + c);
    return orthonormalised(rotatedX, b);
}

glm::dvec3 projectToSphere(glm::dvec3 g, double radius) { return g / glm::length(g) * radius; }

bool updateAnchor(GridAnchor& anchor, const Camera& camera, double thresholdM, bool terrainOutOfView) {
    if (!(glm::length(camera.position) > 0.0)) return false;  // at the centre (or NaN): no direction
    if (!anchor.valid) {
        anchor.position = camera.position;
        anchor.worldFromGrid = gridRotation(camera.position);
        anchor.roamRadiusM = std::max(thresholdM, 0.0);
        anchor.valid = true;
        return true;
    }
    const double moved = glm::length(camera.position - anchor.position);
    // min(): if the caller's threshold grew since the last update, the grid was
    // still built for the old, smaller roaming radius.
    const bool beyond = moved > std::min(thresholdM, anchor.roamRadiusM);
    if (!beyond && !(terrainOutOfView && moved > 0.0)) return false;
    anchor.worldFromGrid = transportGridRotation(anchor.worldFromGrid, camera.position);
    anchor.position = camera.position;
    anchor.roamRadiusM = std::max(thresholdM, 0.0);
    return true;
}

GridProjection gridProjection(const GridAnchor& anchor, double planetRadiusM, double maxTerrainHeightM) {
    GridProjection projection;
    projection.worldFromGrid = anchor.worldFromGrid;
    projection.coverageAngle_rad = coverageAngle(glm::length(anchor.position), planetRadiusM,
                                                 planetRadiusM + std::max(maxTerrainHeightM, 0.0),
                                                 anchor.roamRadiusM);
    projection.zShift = zShiftForCoverage(projection.coverageAngle_rad);
    return projection;
}

std::vector<glm::dvec3> projectedGridVertices(const GridParams& params, const GridAnchor& anchor,
                                              double planetRadiusM, double maxTerrainHeightM) {
    const GridProjection projection = gridProjection(anchor, planetRadiusM, maxTerrainHeightM);
    const int N = params.size;
    std::vector<glm::dvec3> vertices;
    vertices.reserve(static_cast<size_t>(N) * static_cast<size_t>(N));
    for (int j = 0; j < N; ++j) {
        for (int i = 0; i < N; ++i) {
            const glm::dvec3 g = predisplaced(gridVertexCoordinate(i, j, N), params.exponent, projection.zShift);
            vertices.push_back(projectToSphere(projection.worldFromGrid * g, planetRadiusM));
        }
    }
    return vertices;
}

std::vector<glm::dvec3> projectedGridVertices(const GridParams& params, const glm::dvec3& anchorPosition,
                                              double planetRadiusM, double maxTerrainHeightM) {
    GridAnchor anchor;
    anchor.position = anchorPosition;
    anchor.worldFromGrid = gridRotation(anchorPosition);
    anchor.roamRadiusM = 0.0;
    anchor.valid = true;
    return projectedGridVertices(params, anchor, planetRadiusM, maxTerrainHeightM);
}

}  // namespace planet
