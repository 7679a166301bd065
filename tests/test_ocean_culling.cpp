// Issue 15: the sea is not drawn where there is none. Patches over land are dropped in the
// ocean's control stage and fragments under land or behind the terrain are discarded before
// the water is shaded (src/ocean/land_cull.h, shaders/ocean/ocean.tesc, ocean.frag): the
// pixels must be exactly those of the frame without it, in views with sea, shore and land, and
// the inland ground view must draw far fewer ocean primitives.
#include <cmath>
#include <random>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "app/session.h"
#include "gl_test_support.h"
#include "noise/continents.h"
#include "ocean/land_cull.h"
#include "ocean/ocean_pass.h"
#include "render/image_compare.h"
#include "render/readback.h"
#include "render/renderer.h"
#include "terrain/height.h"

using namespace planet;

namespace {

constexpr glm::ivec2 kSize{160, 90};

class OceanCulling : public test::GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    }
    // One frame of `view` at full rate (no history: both frames alike), with or without land
    // culling; the primitives the ocean pass emitted.
    ImageRGBAF render(const std::string& view, bool culling, long long& primitives, glm::ivec2 size = kSize,
                      int* patchesDrawn = nullptr) {
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        renderer->ocean().setLandCulling(culling);
        renderer->ocean().setCountPrimitives(true);
        renderer->render(s.scene, s.camera, size);
        primitives = renderer->ocean().lastPrimitives();
        if (patchesDrawn) *patchesDrawn = renderer->ocean().patchesDrawn();
        return readTextureRGBAF(renderer->targets().hdr(), size.x, size.y);
    }
    std::unique_ptr<Renderer> renderer;
};

}  // namespace

TEST_F(OceanCulling, SamePixelsWithFewerOceanPrimitivesInland) {
    for (const std::string view : {"ground", "beach", "sea"}) {
        long long all = 0, culled = 0;
        int patchesAll = 0, patchesCulled = 0;  // drawn: the runs over land are left out on the CPU too
        const ImageRGBAF before = render(view, false, all, kSize, &patchesAll);
        const ImageRGBAF after = render(view, true, culled, kSize, &patchesCulled);
        ASSERT_EQ(before.pixels.size(), after.pixels.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < before.pixels.size(); ++i) differing += before.pixels[i] != after.pixels[i] ? 1 : 0;
        std::printf("%-7s ocean primitives %lld without culling, %lld with (patches drawn %d, %d); %zu of %zu values "
                    "differ\n", view.c_str(), all, culled, patchesAll, patchesCulled, differing, before.pixels.size());
        EXPECT_EQ(differing, 0u) << view << ": land culling changed the picture";
        EXPECT_GT(all, 0) << view;
        EXPECT_LE(patchesCulled, patchesAll) << view;
        if (view == "ground") {  // (the beach and the sea: sea in every run in view)
            EXPECT_LT(culled, all / 4) << "the inland view still draws most of its sea";
            EXPECT_LT(patchesCulled, patchesAll / 2) << "the inland view still draws most of its runs";
        }
        else EXPECT_GT(culled, 0) << view << ": the sea was culled away";
    }
}

TEST_F(OceanCulling, TheBoundsHoldOnTheMap) {
    Session s = loadSession(test::repoPaths(), "earth", "beach");
    const noise::CubeMap& map = s.ground.continents();
    const double lipschitz = ocean::continentLipschitz(map);
    const double maxWave = 3.0;
    const double threshold = ocean::landContinentThreshold(s.scene.terrain, 0.0, maxWave);
    std::printf("map %d, slope bound %.3f per radian, land at e >= %.5f\n", map.size, lipschitz, threshold);
    ASSERT_GT(threshold, 0.0);
    ASSERT_LT(threshold, 1.0);
    // Above the threshold the ground stands above the highest crest, whatever the mountains.
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int land = 0;
    double worstSlope = 0.0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        const float e = terrain::continentValue(glm::vec3(d), map);
        if (e >= threshold) {
            ++land;
            EXPECT_GT(terrain::terrainHeight(glm::vec3(d), s.ground.shape(), map), maxWave) << "e " << e;
        }
        // The filtered map's slope between nearby points, against the bound.
        const double angle = 1e-3 * (1.0 + unit(rng));
        glm::dvec3 side = glm::normalize(glm::cross(d, glm::dvec3(unit(rng), unit(rng), unit(rng))));
        const glm::dvec3 d2 = std::cos(angle) * d + std::sin(angle) * side;
        const double slope = std::abs(noise::sampleContinents(map, d2).x - noise::sampleContinents(map, d).x) / angle;
        worstSlope = std::max(worstSlope, slope);
    }
    std::printf("%d land samples; steepest filtered slope seen %.3f per radian\n", land, worstSlope);
    EXPECT_GT(land, 1000);
    EXPECT_LE(worstSlope, lipschitz);
    EXPECT_GT(worstSlope, 0.1 * lipschitz) << "the bound is far looser than it need be";
}

TEST_F(OceanCulling, WhereTheWavesCannotShowTheSeaTakesLargerTriangles) {
    // Where even the highest crest is under a quarter of a pixel on screen, the ocean's edges aim
    // at up to four times ocean.target_edge_px (ocean/ocean.tesc): from orbit and space far fewer
    // primitives, the same picture to within the mesh's sub-pixel sag; near the camera (the sea
    // view's foreground) the waves show and the mesh stays as fine. Against the same shaders with
    // the factor at 1 (the fixed target).
    const std::filesystem::path fixedTarget =
        test::shadersWith("planet_ocean_fixed_target", "grid/constants.glsl", "const float OCEAN_FAR_EDGE_FACTOR = 4.0;",
                          "const float OCEAN_FAR_EDGE_FACTOR = 1.0;");
    Renderer fixed(fixedTarget, atmosphere::TableSizes::reduced());
    // The mesh itself, also where the whole sea is its far field (src/ocean/far_field.h).
    renderer->ocean().setFarFieldAllowed(false);
    fixed.ocean().setFarFieldAllowed(false);
    // At 160x90 the grid's patches from orbit span under 8 pixels: already one triangle pair each.
    const glm::ivec2 size{640, 360};
    for (const std::string view : {"orbit", "space", "sea"}) {
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        long long coarse = 0, fine = 0;
        renderer->ocean().setCountPrimitives(true);
        renderer->render(s.scene, s.camera, size);
        coarse = renderer->ocean().lastPrimitives();
        const ImageRGBAF a = readTextureRGBAF(renderer->targets().hdr(), size.x, size.y);
        fixed.ocean().setCountPrimitives(true);
        fixed.render(s.scene, s.camera, size);
        fine = fixed.ocean().lastPrimitives();
        const ImageRGBAF b = readTextureRGBAF(fixed.targets().hdr(), size.x, size.y);
        const ImageComparison c = compareImages(a, b);
        std::printf("%-6s ocean primitives %lld at the fixed target, %lld coarser where the waves cannot show; frame "
                    "mean %.4f %%, p99 %.3f %%, max %.2f %%\n",
                    view.c_str(), fine, coarse, 100 * c.meanRelativeError, 100 * c.errorPercentile(99),
                    100 * c.maxRelativeError);
        EXPECT_GT(fine, 0) << view;
        // Measured on llvmpipe at 640x360, with the grids' stride from high up (src/grid/grid_stride.h):
        // orbit 20426 -> 4666 (frame mean 0.005 %, p99 0.09 %), space 10416 -> 6408 (0.008 %; the
        // limb's band keeps a segment per grid cell either way), sea 117970 -> 99992 (the far sea;
        // 0.0000 %). Before the stride: orbit 36640 -> 3832, space 31074 -> 12482.
        if (view == "sea") EXPECT_GT(coarse, fine / 2) << "the near sea keeps its fine mesh";
        else EXPECT_LT(coarse, view == "orbit" ? fine / 4 : fine * 3 / 4) << view;
        EXPECT_LT(c.meanRelativeError, 0.001) << view;
        EXPECT_LT(c.errorPercentile(99), 0.01) << view;
    }
}

// Issue 15: where the sea is drawn over the ground from above, the terrain leaves out the sea
// floor's dark depths (shaders/terrain/terrain.tesc; src/ocean/land_cull.h's
// darkFloorContinentThreshold): the frame is the one with the whole floor drawn, to the bit on
// llvmpipe (the ocean's water path there from the depth below the sea), with none of the open
// sea's floor drawn and part of the beach's (from orbit the grid's patches, hundreds of kilometres
// across, are too large for the map's slope bound: the continents' maxima over their parts, src/
// terrain/continent_bound.h, leave out most of the open sea's floor). Able to fail: a threshold
// that lets the shelf go shows its floor missing through the shallow water (the beach), and a
// water path left at 1e30 m where no floor was drawn cancelled to none (orbit: the open sea
// 12 % darker).
TEST_F(OceanCulling, TheDarkDepthsOfTheSeaFloorAreNotDrawnAndThatChangesNoPixel) {
    // orbit at 1280x720: its grid's stride leaves patches that the 4x4 parts' bound drops
    // (terrain/patch_continents.glsl: the slope bound left 42 % of the fragments, the maxima 11 %);
    // at 160x90 the patches are larger still: the maxima leave out a quarter.
    for (const std::string view : {"orbit", "orbit1280", "sea", "beach"}) {
        SCOPED_TRACE(view);
        const std::string name = view == "orbit1280" ? "orbit" : view;
        const glm::ivec2 size = view == "orbit1280" ? glm::ivec2(1280, 720) : kSize;
        long long primitives = 0;
        renderer->terrain().setStatistics(true);
        renderer->setDarkFloorCulling(false);
        const ImageRGBAF whole = render(name, true, primitives, size);
        const long long wholePatches = renderer->terrain().lastStatistics().patches;
        const long long wholeFragments = renderer->terrain().lastStatistics().fragments;
        renderer->setDarkFloorCulling(true);
        const ImageRGBAF culled = render(name, true, primitives, size);
        const long long culledFragments = renderer->terrain().lastStatistics().fragments;
        const ImageComparison c = compareImages(culled, whole);
        std::printf("%-6s terrain fragments %lld with the whole floor, %lld without its dark depths (%lld patches); "
                    "mean %.6f %%, max %.4f %%\n",
                    view.c_str(), wholeFragments, culledFragments, wholePatches, 100.0 * c.meanRelativeError,
                    100.0 * c.maxRelativeError);
        EXPECT_EQ(c.nonFinitePixels, 0u);
        EXPECT_LT(c.meanRelativeError, 1e-6);
        EXPECT_LT(c.maxRelativeError, 1e-4);
        if (view == "sea") {
            EXPECT_LT(culledFragments, wholeFragments / 10) << "the open sea's floor is dark";
        } else if (view == "beach") {
            EXPECT_LT(culledFragments, wholeFragments) << "the sea floor beyond the shelf is dark";
            EXPECT_GT(culledFragments, wholeFragments / 2) << "the beach's floor is shallow";
        } else if (view == "orbit1280") {
            EXPECT_LT(culledFragments, wholeFragments / 5) << "the continents' maxima drop the open sea's floor";
        } else {  // 160x90
            EXPECT_LT(culledFragments, wholeFragments) << "the continents' maxima drop some of the open sea's floor";
        }
    }
    renderer->terrain().setStatistics(false);
}

TEST_F(OceanCulling, TheDarkFloorsThresholdHoldsOnTheHeightField) {
    Session s = loadSession(test::repoPaths(), "earth", "beach");
    const double threshold = ocean::darkFloorContinentThreshold(s.scene.terrain, 0.0);
    std::printf("the sea floor is dark (%.0f m down) below e = %.5f\n", ocean::kSeaFloorDarkDepthM, threshold);
    ASSERT_GT(threshold, -1.0);
    ASSERT_LT(threshold, 0.0);
    // Below it the ground is deeper than the dark depth; just above it, not (the bound is tight).
    const noise::CubeMap& map = s.ground.continents();
    std::mt19937 rng(16);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int dark = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 d(glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng))));
        if (terrain::continentValue(d, map) >= threshold) continue;
        ++dark;
        EXPECT_LT(terrain::terrainHeight(d, s.ground.shape(), map), -ocean::kSeaFloorDarkDepthM);
    }
    EXPECT_GT(dark, 1000);
    terrain::TerrainShape shape = s.ground.shape();
    noise::CubeMap uniform;
    uniform.size = 1;
    uniform.texels.assign(6, glm::vec4(float(threshold + 0.01), 0.0f, 0.0f, 0.0f));
    EXPECT_GT(terrain::terrainHeight(glm::vec3(0, 0, 1), shape, uniform), -ocean::kSeaFloorDarkDepthM);
    // The shader's constant is this one.
    std::ifstream water(test::repoPaths().shaders() / "ocean/water.glsl");
    const std::string text((std::istreambuf_iterator<char>(water)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("const float SEA_FLOOR_DARK_DEPTH_M = 400.0;"), std::string::npos);
}

// The water's light (ocean/sea_light.frag) runs once per pixel where the ocean's mesh left the
// sea as the nearest surface, not on the mesh's fragments (a software renderer shades a 4x4 block
// for every triangle that touches it: orbit 1280x720 had 983 344 fragment invocations for its
// sea's pixels) and not on the rest of the ground's rectangle: a copy of the program that counts
// its invocations (an atomic add into a buffer of the test's) counts exactly the pixels it wrote
// (its reflected ray; the rest stays cleared to 0), with the early stencil test, and those are the
// pixels the mesh marked (from orbit the far field's per-pixel draw, src/ocean/far_field.h, which
// marks them as the mesh does; the stencil's OceanPass::kSeaStencil, read back), each where the sea's
// depth replaced the seabed's (a mark where the mesh drew nothing would fail that). Able
// to fail: without `early_fragment_tests` llvmpipe tests the stencil after a shader that writes
// memory has run, and the copy counts every pixel of the rectangle (checked below).
TEST_F(OceanCulling, TheSeasLightRunsOncePerSeaPixel) {
    const test::InvocationCounter counter;
    const std::filesystem::path withEarly =
        test::countingShaders("planet_test_sea_light_counted", "ocean/sea_light.frag", true);
    const std::filesystem::path withoutEarly =
        test::countingShaders("planet_test_sea_light_counted_late", "ocean/sea_light.frag", false);
    for (const std::string view : {"orbit", "beach"}) {
        SCOPED_TRACE(view);
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        auto invocations = [&](const std::filesystem::path& root, long long& marked) {
            Renderer r(root, atmosphere::TableSizes::reduced(), s.continents);
            // The targets made by a first frame, the reflection's emptied (the ocean pass leaves
            // it to the light where no pass reads it past the sea: a flat mirror, from orbit).
            r.render(s.scene, s.camera, kSize);
            r.targets().clearSeaReflection();
            counter.reset();
            r.render(s.scene, s.camera, kSize);
            // The light writes the reflected ray (a unit vector) at every sea pixel, 0 elsewhere.
            const ImageRGBAF reflection = readTextureRGBAF(r.targets().seaReflection(), kSize.x, kSize.y);
            marked = 0;
            for (std::size_t i = 0; i < reflection.pixels.size(); i += 4) {
                const float* ray = &reflection.pixels[i];
                marked += ray[0] != 0.0f || ray[1] != 0.0f || ray[2] != 0.0f;
            }
            const std::vector<GLubyte> stencil = test::readStencil(r.targets().gbuffer().depth, kSize);
            const std::vector<float> depth = test::readDepth(r.targets().gbuffer().depth, kSize);
            const std::vector<float> seabed = test::readDepth(r.targets().seabedDepth(), kSize);
            long long stencilled = 0, markedWithoutSea = 0;
            for (std::size_t i = 0; i < stencil.size(); ++i) {
                if ((stencil[i] & OceanPass::kSeaStencilBits) != OceanPass::kSeaStencil) continue;  // (the open sea too)
                ++stencilled;
                markedWithoutSea += depth[i] == seabed[i];
            }
            EXPECT_EQ(stencilled, marked);
            EXPECT_EQ(markedWithoutSea, 0);
            return counter.read();
        };
        long long marked = 0, markedLate = 0;
        const long long once = invocations(withEarly, marked);
        const long long late = invocations(withoutEarly, markedLate);
        std::printf("%-6s the sea's light ran %lld times for %lld sea pixels (%lld with the stencil tested late)\n",
                    view.c_str(), once, marked, late);
        EXPECT_GT(marked, kSize.x * kSize.y / 10);
        EXPECT_EQ(once, marked);
        EXPECT_EQ(markedLate, marked);
        EXPECT_GT(late, marked + kSize.x * kSize.y / 20);  // the check above can fail
    }
}
