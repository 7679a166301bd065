// Issue 15: whole blocks of the terrain's patches that cannot reach the view are not drawn
// (src/grid/view_cull.h): at the ground view the vertex and control stages ran for the whole grid,
// most of it behind the camera or beside the view. The culling must be conservative: every point
// of a block's terrain (any radius from the lowest sea floor to the highest peak, and the chords
// between them) that the view shows keeps its block; and it changes no pixel.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/session.h"
#include "gl_test_support.h"
#include "grid/constants.h"
#include "grid/grid_mesh.h"
#include "grid/projected_grid.h"
#include "grid/view_cull.h"
#include "render/readback.h"
#include "render/renderer.h"
#include "terrain/terrain_block.h"
#include "terrain/terrain_pass.h"

using namespace planet;

namespace {

struct CulledGrid {
    GridBlock grid;
    std::vector<PatchRun> blocks;
    std::vector<bool> shown;
    double low = 0.0, high = 0.0;  // m from the centre
};

CulledGrid cull(const Session& s, double aspect, bool rows = false) {
    CulledGrid c;
    const double radius = s.scene.planetRadiusM();
    GridParams params;
    params.size = s.scene.terrain.grid_size;
    params.exponent = s.scene.terrain.grid_exponent == 2 ? 2 : 4;
    GridAnchor anchor;
    updateAnchor(anchor, s.camera, anchorThresholdM(params, s.camera.altitude(radius)), false);
    const GridProjection projection = gridProjection(anchor, radius, s.scene.terrain.max_height_m);
    c.grid = makeGridBlock(projection, params.exponent, s.camera.position, radius, params.size);
    c.blocks = rows ? rowBlocks(params.size) : nearFirstBlocks(params.size);
    const terrain::TerrainBlock block = terrain::makeTerrainBlock(s.scene);
    c.low = radius - block.shape.oceanDepth;
    c.high = radius + block.shape.maxHeight;
    c.shown = gridBlocksInView(c.blocks, c.grid, s.camera, aspect, c.low, c.high);
    return c;
}

// The world point at fractional point index `index` of the grid (bilinear between the points' grid
// coordinates, as terrain.tese for one-cell patches) at `radius`.
glm::dvec3 gridPoint(const GridBlock& grid, glm::dvec2 index, double radius) {
    const int i = std::min(static_cast<int>(index.x), grid.pointsPerSide - 2);
    const int j = std::min(static_cast<int>(index.y), grid.pointsPerSide - 2);
    const glm::dvec2 f = index - glm::dvec2(i, j);
    const int n = grid.pointsPerSide;
    const glm::dvec2 g = glm::mix(glm::mix(gridVertexCoordinate(i, j, n), gridVertexCoordinate(i + 1, j, n), f.x),
                                  glm::mix(gridVertexCoordinate(i, j + 1, n), gridVertexCoordinate(i + 1, j + 1, n), f.x), f.y);
    const glm::dmat3 worldFromGrid(glm::dvec3(grid.worldFromGridColumns[0]), glm::dvec3(grid.worldFromGridColumns[1]),
                                   glm::dvec3(grid.worldFromGridColumns[2]));
    return glm::normalize(worldFromGrid * predisplaced(g, grid.exponent, grid.zShift)) * radius;
}

// Whether the world point lies in the view's frustum (no near plane) with its side planes' slopes
// widened by FRUSTUM_WIDENING, as the control stage culls (and gridBlocksInView promises).
bool inView(const Camera& camera, double aspect, const glm::dvec3& point) {
    const glm::dvec3 v = glm::transpose(camera.worldFromView()) * (point - camera.position);
    const double t = grid_constant::FRUSTUM_WIDENING * std::tan(0.5 * camera.fovY_rad);
    return -v.z > 0.0 && std::abs(v.x) <= -v.z * t * aspect && std::abs(v.y) <= -v.z * t;
}

}  // namespace

// Random points of every block, at radii from the sea floor to the peaks, and points on the chords
// between two of a patch's points: each one in the widened view keeps its block. At the ground view most of the
// grid is culled; from orbit, looking down at the planet, less.
TEST(ViewCull, EveryPointInViewKeepsItsBlock) {
    const double aspect = 16.0 / 9.0;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const std::string view : {"ground", "beach", "mountains", "sunset", "orbit", "clouds"})
      for (const bool rows : {false, true}) {  // NearFirst's blocks' rows, row order's runs of 8
        const Session s = loadSession(test::repoPaths(), "earth", view);
        const CulledGrid c = cull(s, aspect, rows);
        ASSERT_EQ(c.shown.size(), c.blocks.size());
        int culledPatches = 0, allPatches = 0, pointsInView = 0, missed = 0;
        for (std::size_t b = 0; b < c.blocks.size(); ++b) {
            const PatchRun& block = c.blocks[b];
            allPatches += block.patchCount;
            if (!c.shown[b]) culledPatches += block.patchCount;
            const glm::dvec2 from(block.pointMin), span(block.pointMax - block.pointMin);
            for (int k = 0; k < 800; ++k) {
                glm::dvec2 at = from + span * glm::dvec2(unit(random), unit(random));
                if (k % 2 == 0) at[k % 4 / 2] = from[k % 4 / 2] + (k % 8 < 4 ? 0.0 : span[k % 4 / 2]);  // on its rim
                const glm::dvec2 near = glm::clamp(at + glm::dvec2(unit(random) - 0.5, unit(random) - 0.5), from,
                                                   from + span);
                const double rise = k % 3 == 0 ? unit(random) : k % 3 == 1 ? 0.0 : 1.0;  // in the shell, or at its faces
                const glm::dvec3 a = gridPoint(c.grid, at, c.low + (c.high - c.low) * rise);
                const glm::dvec3 p = k % 5 != 0 ? a
                                                : glm::mix(a, gridPoint(c.grid, near, c.low + (c.high - c.low) * rise),
                                                           unit(random));  // a chord's point, within a patch or so
                if (!inView(s.camera, aspect, p)) continue;
                ++pointsInView;
                if (!c.shown[b]) ++missed;
            }
        }
        std::printf("%-9s %-10s %d of %d patches culled; %d sampled points in view, %d of them in culled blocks\n",
                    view.c_str(), rows ? "row order" : "near first", culledPatches, allPatches, pointsInView, missed);
        EXPECT_GT(pointsInView, 0) << view;
        EXPECT_EQ(missed, 0) << view << ": a block the view shows was culled";
        if (view == "ground" || view == "beach") {
            EXPECT_GT(culledPatches, allPatches / 2) << view;
        }
    }
}

// A camera looking straight away from the planet culls every block; one looking straight down at it
// from low orbit culls none of those under it.
TEST(ViewCull, LookingAwayCullsEverythingLookingDownKeepsTheGroundBelow) {
    Session s = loadSession(test::repoPaths(), "earth", "orbit");
    const glm::dvec3 up = glm::normalize(s.camera.position);
    const glm::dvec3 side = glm::normalize(glm::cross(up, std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
    s.camera.orientation = orientationFromAxes(side, glm::cross(side, up), up);  // forward: straight up
    const CulledGrid away = cull(s, 1.0);
    int shownAway = 0;
    for (bool b : away.shown) shownAway += b ? 1 : 0;
    EXPECT_EQ(shownAway, 0) << "blocks kept though the camera looks away from the planet";
    s.camera.orientation = orientationFromAxes(side, glm::cross(side, -up), -up);  // straight down
    const CulledGrid down = cull(s, 1.0);
    // The block under the camera: the centre's block (the first drawn) lies below the grid's anchor.
    EXPECT_TRUE(down.shown.front()) << "the ground right below the camera was culled";
}

namespace {

class ViewCullRender : public test::GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    }
    // `view` at 160x90, full rate, without the culling (`setCulling(false)`) and with it: how many
    // values of the HDR image differ, and the patches `drawn` each time.
    template <class Pass>
    std::size_t differingWithCulling(const std::string& view, Pass& pass, int drawn[2]) {
        const glm::ivec2 size{160, 90};
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        ImageRGBAF images[2];
        for (int culling = 0; culling < 2; ++culling) {
            pass.setViewCulling(culling == 1);
            renderer->render(s.scene, s.camera, size);
            images[culling] = readTextureRGBAF(renderer->targets().hdr(), size.x, size.y);
            drawn[culling] = pass.patchesDrawn();
        }
        pass.setViewCulling(true);
        std::size_t differing = 0;
        for (std::size_t i = 0; i < images[0].pixels.size(); ++i)
            differing += images[0].pixels[i] != images[1].pixels[i] ? 1 : 0;
        std::printf("%-9s patches drawn %d without the culling, %d with it; %zu values differ\n", view.c_str(), drawn[0],
                    drawn[1], differing);
        return differing;
    }
    std::unique_ptr<Renderer> renderer;
};

}  // namespace

// The pictures with and without the culling are the same value for value, with far fewer patches drawn
// at the ground.
TEST_F(ViewCullRender, CullingChangesNoPixel) {
    for (const std::string view : {"ground", "mountains", "orbit"}) {
        int drawn[2];
        EXPECT_EQ(differingWithCulling(view, renderer->terrain(), drawn), 0u) << view;
        EXPECT_LE(drawn[1], drawn[0]) << view;
        if (view == "ground") {
            EXPECT_LT(drawn[1], drawn[0] / 2) << view;
        }
    }
}

// The sea's grid likewise, its runs widened by the waves' reach (up, down and sideways): the sea,
// the beach and the sunset the same value for value.
TEST_F(ViewCullRender, TheSeasCullingChangesNoPixel) {
    for (const std::string view : {"sea", "beach", "sunset"}) {
        int drawn[2];
        EXPECT_EQ(differingWithCulling(view, renderer->ocean(), drawn), 0u) << view;
        EXPECT_LT(drawn[1], drawn[0]) << view;
    }
}
