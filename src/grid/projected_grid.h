// Projected grid: the persistent world-space grid of Michelic (seed 003, §3
// "Grid Projection", Eq. 1-4), CPU side, all in double.
//
// Terrain and ocean both draw one fixed N x N grid (paper §6: 100 x 100 for the
// terrain, 80 x 80 for the ocean) that the GPU projects onto the planet every
// frame. The steps, in the grid's own frame (grid z towards the projection
// camera) and then in the world frame (scene/scene.h: centre at the origin,
// +Z north):
//
//   1. g = (g_x, g_y) in [-1, 1]^2, denser at the centre   gridVertexCoordinate
//   2. g_z = (1 - |g_x|^n)(1 - |g_y|^n) + z_s              predisplaced (Eq. 2, then the shift)
//      The hemisphere pre-displacement keeps the projection one-to-one when
//      z_s < 0 (paper figure 4); z_s sets how far from the camera the grid
//      reaches (zShift, Eq. 3; zShiftForCoverage).
//   3. rotate so that grid z points at the projection camera  gridRotation (Eq. 4)
//   4. v = r g / |g|                                        projectToSphere (Eq. 1)
//   5. (later, on the GPU) displace v radially by the terrain height or waves.
//
// The projection camera ("anchor") is the real camera's position frozen until
// the real camera has moved farther than a threshold from it (paper: "we keep
// the camera position for the projection constant until the distance to the
// actual camera position exceeds a certain threshold"), so translations within
// the threshold do not morph the mesh; camera rotations never do.
//
// Where this deviates from the paper, and why:
//  - Eq. 4 as printed (u = w x v) has determinant -1, a reflection that flips
//    triangle winding; we use u = v x w (det +1, same columns up to u's sign).
//  - Eq. 4 with a constant b is undefined at w = +-b, and no frame that is a
//    function of the position alone can be continuous on the whole sphere (the
//    hairy-ball theorem: grid x would be a continuous tangent field without
//    zeros). So the anchor carries its frame and *parallel-transports* it when
//    it moves (the minimal rotation taking the old grid z to the new one):
//    continuous along any path, pole or not, and still independent of the
//    camera's orientation, which is what the paper's constant b is for. Eq. 4
//    (b = +Z) only seeds the first frame; gridRotation itself stays available
//    and falls back to a second reference near the pole of b.
//  - Eq. 3 puts the grid's edge midpoints on the angle phi to the farthest
//    visible peak. That covers the visible cap only while z_s >= 0: for z_s < 0
//    (cameras beyond ~19 planet radii for Earth) the boundary's *corners*
//    (g = (+-1, +-1)) are nearer the grid's centre than its edge midpoints, and
//    an Eq. 3 grid leaves slivers of the limb uncovered at the four corner
//    azimuths. zShiftForCoverage makes whichever is nearer (edges for z_s >= 0,
//    corners for z_s < 0) land on the required angle.
//  - The anchor lags the real camera by up to the threshold, so the grid must
//    cover what any camera within that distance can see, not just what the
//    anchor sees: coverageAngle widens phi by that (and equals phi when the
//    threshold is 0).
//
// Coverage guarantee (tests/test_projected_grid.cpp checks it by ray casting):
// every point at a radius in [r, r + maxTerrainHeight] that a camera within
// GridAnchor::roamRadiusM of the anchor can see lies inside the projected
// grid, provided the coverage angle stays below kMaxCoverageAngleRad.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "grid/constants.h"
#include "scene/camera.h"

namespace planet {

struct GridParams {
    int size = 100;                     // N: vertices per side, N x N in all, [8, 1024]
    int exponent = 4;                   // n in Eq. 2, 4 (paper's choice) or 2
    // The anchor moves when the real camera is farther from it than
    // max(hysteresisMinM, hysteresisFraction * anchor altitude). Relative to the
    // altitude because the mesh's scale is: 5% of 2 m is a step on a beach, 5%
    // of 1000 km is a small fraction of the visible disc.
    double hysteresisFraction = 0.05;   // of the anchor's altitude, [0, 1]
    double hysteresisMinM = 0.1;        // m, [0, 1e6]
};

// "" when every field is in range, else a message naming the first bad field.
std::string validateGridParams(const GridParams& params);

// The threshold for updateAnchor: max(hysteresisMinM, hysteresisFraction * altitude), m.
double anchorThresholdM(const GridParams& params, double anchorAltitudeM);

// Above this the grid's centre would fold back (1 + z_s <= 0 at the
// corner-tight z_s): ~125 deg. We clamp at 120 deg, reached only when the
// highest terrain is more than ~15% of the radius; coverage is not guaranteed there.
inline constexpr double kMaxCoverageAngleRad = 2.0943951023931953;  // 120 deg

// Grid coordinate of vertex (i, j), i along grid x, j along grid y, both in
// [0, N-1]: g = -1 + 2 (i, j) / (N - 1), in [-1, 1]^2, exactly +-1 at the edges
// and symmetric under g -> -g (so the vertex set is symmetric under 90 deg turns).
glm::dvec2 gridCoordinate(int i, int j, int N);

// Where vertex (i, j) sits on the grid: gridCoordinate g moved along its ray from the
// centre, g * f(m) / m with m = |g|_inf and f(t) = a t + 2 (1 - a) t^2 - (1 - a) t^3,
// a = kGridCentreDensity: a bijection of [-1, 1]^2 onto itself that keeps each square ring of
// vertices on a square ring and leaves the boundary and its spacing in place (f(1) = 1,
// f'(1) = 1), so coverage is unchanged. Not in the paper: at low altitude the grid must reach
// peaks beyond the horizon hundreds of kilometres away, and evenly spaced vertices put
// kilometres between them at the camera's feet, more than tessellation (at most 64
// subdivisions) can make up; here the spacing is a (1/20) of the even one at the centre (the
// projection camera), at most 1.32 times it (at m = 2/3), and equal to it at the edge.
inline const double kGridCentreDensity = grid_constant::GRID_CENTRE_DENSITY;  // shaders/grid/constants.glsl
glm::dvec2 gridVertexCoordinate(int i, int j, int N);

// The smallest angle from grid z (rad) at which the projected grid puts any point outside the
// box of vertex indices [boxMin, boxMax] (inclusive) of an N x N grid: its vertices and the
// bilinear interiors of its patches (terrain.tese interpolates gridVertexCoordinate), for Eq. 2's
// exponent n and Eq. 3's z_s. The box must hold the grid's centre; pi when it is the whole grid.
// A lower bound, met where the box's nearest side crosses a grid axis (derivation in the .cpp).
double angleOutsideVertexBox(glm::ivec2 boxMin, glm::ivec2 boxMax, int N, int n, double z_s);

// Eq. 2: the hemisphere approximation (1 - |g_x|^n)(1 - |g_y|^n); 1 at the
// centre, 0 on the whole boundary. |g| so that odd n stays symmetric.
double hemisphereHeight(glm::dvec2 g, int n);

// Grid-frame point before projection: (g_x, g_y, hemisphereHeight(g, n) + z_s).
glm::dvec3 predisplaced(glm::dvec2 g, int n, double z_s);

// Eq. 3, as printed. Camera at distance d from the centre, planet (ground
// level) radius r, highest possible peak at distance R from the centre;
// h = sqrt(d^2 - r^2) the camera's tangent length to the ground sphere,
// s = sqrt(R^2 - r^2) the length from that tangent point along the same line
// out to the peak sphere. Returns z_s = (R^2 + d^2 - (h+s)^2) / (2 r (h+s)),
// dimensionless (the grid spans [-1, 1]). See the derivation in the .cpp.
double zShift(double R, double d, double h, double s, double r);

// Angle at the centre between the camera (distance d) and the farthest point
// of the peak sphere (radius R >= r) it can see past the ground sphere
// (radius r): phi = acos(r / d) + acos(r / R), rad. For d < r (inside the
// ground) the first term is 0. Eq. 3 is z_s = cot(phi).
double horizonAngle(double d, double r, double R);

// The angle the grid must cover around the anchor (distance d from the
// centre) so that any camera within roamRadiusM of it sees nothing outside:
// horizonAngle(d + roam, r, R) + asin(min(1, roam / d)), clamped to
// kMaxCoverageAngleRad. Equals horizonAngle when roamRadiusM = 0.
double coverageAngle(double d, double r, double R, double roamRadiusM);

// z_s that puts the grid boundary's nearest points on the given angle from
// the grid's centre: cot(angle) for angle <= 90 deg (edge midpoints, as in
// Eq. 3), sqrt(2) cot(angle) above (corners). The projected grid then covers
// the whole cap of that angular radius and no less.
double zShiftForCoverage(double coverageAngleRad);

// Angular radius (from grid z) of the projected grid's boundary at grid
// azimuth theta (rad, from grid x towards grid y): atan2(rho, z_s) with
// rho = 1 / max(|cos|, |sin|) the square's radius at that azimuth. The
// projected grid is exactly the set of directions inside this.
double boundaryAngle(double z_s, double azimuthRad);

// Eq. 4: worldFromGrid with grid z = w = normalize(cameraDirFromCentre),
// grid y = v = normalize(w x b), grid x = u = v x w (det +1; see header).
// When w is within ~0.06 deg of +-b, b is replaced by the world axis least
// aligned with w: defined everywhere, but (necessarily) not continuous there.
// cameraDirFromCentre need not be unit length; it must not be zero.
glm::dmat3 gridRotation(glm::dvec3 cameraDirFromCentre, glm::dvec3 reference = {0.0, 0.0, 1.0});

// Parallel transport: worldFromGrid rotated by the minimal rotation that
// takes its grid z (column 2) onto normalize(newDirFromCentre), then
// re-orthonormalised. The change is a rotation by exactly the angle between
// the two directions, so a frame carried along a path is as continuous as the
// path. For a (near-)antipodal jump, where the minimal rotation is undefined,
// it restarts from gridRotation(newDir).
glm::dmat3 transportGridRotation(const glm::dmat3& worldFromGrid, glm::dvec3 newDirFromCentre);

// Eq. 1: v = g / |g| * radius. g must not be zero.
glm::dvec3 projectToSphere(glm::dvec3 g, double radius);

// The projection camera.
struct GridAnchor {
    glm::dvec3 position{0.0};         // world frame, m
    glm::dmat3 worldFromGrid{1.0};    // column 2 = normalize(position)
    double roamRadiusM = 0.0;         // m: the real camera stays within this of position until the next update
    bool valid = false;               // false until the first updateAnchor
};

// Moves the anchor to the camera when it is invalid, when
// |camera - anchor| > min(thresholdM, anchor.roamRadiusM), or when forced
// (paper: update "earlier when the change in geometry is less visible, e.g.
// when looking at the sky" -> pass terrainOutOfView; also use it after a
// teleport). A forced update only happens if the camera actually moved.
// The frame is transported (transportGridRotation); the first one is Eq. 4
// with b = +Z. roamRadiusM becomes thresholdM. Returns true when it moved.
bool updateAnchor(GridAnchor& anchor, const Camera& camera, double thresholdM, bool terrainOutOfView);

// What the tessellation evaluation shader needs: per-vertex it computes
// worldFromGrid * predisplaced(g, n, zShift), then Eq. 1.
struct GridProjection {
    glm::dmat3 worldFromGrid{1.0};
    double zShift = 0.0;              // dimensionless, grid units
    double coverageAngle_rad = 0.0;   // rad, the guaranteed covered cap around grid z
};

GridProjection gridProjection(const GridAnchor& anchor, double planetRadiusM, double maxTerrainHeightM);

// All N x N world positions (index j * N + i, see gridVertexCoordinate) on the
// sphere of radius planetRadiusM, the CPU reference of the shader.
std::vector<glm::dvec3> projectedGridVertices(const GridParams& params, const GridAnchor& anchor,
                                              double planetRadiusM, double maxTerrainHeightM);
// Stateless form: the anchor at anchorPosition with Eq. 4's frame (b = +Z)
// and no roaming (z_s from Eq. 3, corner-corrected when negative).
std::vector<glm::dvec3> projectedGridVertices(const GridParams& params, const glm::dvec3& anchorPosition,
                                              double planetRadiusM, double maxTerrainHeightM);

}  // namespace planet
