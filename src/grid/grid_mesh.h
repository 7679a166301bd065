// The projected grid's mesh on the GPU: N x N grid coordinates (gridVertexCoordinate) as
// (N-1)^2 four-vertex patches for the tessellation stages. The terrain and the ocean each
// draw one (Michelic §6: 100 x 100 and 80 x 80).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "gl/handle.h"
#include "grid/projected_grid.h"

namespace planet {

// GridBlock: the grid's projection as shaders/terrain/grid.glsl reads it (BLOCK_GRID,
// std140: a dvec4 takes 32 bytes). Each pass that draws a grid owns one (GridMesh).
struct GridBlock {
    glm::dvec4 worldFromGridColumns[3];  // Eq. 4's rotation by column, w 0
    glm::dvec4 cameraPositionAndRadius;  // camera (world, m); w: the grid sphere's radius, m
    double zShift;                       // z_s of Eq. 3
    int exponent;                        // n of Eq. 2
    int pointsPerSide = 0;               // N: the grid's points are N x N, index j * N + i
    int stride = 1;                      // cells a patch spans per side (GridMesh::setStride)
    int padding[3] = {0, 0, 0};          // to the 32 bytes a std140 block with a dvec4 rounds to
};
static_assert(offsetof(GridBlock, cameraPositionAndRadius) == 96 && offsetof(GridBlock, zShift) == 128 &&
                  offsetof(GridBlock, exponent) == 136 && offsetof(GridBlock, stride) == 144 &&
                  sizeof(GridBlock) == 160,
              "GridBlock must match std140 (shaders/terrain/grid.glsl)");

// Eq. 1-4's frame and shift, Eq. 2's n, the camera (world, m) and the sphere's radius (m).
GridBlock makeGridBlock(const GridProjection& projection, int exponent, const glm::dvec3& cameraPosition,
                        double radius, int pointsPerSide, int stride = 1);

// The order the patches are drawn in. Rows: row by row. NearFirst: ring by ring (of 8 x 8 patch blocks) outwards
// from the grid's centre, the point below the grid's projection camera (Eq. 2-4), which
// stays within a few percent of its altitude of the camera: near ground is drawn before the
// ground it hides, so the depth test rejects hidden fragments before they are shaded.
// Opaque passes draw the same pixels in either order (the nearest fragment wins).
enum class PatchOrder { Rows, NearFirst };

// A run of the index buffer's patches, in draw order, and the box of grid points (indices, inclusive)
// their corners lie in. NearFirst's rings: ring k's patches follow those of rings 0..k-1, and rings
// 0..k together lie in the box (the grid's centre inside), beyond which angleOutsideVertexBox
// (grid/projected_grid.h) bounds how near the rest can come. The runs grid/view_cull.h culls: up to
// 8 patches along a row (stride 1), the rows of NearFirst's 8 x 8 blocks or, in row order, each row's.
struct PatchRun {
    int firstPatch = 0;
    int patchCount = 0;
    glm::ivec2 pointMin{0};
    glm::ivec2 pointMax{0};
};
std::vector<PatchRun> nearFirstRings(int size);

std::vector<PatchRun> nearFirstBlocks(int size);
std::vector<PatchRun> rowBlocks(int size);

// The patches of stride x stride cells (GridMesh::setStride) of a size x size grid, in row
// order: four point indices (j * size + i) each, corners (i0, j0), (i1, j0), (i1, j1), (i0, j1).
std::vector<GLuint> stridePatches(int size, int stride);

class GridMesh {
public:
    explicit GridMesh(std::string label, PatchOrder order = PatchOrder::Rows);

    // Rebuilds the buffers when the size or the order changed; size in [2, 4096].
    void resize(int size);
    void setOrder(PatchOrder order);
    // Patches of stride x stride cells (1, 2, 4 or 8; grid/grid_stride.h picks it), their
    // corners on the same points: fewer, larger patches that tessellation subdivides to the
    // same target, where the grid's cells are far smaller on screen than that target. The
    // last patch of a row or column takes what is left. Larger strides draw in row order
    // (NearFirst's rings are for stride 1, the views near the ground).
    void setStride(int stride);
    int stride() const { return stride_; }
    // Uploads the grid's projection (the prepare step).
    void setProjection(const GridBlock& block);
    // Binds the grid's block at BLOCK_GRID and draws the patches (GL_PATCHES, 4 vertices
    // each) with the bound program: all of them, or `count` from `first` in draw order.
    void draw() const { draw(0, patchCount()); }
    void draw(int first, int count) const;
    int patchCount() const { return patchCount_; }
    // The grid's points: size x size coordinates (vec2), index j * size + i, as the vertex stage
    // reads them (gl_VertexID), for a compute pass that works per point; and the grid's block at
    // BLOCK_GRID for it.
    int pointCount() const { return size_ * size_; }
    int size() const { return size_; }
    const gl::Buffer& points() const { return vertices_; }
    void bindBlock() const;
    // NearFirst's rings (empty in row order).
    const std::vector<PatchRun>& rings() const { return stride_ == 1 ? rings_ : noRings_; }
    // The patches' blocks (empty with a stride), and which of them the draws draw:
    // `shown` one flag per block (grid/view_cull.h), or empty for all; until the next call, or until
    // the size, the order or the stride changes.
    const std::vector<PatchRun>& blocks() const { return stride_ == 1 ? blocks_ : noBlocks_; }
    void showBlocks(std::vector<bool> shown);
    // The patches the draws draw of `count` from `first` (all, or those of the shown blocks).
    int patchesDrawn(int first, int count) const;

    // Mesa's software renderers (llvmpipe, softpipe) tessellate in the Gallium draw module,
    // which numbers the tessellated vertices of one chunk of input (up to 4096 vertices: 1024
    // patches) with 16-bit indices: past 65 535 vertices the indices wrap, and triangles join
    // vertices of unrelated patches into sheets across the whole view (the mountains view at
    // 1280 x 720 was one grey wall, level 64 near the camera; 640 x 360, whose levels stop
    // near 32, was right). A quad at level 64 makes at most 65 x 65 vertices, so there the
    // patches are drawn in runs of kPatchesPerSoftwareDraw, one glMultiDrawElements.
    static constexpr int kPatchesPerSoftwareDraw = 65535 / (65 * 65);

private:
    std::string label_;
    gl::VertexArray vertexArray_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::Buffer block_;  // GridBlock
    PatchOrder order_;
    int size_ = 0;
    int stride_ = 1;
    int patchCount_ = 0;
    gl::Buffer coarseIndices_[3];            // strides 2, 4, 8, built on first use
    int coarsePatchCount_[3] = {0, 0, 0};
    bool splitDraws_;  // a software renderer: draw in runs (above)
    std::vector<PatchRun> rings_;
    std::vector<PatchRun> noRings_;
    std::vector<PatchRun> blocks_;
    std::vector<PatchRun> noBlocks_;
    std::vector<bool> shown_;  // per block; empty: all
    // The runs of patches (first, count) the draws draw of `count` from `first`, in draw order.
    std::vector<glm::ivec2> runs(int first, int count) const;
};

}  // namespace planet
