// Issue 15: from high up the projected grids' cells are far smaller on screen than the
// tessellation target, and the grids draw patches of several cells (grid/grid_stride.h,
// GridMesh::setStride) that tessellation subdivides to the same target. The stride's rule,
// its cells' measure (an analytic grid), the patches' tiling of the grid, and on the GPU: the
// strides picked at orbit and space, none near the ground, and the images against stride 1.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "app/session.h"
#include "gl_test_support.h"
#include "grid/grid_mesh.h"
#include "grid/grid_stride.h"
#include "render/image_compare.h"
#include "render/readback.h"
#include "render/renderer.h"

using namespace planet;

TEST(GridStride, LargestPowerOfTwoWithinThePatchSizeAndNoFlicker) {
    // 48 px patches, 0.8 x 48 = 38.4 to step up, 1.25 x 48 = 60 to keep.
    EXPECT_EQ(gridStrideFor(7.0, 48.0, 0), 4);    // 28 <= 38.4 < 56
    EXPECT_EQ(gridStrideFor(4.0, 48.0, 0), 8);    // 32 <= 38.4; 8 is the largest
    EXPECT_EQ(gridStrideFor(1.0, 48.0, 0), kMaxGridStride);
    EXPECT_EQ(gridStrideFor(30.0, 48.0, 0), 1);   // 60 > 38.4
    EXPECT_EQ(gridStrideFor(0.0, 48.0, 4), 1);    // no visible cell
    // Between the two margins the previous stride stays, whichever it was.
    EXPECT_EQ(gridStrideFor(10.0, 48.0, 4), 4);   // 40 > 38.4 but <= 60: kept
    EXPECT_EQ(gridStrideFor(10.0, 48.0, 2), 2);   // 40 > 38.4: not raised
    EXPECT_EQ(gridStrideFor(16.0, 48.0, 4), 2);   // 64 > 60: lowered
    EXPECT_EQ(gridStrideFor(10.0, 48.0, 8), 4);   // 80 > 60: lowered to what fits
    // A jump (the cells 1.5 x larger or smaller than the last frame's) starts afresh.
    GridStride s;
    s.update(10.0, 48.0, kMaxGridStride);
    EXPECT_EQ(s.stride, 2);
    s.update(9.0, 48.0, kMaxGridStride);
    EXPECT_EQ(s.stride, 4);  // 4 x 9 = 36 <= 38.4: stepped up
    GridStride t;
    t.update(7.0, 48.0, kMaxGridStride);
    EXPECT_EQ(t.stride, 4);
    t.update(10.0, 48.0, kMaxGridStride);
    EXPECT_EQ(t.stride, 4);  // kept
    t.update(20.0, 48.0, kMaxGridStride);
    EXPECT_EQ(t.stride, 1);  // a jump: afresh (2 x 20 = 40 > 38.4), not kept at 2 (40 <= 60)
    // What the tessellator can subdivide bounds it: k x segments <= 64.
    GridStride u;
    u.update(4.0, 48.0, strideWithinTessellation(20.0));
    EXPECT_EQ(u.stride, 2);  // 8 would fit the pixels, but 4 x 20 > 64
    EXPECT_EQ(strideWithinTessellation(0.5), kMaxGridStride);
    EXPECT_EQ(strideWithinTessellation(16.0), 4);
    EXPECT_EQ(strideWithinTessellation(40.0), 1);
}

TEST(GridStride, MedianCellOfAPlanarGridSeenHeadOn) {
    // A flat grid 1 km apart at the top of a planet, the camera 100 km above its centre looking
    // down: each cell's edge subtends s D / (D^2 + x^2), within 0.3 % of s / D this near the axis.
    const double R = 6.371e6, D = 1.0e5, s = 1000.0;
    const int N = 11;
    std::vector<glm::dvec3> points;
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) points.push_back({(i - 5) * s, (j - 5) * s, R});
    Camera camera;
    camera.position = {0.0, 0.0, R + D};
    camera.orientation = orientationFromAxes({1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, -1.0});
    const double radiansPerPixel = 1.0e-4;
    const auto cells = [&](double halfFov, double maxSagM) {
        return measureVisibleCells(points, N, camera, radiansPerPixel, halfFov, R, 12.0, maxSagM);
    };
    const double median = cells(0.5, 1.0e30).medianPixels;
    EXPECT_NEAR(median, s / D / radiansPerPixel, 0.003 * s / D / radiansPerPixel);
    // Segments a cell needs: its 100 px over a 12 px target, 8.33 (the sag bound, a chord of 1 km
    // under 0.25 px = 2.5 m, asks for 1000 / sqrt(8 R 2.5) = 0.09, less); with a 0.1 mm sag bound,
    // 1000 / sqrt(8 R 1e-4) = 14.0.
    EXPECT_NEAR(cells(0.5, 1.0e30).maxSegments, 100.0 / 12.0, 0.03);
    EXPECT_NEAR(cells(0.5, 1.0e-4).maxSegments, 1000.0 / std::sqrt(8.0 * R * 1.0e-4), 0.05);
    // Looking away (up), no cell is in the view's cone.
    camera.orientation = orientationFromAxes({1.0, 0.0, 0.0}, {0.0, -1.0, 0.0}, {0.0, 0.0, 1.0});
    EXPECT_EQ(cells(0.5, 1.0e30).medianPixels, 0.0);
    EXPECT_EQ(cells(0.5, 1.0e30).maxSegments, 0.0);
    // From below the planet's surface plane (the far side), none is above its horizon.
    camera.position = {0.0, 0.0, -R - D};
    camera.orientation = orientationFromAxes({1.0, 0.0, 0.0}, {0.0, -1.0, 0.0}, {0.0, 0.0, 1.0});
    EXPECT_EQ(cells(1.5, 1.0e30).medianPixels, 0.0);
}

TEST(GridStride, GridPointsAreProjectedAgainOnlyWhenTheAnchorMoves) {
    // From orbit, the camera turning and drifting within the anchor's hysteresis: the grid's points
    // stay those of the anchor (the walk over them still sees the new view); the anchor moving
    // projects them afresh.
    const double R = 6.371e6;
    GridParams params;
    params.size = 40;
    Camera camera = cameraAtGeographic(10.0, 20.0, 4.0e5, 0.0, -60.0, 60.0, R);
    GridAnchor anchor;
    updateAnchor(anchor, camera, anchorThresholdM(params, camera.altitude(R)), false);
    GridStride state;
    const auto choose = [&] {
        return chooseGridStride(state, 0, true, params, anchor, R, 8000.0, camera, camera.fovY_rad / 360.0, 16.0 / 9.0,
                                12.0, 1000.0);
    };
    choose();
    ASSERT_EQ(state.points, projectedGridVertices(params, anchor, R, 8000.0));
    const std::vector<glm::dvec3> first = state.points;
    const glm::dvec3 start = camera.position;
    camera = cameraAtGeographic(10.0, 20.0, 4.0e5 + 100.0, 30.0, -50.0, 60.0, R);
    EXPECT_FALSE(updateAnchor(anchor, camera, anchorThresholdM(params, camera.altitude(R)), false));
    choose();
    EXPECT_EQ(state.points, first);
    camera = cameraAtGeographic(12.0, 20.0, 4.0e5, 0.0, -60.0, 60.0, R);
    ASSERT_TRUE(updateAnchor(anchor, camera, anchorThresholdM(params, camera.altitude(R)), false));
    ASSERT_GT(glm::length(camera.position - start), 1.0e5);
    choose();
    EXPECT_NE(state.points, first);
    EXPECT_EQ(state.points, projectedGridVertices(params, anchor, R, 8000.0));
    // Another grid size is another grid.
    params.size = 20;
    choose();
    EXPECT_EQ(state.points.size(), 400u);
}

TEST(GridStride, StridePatchesTileTheGridOnce) {
    for (int size : {26, 80, 100}) {
        for (int stride : {1, 2, 4, 8}) {
            const std::vector<GLuint> patches = stridePatches(size, stride);
            std::vector<int> covered(static_cast<std::size_t>((size - 1) * (size - 1)), 0);
            for (std::size_t p = 0; p < patches.size(); p += 4) {
                const int i0 = static_cast<int>(patches[p] % size), j0 = static_cast<int>(patches[p] / size);
                const int i1 = static_cast<int>(patches[p + 2] % size), j1 = static_cast<int>(patches[p + 2] / size);
                ASSERT_EQ(patches[p + 1], static_cast<GLuint>(j0 * size + i1));
                ASSERT_EQ(patches[p + 3], static_cast<GLuint>(j1 * size + i0));
                ASSERT_GT(i1, i0);
                ASSERT_GT(j1, j0);
                ASSERT_LE(i1 - i0, stride);
                ASSERT_LE(j1 - j0, stride);
                for (int j = j0; j < j1; ++j)
                    for (int i = i0; i < i1; ++i) ++covered[static_cast<std::size_t>(j * (size - 1) + i)];
            }
            for (int c : covered) ASSERT_EQ(c, 1) << "size " << size << " stride " << stride;
        }
    }
}

namespace {

class GridStrideFrame : public test::GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    }
    // One full-rate frame of `view` with the grids' stride forced (0: as picked).
    ImageRGBAF render(const std::string& view, glm::ivec2 size, int stride) {
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        renderer->terrain().setStrideOverride(stride);
        renderer->ocean().setStrideOverride(stride);
        renderer->ocean().setCountPrimitives(true);
        renderer->ocean().setFarFieldAllowed(false);  // the sea's mesh, not its far field's per-pixel draw
        renderer->terrain().setStatistics(true);
        renderer->render(s.scene, s.camera, size);
        return readTextureRGBAF(renderer->targets().hdr(), size.x, size.y);
    }
    std::unique_ptr<Renderer> renderer;
};

}  // namespace

TEST_F(GridStrideFrame, FromHighUpLargerPatchesGiveTheSamePicture) {
    // 640x360: at 160x90 a cell from orbit spans a pixel or two and every stride is 8.
    const glm::ivec2 size{640, 360};
    for (const std::string view : {"orbit", "space"}) {
        const ImageRGBAF picked = render(view, size, 0);
        const int terrainStride = renderer->terrain().stride(), oceanStride = renderer->ocean().stride();
        const long long oceanPrimitives = renderer->ocean().lastPrimitives();
        const long long terrainPatches = renderer->terrain().lastStatistics().patches;
        const ImageRGBAF one = render(view, size, 1);
        const long long oceanPrimitivesOne = renderer->ocean().lastPrimitives();
        const long long terrainPatchesOne = renderer->terrain().lastStatistics().patches;
        const ImageComparison c = compareImages(picked, one);
        std::printf("%-6s stride terrain %d ocean %d; terrain patches %lld -> %lld, ocean primitives %lld -> %lld; "
                    "against stride 1: mean %.4f %%, p99 %.3f %%, max %.2f %%\n",
                    view.c_str(), terrainStride, oceanStride, terrainPatchesOne, terrainPatches, oceanPrimitivesOne,
                    oceanPrimitives, 100 * c.meanRelativeError, 100 * c.errorPercentile(99), 100 * c.maxRelativeError);
        EXPECT_GE(terrainStride, 2) << view;
        EXPECT_GE(oceanStride, 2) << view;
        if (terrainPatchesOne >= 0) {
            EXPECT_LT(terrainPatches, terrainPatchesOne / 3) << view;
        }
        // The sea's triangles: far fewer from space; from orbit the limb's band keeps a segment per
        // cell (shaders/grid/tessellation.glsl's limbCellSegments) and odd levels round it up
        // (measured at 640x360: space 12482 -> 6408, orbit 3832 -> 4666).
        if (view == "space") {
            EXPECT_LT(oceanPrimitives, oceanPrimitivesOne * 3 / 4) << view;
        } else {
            EXPECT_LT(oceanPrimitives, oceanPrimitivesOne * 3 / 2) << view;
        }
        // The meshes differ by their tessellation only: the sea is shaded on its sphere and its
        // grid's reflection read per pixel, the terrain's chords sag under 1 km either way.
        // Measured on llvmpipe: orbit mean 0.007 %, p99 0.13 %; space 0.020 %, 0.46 % (the
        // sea's reflection interpolated across the larger triangles: 0.3 %, 6 %; the terrain's
        // chords sagging 38 km: the land 2 % darker).
        EXPECT_LT(c.meanRelativeError, 5e-4) << view;
        EXPECT_LT(c.errorPercentile(99), 0.01) << view;
        EXPECT_LT(std::abs(c.meanLuminanceDifference), 1e-3) << view;
    }
}

TEST_F(GridStrideFrame, NearTheGroundTheGridsKeepTheirCells) {
    // Below the terrain detail's reach (3 km above the highest ground) the meshes are as they
    // were: stride 1, the picture the same to the bit as with it forced.
    const glm::ivec2 size{160, 90};
    for (const std::string view : {"sea", "aircraft"}) {
        const ImageRGBAF picked = render(view, size, 0);
        EXPECT_EQ(renderer->terrain().stride(), 1) << view;
        EXPECT_EQ(renderer->ocean().stride(), 1) << view;
        const ImageRGBAF one = render(view, size, 1);
        ASSERT_EQ(picked.pixels.size(), one.pixels.size());
        int differing = 0;
        for (std::size_t i = 0; i < picked.pixels.size(); ++i) differing += picked.pixels[i] != one.pixels[i] ? 1 : 0;
        EXPECT_EQ(differing, 0) << view;
    }
}
