// Issue 15: the terrain at the ground view does no work twice and draws near ground first.
// The control stage takes its corners' points from the vertex stage, which evaluates each
// grid point's height once (shaders/terrain/terrain.vert, terrain.tesc), instead of four
// heights per patch; the patches are drawn ring by ring from the grid's centre outwards
// (grid/grid_mesh.h PatchOrder::NearFirst), so the depth test rejects hidden ground before it
// is shaded. Neither changes a pixel. The stage counts are TerrainPass::Statistics
// (GL pipeline statistics queries).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <vector>

#include "app/session.h"
#include "gl/context.h"
#include "gl_test_support.h"
#include "render/image_compare.h"
#include "render/readback.h"
#include "render/renderer.h"
#include "terrain/height.h"
#include "terrain/terrain_pass.h"

using namespace planet;

namespace {

class TerrainCulling : public test::GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    }
    // One frame of `view` at full rate; the terrain pass's counts, and the HDR image. With
    // `minReliefSlope` >= 0 or `targetEdgePixels` > 0, the preset's terrain.min_relief_slope or
    // terrain.target_edge_px set to it.
    TerrainPass::Statistics render(const std::string& view, glm::ivec2 size, PatchOrder order, ImageRGBAF& image,
                                   double minReliefSlope = -1.0, double targetEdgePixels = -1.0) {
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        if (minReliefSlope >= 0.0) s.scene.terrain.min_relief_slope = minReliefSlope;
        if (targetEdgePixels > 0.0) s.scene.terrain.target_edge_px = targetEdgePixels;
        renderer->terrain().setStatistics(true);
        renderer->terrain().setPatchOrder(order);
        renderer->render(s.scene, s.camera, size);
        image = readTextureRGBAF(renderer->targets().hdr(), size.x, size.y);
        return renderer->terrain().lastStatistics();
    }
    std::unique_ptr<Renderer> renderer;
};

// A shader's text without its comments.
std::string shaderCode(const std::string& name) {
    std::ifstream in(test::repoPaths().shaders() / name);
    std::stringstream text;
    text << in.rdbuf();
    return std::regex_replace(text.str(), std::regex("//[^\n]*"), "");
}

}  // namespace

TEST_F(TerrainCulling, SamePixelsInEitherPatchOrder) {
    const glm::ivec2 size{160, 90};
    for (const std::string view : {"ground", "beach", "orbit"}) {
        ImageRGBAF rows, near;
        const TerrainPass::Statistics a = render(view, size, PatchOrder::Rows, rows);
        const TerrainPass::Statistics b = render(view, size, PatchOrder::NearFirst, near);
        ASSERT_EQ(rows.pixels.size(), near.pixels.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < rows.pixels.size(); ++i) differing += rows.pixels[i] != near.pixels[i] ? 1 : 0;
        std::printf("%-6s %lld primitives (%lld in view), %lld patches, vertex stage %lld rows / %lld near first, "
                    "evaluation stage %lld, fragments %lld; %zu values differ\n",
                    view.c_str(), b.primitives, b.clipped, b.patches, a.vertices, b.vertices, b.evaluations,
                    b.fragments, differing);
        EXPECT_EQ(differing, 0u) << view << ": the patch order changed the picture";
        EXPECT_EQ(a.primitives, b.primitives) << view;
    }
}

// The heights behind the levels and the culling are evaluated once per grid point: the
// control stage evaluates none, and the vertex stage runs about once per grid point (vertex
// reuse), not once per patch corner. The ground view at 320x180: 100 x 100 grid points,
// 9801 patches; before, 4 x 9801 = 39204 heights in the control stage. On Mesa's software
// renderers the patches go out in runs of GridMesh::kPatchesPerSoftwareDraw (the draw
// module's 16-bit tessellation indices), and results are reused within a run only: 1.82
// per grid point (18188) against 1.18 in one draw (11800), where 2 would mean no reuse
// across a run's rows.
TEST_F(TerrainCulling, HeightsOncePerGridPointAtTheGround) {
    EXPECT_EQ(shaderCode("terrain/terrain.tesc").find("terrainHeight"), std::string::npos)
        << "the control stage evaluates heights again";
    EXPECT_NE(shaderCode("terrain/terrain.vert").find("terrainHeightGrad("), std::string::npos);
    ImageRGBAF image;
    renderer->terrain().setViewCulling(false);  // the whole grid (the blocks out of view: below)
    const TerrainPass::Statistics st = render("ground", {320, 180}, PatchOrder::NearFirst, image);
    renderer->terrain().setViewCulling(true);
    std::printf("ground 320x180: %lld vertex invocations, %lld patches, %lld evaluations, %lld primitives\n",
                st.vertices, st.patches, st.evaluations, st.primitives);
    if (st.vertices < 0) GTEST_SKIP() << "no pipeline statistics queries";
    EXPECT_EQ(st.patches, 99 * 99);
    const bool runs = gl::softwareRenderer(gl::rendererDescription());
    EXPECT_LE(st.vertices, runs ? 19000 : 13000) << "the vertex stage's results are not reused between patches";
    // With the blocks out of view left undrawn (grid/view_cull.h), the control stage runs on the
    // patches the pass says it draws, and the vertex stage on about as few points.
    const TerrainPass::Statistics culled = render("ground", {320, 180}, PatchOrder::NearFirst, image);
    std::printf("ground 320x180, blocks out of view culled: %lld vertex invocations, %lld patches\n", culled.vertices,
                culled.patches);
    EXPECT_EQ(culled.patches, renderer->terrain().patchesDrawn());
    EXPECT_LT(culled.patches, st.patches / 2);
    EXPECT_LT(culled.vertices, st.vertices * 6 / 10);
}

// Patches tessellated at the highest levels stay in their place. Mesa's draw module numbers
// the tessellated vertices of a chunk of patches with 16-bit indices; past 65 535 they wrapped
// and joined vertices of unrelated patches into sheets over the whole view: the mountains
// view at 1280 x 720 (levels near 64 on the slope at the camera's feet; 640 x 360 stays
// near 32) was one grey wall. GridMesh draws in runs there (kPatchesPerSoftwareDraw).
TEST_F(TerrainCulling, HighestLevelsStayInTheirPatches) {
    Session s = loadSession(test::repoPaths(), "earth", "mountains");
    s.scene.render.temporal = false;
    s.scene.clouds.enabled = false;  // the sky and the terrain alone: a fifth of the frame's time
    const glm::ivec2 size{1280, 720};
    renderer->terrain().setStatistics(false);
    renderer->render(s.scene, s.camera, size);
    const ImageRGBAF image = readTextureRGBAF(renderer->targets().hdr(), size.x, size.y);
    // The top tenth of the view (pitch 3 degrees, field of view 40: the horizon is 42 % down,
    // the range's summit 37 %) is sky: blue. The wall was a grey-brown surface (blue < red).
    int sky = 0, pixels = 0;
    for (int y = 0; y < size.y / 10; ++y)  // the readback's rows run from the top
        for (int x = 0; x < size.x; ++x, ++pixels) {
            const float* p = &image.pixels[4 * (static_cast<std::size_t>(y) * size.x + x)];
            if (p[2] > 1.5f * p[0]) ++sky;
        }
    std::printf("mountains 1280x720: %d of %d pixels in the top tenth are sky\n", sky, pixels);
    EXPECT_EQ(sky, pixels) << "the terrain covers the sky: tessellated vertices joined across patches";
}

// The ground detail's program only where its ground can be in view (TerrainPass::detailInReach):
// from orbit and space no pixel is within its 3 km, and the program without its code draws
// the same frame for less (llvmpipe runs code that no pixel enters). At ground level and in
// the aircraft's view it is drawn.
TEST_F(TerrainCulling, TheGroundDetailIsDrawnOnlyWithinItsReach) {
    EXPECT_TRUE(TerrainPass::detailInReach(2.0, 8000.0));
    EXPECT_TRUE(TerrainPass::detailInReach(10900.0, 8000.0));
    EXPECT_FALSE(TerrainPass::detailInReach(11100.0, 8000.0));
    const glm::ivec2 size{160, 90};
    ImageRGBAF image;
    for (const std::string view : {"ground", "beach", "mountains"}) {
        render(view, size, PatchOrder::NearFirst, image);
        EXPECT_TRUE(renderer->terrain().detailDrawn()) << view;
    }
    for (const std::string view : {"orbit", "space"}) {
        render(view, size, PatchOrder::NearFirst, image);
        EXPECT_FALSE(renderer->terrain().detailDrawn()) << view;
    }
}

// Within the detail's reach, only the patches that can come within its range take the detail's
// program (TerrainPass::detailPatchCount): every point of every patch after them, at any height
// from 12 km under to 9 km over the sea, is farther from the camera than the range. Cameras from
// 2 m to 10 km up, at the grid's anchor and as far from it as the anchor lets them roam
// (anchorThresholdM), the grid's points and 5 x 5 points in each patch.
TEST(TerrainDetailRings, EveryPatchAfterTheDetailsRingsIsBeyondItsRange) {
    const double radius = 6.371e6, maxHeight = 8000.0, range = terrain::terrainNearRangeM();
    const GridParams params;  // 100 x 100, exponent 4, as earth.toml
    const int N = params.size;
    const std::vector<PatchRun> rings = nearFirstRings(N);
    ASSERT_GT(rings.size(), 2u);
    for (const double altitude : {2.0, 300.0, 3000.0, 10000.0})
        for (const double roam : {0.0, 1.0}) {
            Camera camera;
            camera.position = glm::dvec3(0.3, -0.5, 0.8) * ((radius + altitude) / glm::length(glm::dvec3(0.3, -0.5, 0.8)));
            GridAnchor anchor;
            updateAnchor(anchor, camera, anchorThresholdM(params, altitude), false);
            // The camera moved off the anchor sideways by the fraction `roam` of the threshold.
            const glm::dvec3 side = glm::normalize(glm::cross(camera.position, glm::dvec3(0.0, 0.0, 1.0)));
            camera.position += side * (roam * 0.999 * anchorThresholdM(params, altitude));
            const GridProjection projection = gridProjection(anchor, radius, maxHeight);
            const GridBlock block = makeGridBlock(projection, params.exponent, camera.position, radius, params.size);
            const int count = TerrainPass::detailPatchCount(rings, (N - 1) * (N - 1), N, block, range);
            // The rings drawn with the detail: those that end at `count`.
            glm::ivec2 low(0), high(N - 1);
            for (const PatchRun& ring : rings)
                if (ring.firstPatch + ring.patchCount == count) low = ring.pointMin, high = ring.pointMax;
            double nearest = 1e30;
            for (int j = 0; j + 1 < N; ++j)
                for (int i = 0; i + 1 < N; ++i) {
                    if (i >= low.x && i + 1 <= high.x && j >= low.y && j + 1 <= high.y) continue;
                    const glm::dvec2 c00 = gridVertexCoordinate(i, j, N), c10 = gridVertexCoordinate(i + 1, j, N);
                    const glm::dvec2 c01 = gridVertexCoordinate(i, j + 1, N), c11 = gridVertexCoordinate(i + 1, j + 1, N);
                    for (int b = 0; b <= 4; ++b)
                        for (int a = 0; a <= 4; ++a) {
                            const glm::dvec2 g = glm::mix(glm::mix(c00, c10, a / 4.0), glm::mix(c01, c11, a / 4.0), b / 4.0);
                            const glm::dvec3 direction =
                                glm::normalize(projection.worldFromGrid * predisplaced(g, params.exponent, projection.zShift));
                            for (const double height : {-12000.0, 0.0, 9000.0})
                                nearest = std::min(nearest, glm::length(direction * (radius + height) - camera.position));
                        }
                }
            std::printf("%6.0f m up, roamed %.0f of the threshold: the detail on %d of %d patches; the nearest "
                        "point of the rest %.0f m away\n",
                        altitude, roam, count, (N - 1) * (N - 1), nearest);
            EXPECT_GT(nearest, range) << altitude << " m";
            // Not every patch: at 2 m the centre's block alone (64 patches of 9801).
            if (altitude < 1000.0) {
                EXPECT_LT(count, (N - 1) * (N - 1) / 10) << altitude << " m";
            }
        }
}

// The split draws the same picture as the detail's program on every patch, for a fraction of them.
TEST_F(TerrainCulling, TheDetailsRingsDrawTheSamePixelsAsTheDetailEverywhere) {
    const glm::ivec2 size{160, 90};
    for (const std::string view : {"ground", "beach", "mountains"}) {
        ImageRGBAF rings, everywhere;
        render(view, size, PatchOrder::NearFirst, rings);
        const int count = renderer->terrain().detailPatches();
        renderer->terrain().setDetailOnEveryPatch(true);
        render(view, size, PatchOrder::NearFirst, everywhere);
        renderer->terrain().setDetailOnEveryPatch(false);
        ASSERT_EQ(rings.pixels.size(), everywhere.pixels.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < rings.pixels.size(); ++i) differing += rings.pixels[i] != everywhere.pixels[i] ? 1 : 0;
        std::printf("%-9s the detail's program on %d of 9801 patches; %zu values differ from it on all\n", view.c_str(),
                    count, differing);
        EXPECT_GT(count, 0) << view;
        EXPECT_LT(count, 9801 / 10) << view;
        EXPECT_EQ(differing, 0u) << view;
    }
}

// The ground's material (terrain/ground_material.frag) runs once per pixel where the terrain's
// mesh is the nearest surface, not on the mesh's fragments (a software renderer shades a 4x4
// block for every triangle that touches it: `mountains` 1280x720 had 8 258 112 fragment
// invocations for its 921 600 pixels) and not on the rest of the ground's rectangle: a copy of
// the program that counts its invocations (an atomic add into a buffer of the test's), both of
// its builds (with and without the detail, each behind its own stencil value), counts exactly
// the pixels it wrote (a unit normal in the G-buffer; the rest stays cleared to 0), which are the
// pixels the mesh marked (the stencil's two values, read back with the ocean off: its pass clears
// the stencil) and those where it drew (a depth above the cleared 0). Able to fail:
// without `early_fragment_tests` (the shader then writes memory, and llvmpipe tests the stencil
// after it ran) each build runs on every pixel of the rectangle (checked below).
TEST_F(TerrainCulling, TheGroundsMaterialRunsOncePerGroundPixel) {
    const glm::ivec2 size{160, 90};
    const test::InvocationCounter counter;
    const std::filesystem::path withEarly =
        test::countingShaders("planet_test_ground_material_counted", "terrain/ground_material.frag", true);
    const std::filesystem::path withoutEarly =
        test::countingShaders("planet_test_ground_material_counted_late", "terrain/ground_material.frag", false);
    for (const std::string view : {"ground", "orbit"}) {
        SCOPED_TRACE(view);
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        s.scene.terrain.ocean = false;  // the stencil left as the terrain marked it
        auto invocations = [&](const std::filesystem::path& root, long long& ground, bool& detailed) {
            Renderer r(root, atmosphere::TableSizes::reduced(), s.continents);
            counter.reset();
            r.render(s.scene, s.camera, size);
            const ImageRGBAF normal = readTextureRGBAF(r.targets().gbuffer().normal, size.x, size.y);
            ground = 0;
            for (std::size_t i = 0; i < normal.pixels.size(); i += 4)
                ground += normal.pixels[i] != 0.0f || normal.pixels[i + 1] != 0.0f || normal.pixels[i + 2] != 0.0f;
            detailed = r.terrain().detailDrawn();
            const std::vector<GLubyte> stencil = test::readStencil(r.targets().gbuffer().depth, size);
            const std::vector<float> depth = test::readDepth(r.targets().gbuffer().depth, size);
            long long plain = 0, withDetail = 0, drawn = 0;
            for (std::size_t i = 0; i < stencil.size(); ++i) {
                plain += stencil[i] == TerrainPass::kPlainStencil;
                withDetail += stencil[i] == TerrainPass::kDetailedStencil;
                drawn += depth[i] > 0.0f;
            }
            EXPECT_EQ(plain + withDetail, ground);
            EXPECT_EQ(drawn, ground);
            EXPECT_EQ(withDetail > 0, r.terrain().detailDrawn());
            return counter.read();
        };
        long long ground = 0, groundLate = 0;
        bool detailed = false, detailedLate = false;
        const long long once = invocations(withEarly, ground, detailed);
        const long long late = invocations(withoutEarly, groundLate, detailedLate);
        std::printf("%-6s the ground's material ran %lld times for %lld ground pixels (%lld with the stencil tested "
                    "late); the detail's build %s\n",
                    view.c_str(), once, ground, late, detailed ? "drawn" : "not drawn");
        EXPECT_EQ(detailed, view == "ground");  // both builds at the ground
        EXPECT_GT(ground, size.x * size.y / 10);
        EXPECT_EQ(once, ground);
        EXPECT_EQ(groundLate, ground);
        EXPECT_GT(late, ground + size.x * size.y / 20);  // the check above can fail
    }
}

// Edges seen at a grazing angle split for what of them can show (grid/tessellation.glsl's
// edgeSegmentsShown, terrain/terrain.tesc): their apparent size on screen, or the relief their
// segments could show (the ground's slope at their ends, tripled, at least
// terrain.min_relief_slope), not their length as if seen face on (min_relief_slope 1). Against a
// mesh four times as fine (4 px, face on) the picture's error stays near the face-on mesh's: the
// mesh's points move the G-buffer's by a fraction of a triangle either way. Measured (640x360,
// reduced tables): ground 28 300 triangles against 83 500 face on, mean relative luminance error
// against the fine mesh 0.20 % against 0.09 %, p99 2.6 % against 2.2 %; mountains 129 000 against
// 135 000, 0.68 % against 0.62 %, p99 10.7 % against 9.3 %. Able to fail: the face-on rule draws
// as many triangles as before; the apparent size alone (no relief: margin and
// min_relief_slope 0) loses the distant range's ridges (mountains 45 000 triangles, mean 1.7 %,
// p99 37 %).
TEST_F(TerrainCulling, GrazingEdgesSplitForWhatTheyShow) {
    const glm::ivec2 size{640, 360};
    for (const std::string view : {"ground", "mountains"}) {
        ImageRGBAF shown, faceOn, fine;
        const TerrainPass::Statistics a = render(view, size, PatchOrder::NearFirst, shown);
        const TerrainPass::Statistics b = render(view, size, PatchOrder::NearFirst, faceOn, 1.0);
        render(view, size, PatchOrder::NearFirst, fine, 1.0, 4.0);
        const ImageComparison c = compareImages(shown, fine), d = compareImages(faceOn, fine);
        std::printf("%-9s %lld triangles as shown, %lld face on; against a 4 px mesh: mean relative luminance error "
                    "%.3f %% against %.3f %%, p99 %.3f %% against %.3f %%\n",
                    view.c_str(), a.primitives, b.primitives, 100.0 * c.meanRelativeError, 100.0 * d.meanRelativeError,
                    100.0 * c.errorPercentile(99.0), 100.0 * d.errorPercentile(99.0));
        EXPECT_EQ(c.nonFinitePixels, 0u);
        EXPECT_LT(c.meanRelativeError, d.meanRelativeError + 0.002) << view;
        EXPECT_LT(c.errorPercentile(99.0), 1.25 * d.errorPercentile(99.0) + 0.005) << view;
        if (a.primitives < 0) GTEST_SKIP() << "no primitive counts";
        EXPECT_LT(a.primitives, b.primitives) << view;
        if (view == "ground") {
            EXPECT_LT(a.primitives, 0.6 * b.primitives) << view;
        }
    }
}
