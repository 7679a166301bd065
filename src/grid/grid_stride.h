// How many of a projected grid's cells each patch spans (GridMesh::setStride). The grid has a
// fixed number of points, spread over the whole visible cap whatever the altitude (Michelic
// Eq. 2-4), so from high up its cells are far smaller on screen than the tessellation target
// (from space, 1280x720: the terrain's about 7 px against 12, the ocean's 8 against the 32 its
// far edges aim at), and every cell is a patch at level 1 of its own: the vertex and
// tessellation stages pay per patch (on a software renderer on the submitting thread), and a
// software rasteriser shades a 4x4 block for each small triangle that touches it. Patches of
// k x k cells, which tessellation subdivides to the same target, cost far less there
// (llvmpipe, space: terrain pass 40 -> 19 ms, ocean 80 -> 46 with the grids four times
// coarser). The stride is the largest power of two (up to 8) whose patches stay within
// kStridePatchPixels on screen at the grid's median visible cell, with a margin either way
// so that it does not flicker between two strides.
#pragma once

#include <algorithm>
#include <vector>

#include <glm/glm.hpp>

#include "grid/projected_grid.h"
#include "scene/camera.h"

namespace planet {

// The patch size on screen that a stride aims at, px: a few tessellation targets (12 px for the
// terrain, 8 to 32 for the ocean).
inline constexpr double kStridePatchPixels = 48.0;
inline constexpr int kMaxGridStride = 8;

// What a grid's visible cells ask for on screen, from one walk over them. A cell is visible when
// its first corner is above the horizon (in front of the sphere's tangent plane there) and within
// the view's cone (`halfDiagonalFov` from the view direction). `points`: the grid's N x N points
// (index j * N + i; projectedGridVertices).
struct VisibleCells {
    // The median of each cell's longer edge on screen, px: the angle between its corners seen from
    // the camera over `radiansPerPixel`. 0 when no cell is visible.
    double medianPixels = 0.0;
    // The most segments any cell's edge needs on its own (shaders/grid/tessellation.glsl's
    // edgeSegments: the edge's angle over targetPixels, and chords sagging under a quarter of a
    // pixel and under maxSagM on the sphere of `planetRadiusM`). A stride's patch edge gives each of
    // its cells as many (strideEdgeLevel), so k times this must stay within the tessellator's 64:
    // near the horizon from orbit a cell needs tens.
    double maxSegments = 0.0;
};
VisibleCells measureVisibleCells(const std::vector<glm::dvec3>& points, int N, const Camera& camera,
                                 double radiansPerPixel, double halfDiagonalFov, double planetRadiusM,
                                 double targetPixels, double maxSagM);

// The largest power of two k <= kMaxGridStride with k x segments <= 64 (1 when none).
int strideWithinTessellation(double segments);

// The stride for cells of `cellPixels` on screen: the largest power of two k <= kMaxGridStride
// with k x cellPixels within 0.8 patchPixels, or `previous` while that is within 1.25 patchPixels
// and at least the former (no flicker at a boundary; 0: none). 1 for no visible cell.
int gridStrideFor(double cellPixels, double patchPixels, int previous);

// Whether a grid may take a stride above 1: only a camera above the terrain detail's reach
// (`nearRangeM` above the highest ground `maxHeightM`; src/terrain/terrain_pass.h's detailInReach),
// so the views near the ground keep their meshes to the vertex.
inline bool gridStrideAllowed(double cameraAltitudeM, double maxHeightM, double nearRangeM) {
    return cameraAltitudeM - maxHeightM >= nearRangeM;
}

// Half the view's diagonal field of view, rad, for measureVisibleCells.
double halfDiagonalFov(double fovY_rad, double aspect);

// The stride a grid's pass keeps from frame to frame: `previous` only while the median cell
// stays within a factor 1.5 of the last frame's (a jump starts afresh, so a view's stride does
// not depend on where the camera came from).
struct GridStride {
    int stride = 1;
    double cellPixels = 0.0;
    // The grid's points (projectedGridVertices) and what they were projected from: the anchor
    // moves only now and then (Michelic's hysteresis), so most frames reuse them.
    struct PointsOf {
        GridAnchor anchor;
        int size = 0, exponent = 0;
        double radiusM = 0.0, maxHeightM = 0.0;
        bool operator==(const PointsOf& o) const {
            return anchor.valid == o.anchor.valid && anchor.position == o.anchor.position &&
                   anchor.worldFromGrid == o.anchor.worldFromGrid && anchor.roamRadiusM == o.anchor.roamRadiusM &&
                   size == o.size && exponent == o.exponent && radiusM == o.radiusM && maxHeightM == o.maxHeightM;
        }
    };
    std::vector<glm::dvec3> points;
    PointsOf pointsOf;
    // `limit`: the largest stride the tessellator can subdivide (strideWithinTessellation).
    void update(double newCellPixels, double patchPixels, int limit) {
        const bool near = cellPixels > 0.0 && newCellPixels < 1.5 * cellPixels && newCellPixels > cellPixels / 1.5;
        stride = std::min(gridStrideFor(newCellPixels, patchPixels, near ? stride : 0), limit);
        cellPixels = newCellPixels;
    }
};

// The stride a grid's pass draws with this frame: `stride` when above 0 (tests), 1 where a stride
// is not `allowed` (gridStrideAllowed), else from the grid's visible cells (the grid of `params`
// and `anchor` on the sphere of `radiusM`, reaching `maxHeightM` above it; its tessellation's
// `targetPixels` and `maxSagM`), `state` keeping the last frame's.
int chooseGridStride(GridStride& state, int stride, bool allowed, const GridParams& params, const GridAnchor& anchor,
                     double radiusM, double maxHeightM, const Camera& camera, double radiansPerPixel, double aspect,
                     double targetPixels, double maxSagM);

}  // namespace planet
