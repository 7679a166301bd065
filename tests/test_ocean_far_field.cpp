// Issue 15: where the whole sea is the ocean mesh's far field (src/ocean/far_field.h), the ocean
// pass draws ocean.frag's OCEAN_FAR_FIELD build once per pixel instead of the mesh. The test of
// when (against the sag worked by hand in both of the edge target's regimes), the grid's inverse
// that gives each pixel its place on the grid (terrain/grid.glsl's gridPointOf, on the GPU against
// the places it came from), and the frames with and without it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <limits>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "app/session.h"
#include "gl/handle.h"
#include "gl/program.h"
#include "gl_test_support.h"
#include "grid/constants.h"
#include "grid/grid_mesh.h"
#include "grid/projected_grid.h"
#include "ocean/far_field.h"
#include "ocean/ocean_block.h"
#include "ocean/ocean_gpu.h"
#include "ocean/ocean_pass.h"
#include "render/bindings.h"
#include "render/image_compare.h"
#include "render/readback.h"
#include "render/renderer.h"

using namespace planet;

namespace {

constexpr double kRadiusM = 6360e3;
const double kRadiansPerPixel = glm::radians(60.0) / 720.0;  // the views' 60 deg over 720 rows
constexpr double kTargetPx = 8.0, kCoarsestPx = 12.0;      // the default ocean's and terrain's targets

bool farAt(double heightM, double maxWaveM) {
    return ocean::seaIsFarField(heightM, kRadiansPerPixel, maxWaveM, kTargetPx, kCoarsestPx, kRadiusM);
}

}  // namespace

TEST(OceanFarField, BeginsWhereTheNearestChordSagsHalfAMetre) {
    // Low waves (1 m): at the threshold the crests span far under a quarter of a pixel, so the
    // edges aim at 4 x 8 = 32 px (above the terrain's 12): a chord d rpp 32 long sags
    // (d rpp 32)^2 / 8R = 0.5 m at d = sqrt(4R) / (32 rpp), and the nearest sea is the camera's
    // height less the crest.
    const double wave = 1.0;
    const double nearest = std::sqrt(4.0 * kRadiusM) / (32.0 * kRadiansPerPixel);
    ASSERT_GT(0.25 / (2.0 * wave / nearest / kRadiansPerPixel), 4.0) << "not the capped regime";
    EXPECT_TRUE(farAt((nearest + wave) * (1.0 + 1e-9), wave));
    EXPECT_FALSE(farAt((nearest + wave) * (1.0 - 1e-6), wave));
    // High waves (20 m): there the target is 8 x 0.25 d rpp / 2W = d rpp / W px (between 12 and 32),
    // a chord (d rpp)^2 / W m, sagging (d rpp)^4 / (8 R W^2) = 0.5 at d = (4 R W^2)^(1/4) / rpp.
    const double high = 20.0;
    const double d = std::pow(4.0 * kRadiusM * high * high, 0.25) / kRadiansPerPixel;
    const double edgePx = d * kRadiansPerPixel / high;
    ASSERT_GT(edgePx, kCoarsestPx);
    ASSERT_LT(edgePx, 32.0);
    EXPECT_NEAR(ocean::edgeTargetPixels(d, kRadiansPerPixel, high, kTargetPx), edgePx, 1e-9 * edgePx);
    EXPECT_TRUE(farAt((d + high) * (1.0 + 1e-9), high));
    EXPECT_FALSE(farAt((d + high) * (1.0 - 1e-6), high));
    // Never at or under the sea, nor for a height or a pixel that is not a number.
    EXPECT_FALSE(farAt(0.0, wave));
    EXPECT_FALSE(farAt(-1e9, wave));
    EXPECT_FALSE(farAt(0.5 * wave, wave));
    EXPECT_FALSE(farAt(std::numeric_limits<double>::quiet_NaN(), wave));
    EXPECT_FALSE(farAt(std::numeric_limits<double>::infinity(), wave));
    EXPECT_FALSE(ocean::seaIsFarField(1e9, 0.0, wave, kTargetPx, kCoarsestPx, kRadiusM));
}

namespace {

class OceanFarFieldGpu : public test::GLTest {};

// The lowest height above the sea at which seaIsFarField holds for `s`'s scene at `size` (bisection).
double farFieldHeight(const Session& s, glm::ivec2 size) {
    const double rpp = s.camera.fovY_rad / size.y;  // as src/render/renderer.cpp passes it
    const auto far = [&](double h) {
        return ocean::seaIsFarField(h, rpp, ocean::maxWaveHeight(s.scene.waves), s.scene.ocean.target_edge_px,
                                    ocean::makeOceanBlock(s.scene).coarsestEdgePixels, s.scene.planetRadiusM());
    };
    double lo = 0.0, hi = 1e7;
    for (int i = 0; i < 60; ++i) (far(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
    return hi;
}

// A copy of the shaders whose ocean.frag counts, into test::InvocationCounter's buffer, the mesh's
// fragments not wholly in the far field (farness < 1: their point is not only the sphere's).
std::filesystem::path nearFragmentCountingShaders() {
    const std::string farness = "    float farness = smoothstep(OCEAN_NEAR_FIELD_SAG_M, OCEAN_FAR_FIELD_SAG_M, sag);\n";
    const std::filesystem::path root = test::shadersWith("planet_test_ocean_near_fragments", "ocean/ocean.frag", farness,
                                                         farness + "    if (farness < 1.0) atomicAdd(testInvocations, 1u);\n");
    std::stringstream read;
    read << std::ifstream(root / "ocean/ocean.frag").rdbuf();
    std::string text = read.str();
    const std::string anchor = "const float SHORE_FADE_M";
    const std::size_t at = text.find(anchor);
    EXPECT_NE(at, std::string::npos);
    text.insert(at, test::invocationCountDeclaration());
    std::ofstream(root / "ocean/ocean.frag") << text;
    return root;
}

// The ocean's grid for `view`'s camera, as OceanPass::prepare makes it (stride 1).
GridBlock oceanGridFor(const Session& s) {
    GridParams params;
    params.size = s.scene.ocean.grid_size;
    params.exponent = grid_constant::OCEAN_GRID_EXPONENT;
    params.hysteresisFraction = s.scene.terrain.grid_hysteresis;
    const double radius = s.scene.planetRadiusM() + s.scene.ocean.sea_level_m;
    const double maxWave = ocean::maxWaveHeight(s.scene.waves);
    GridAnchor anchor;
    updateAnchor(anchor, s.camera, anchorThresholdM(params, glm::length(s.camera.position) - radius), false);
    return makeGridBlock(gridProjection(anchor, radius, maxWave), params.exponent, s.camera.position, radius,
                         params.size, 1);
}

}  // namespace

TEST_F(OceanFarFieldGpu, TheGridsInverseFindsThePlaceEachDirectionCameFrom) {
    const gl::Program program = gl::buildProgram(
        {std::filesystem::path(PLANET_SOURCE_DIR) / "shaders", gl::shaderPreamble()}, {"grid_probe", {"grid/grid_probe.comp"}});
    for (const std::string view : {"orbit", "space"}) {
        const Session s = loadSession(test::repoPaths(), "earth", view);
        const GridBlock block = oceanGridFor(s);
        const int n = block.pointsPerSide;
        ASSERT_GT(block.zShift, 0.0) << view;  // the far field's grids (gridPointOf's domain)
        // Every point of the grid and the middle of every cell but the outermost ring.
        std::vector<glm::vec2> places;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                places.emplace_back(i, j);
                if (i > 0 && j > 0 && i < n - 2 && j < n - 2) places.emplace_back(i + 0.5f, j + 0.25f);
            }
        gl::Buffer gridBuffer, input, output;
        glNamedBufferStorage(gridBuffer.id(), sizeof block, &block, 0);
        glNamedBufferStorage(input.id(), static_cast<GLsizeiptr>(places.size() * sizeof(glm::vec2)), places.data(), 0);
        glNamedBufferStorage(output.id(), static_cast<GLsizeiptr>(places.size() * sizeof(glm::vec2)), nullptr, 0);
        glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_GRID, gridBuffer.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_PROBE_INPUT, input.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_PROBE_OUTPUT, output.id());
        glUseProgram(program.id());
        glProgramUniform1i(program.id(), 0, static_cast<GLint>(places.size()));
        glDispatchCompute(static_cast<GLuint>((places.size() + 63) / 64), 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<glm::vec2> found(places.size());
        glGetNamedBufferSubData(output.id(), 0, static_cast<GLsizeiptr>(found.size() * sizeof(glm::vec2)), found.data());
        double worst = 0.0, worstInner = 0.0;
        for (std::size_t k = 0; k < places.size(); ++k) {
            const double e = glm::length(glm::dvec2(found[k] - places[k]));
            worst = std::max(worst, e);
            const glm::vec2 p = places[k];
            if (p.x >= 1 && p.y >= 1 && p.x <= n - 2 && p.y <= n - 2) worstInner = std::max(worstInner, e);
        }
        std::printf("%-5s grid %d x %d, z_s %.3f: places found within %.2e points (%.2e off the outer ring)\n",
                    view.c_str(), n, n, block.zShift, worst, worstInner);
        // A hundredth of a cell: the grid's reflection, read bilinearly between the points, changes
        // by far less than the frame's rounding over that.
        EXPECT_LT(worstInner, 0.01) << view;
        EXPECT_LT(worst, 0.05) << view;
    }
}

TEST_F(OceanFarFieldGpu, TheFarFieldGivesTheMeshsFrame) {
    Renderer renderer(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    const glm::ivec2 size{320, 180};
    // "threshold": the orbit view's camera lowered to 2 % above the height where the far field
    // begins at this size (found from seaIsFarField by bisection), where the switch between the
    // two happens as a camera descends: no seam there either.
    for (const std::string view : {"orbit", "space", "threshold", "deck", "sea"}) {
        Session s = loadSession(test::repoPaths(), "earth", view == "threshold" ? "orbit" : view);
        s.scene.render.temporal = false;
        if (view == "threshold") {
            const double radius = s.scene.planetRadiusM() + s.scene.ocean.sea_level_m;
            const double h = farFieldHeight(s, size);
            std::printf("the far field begins %.1f km above the sea at %dx%d\n", h / 1000.0, size.x, size.y);
            s.camera.position = glm::normalize(s.camera.position) * (radius + 1.02 * h);
        }
        renderer.ocean().setCountPrimitives(true);
        renderer.ocean().setFarFieldAllowed(true);
        renderer.render(s.scene, s.camera, size);
        const bool far = renderer.ocean().farField();
        const long long farPrimitives = renderer.ocean().lastPrimitives();
        const ImageRGBAF a = readTextureRGBAF(renderer.targets().hdr(), size.x, size.y);
        renderer.ocean().setFarFieldAllowed(false);
        renderer.render(s.scene, s.camera, size);
        const long long meshPrimitives = renderer.ocean().lastPrimitives();
        const ImageRGBAF b = readTextureRGBAF(renderer.targets().hdr(), size.x, size.y);
        const ImageComparison c = compareImages(a, b);
        std::printf("%-5s far field %s: %lld ocean primitives (the mesh: %lld); frame mean %.4f %%, p99 %.3f %%, "
                    "max %.2f %%\n",
                    view.c_str(), far ? "yes" : "no", farPrimitives, meshPrimitives, 100 * c.meanRelativeError,
                    100 * c.errorPercentile(99), 100 * c.maxRelativeError);
        EXPECT_TRUE(test::allFinite(a)) << view;
        if (view == "orbit" || view == "space" || view == "threshold") {
            EXPECT_TRUE(far) << view;
            EXPECT_EQ(farPrimitives, 0) << view << ": no mesh drawn";
            EXPECT_GT(meshPrimitives, 0) << view;
            EXPECT_LT(c.meanRelativeError, 0.0005) << view;
            EXPECT_LT(c.errorPercentile(99), 0.01) << view;
        } else {
            EXPECT_FALSE(far) << view << ": waves or the mesh's own points show";
            EXPECT_EQ(farPrimitives, meshPrimitives) << view;
            EXPECT_EQ(c.meanRelativeError, 0.0) << view;
        }
    }
}

// The CPU's test against the shader's own: the mesh's fragments (the mesh forced) that are not
// wholly in the far field, counted by a copy of ocean.frag, looking straight down at the open sea
// (the nearest sea in view): none just above the height where seaIsFarField begins to hold, some
// just below it (the test is no looser than need be), for the default sea and a stormy one (the
// edge target's other regime). And from so far out that the grid's z_s < 0 (past gridPointOf's
// domain) the mesh again, with a finite frame.
TEST_F(OceanFarFieldGpu, TheCpusTestAgreesWithTheMeshsFarness) {
    const test::InvocationCounter counter;
    Renderer renderer(nearFragmentCountingShaders(), atmosphere::TableSizes::reduced());
    renderer.ocean().setFarFieldAllowed(false);
    const glm::ivec2 size{160, 90};
    Session base = loadSession(test::repoPaths(), "earth", "orbit");
    base.scene.render.temporal = false;
    base.scene.clouds.enabled = false;
    // A nadir over the open sea near the orbit view's.
    double lat = 20.0, lon = -10.0;
    for (int tries = 0; tries < 40; ++tries, lon -= 3.0) {
        const Camera c = cameraAtGeographic(lat, lon, 1e5, 0.0, -90.0, 60.0, base.scene.planetRadiusM());
        if (base.ground.height(glm::vec3(glm::normalize(c.position))) < -1000.0f) break;
    }
    ASSERT_LT(base.ground.height(glm::vec3(glm::normalize(
                  cameraAtGeographic(lat, lon, 1e5, 0.0, -90.0, 60.0, base.scene.planetRadiusM()).position))),
              -1000.0f);
    for (const double waveScale : {1.0, 8.0}) {
        Session s = base;
        for (auto& w : s.scene.waves) w.amplitude_m *= waveScale;
        const double h = farFieldHeight(s, size);
        long long counts[2] = {0, 0};
        for (int i = 0; i < 2; ++i) {
            const double height = h * (i == 0 ? 1.001 : 0.98);
            s.camera = cameraAtGeographic(lat, lon, height + s.scene.ocean.sea_level_m, 0.0, -90.0, 60.0,
                                          s.scene.planetRadiusM());
            counter.reset();
            renderer.render(s.scene, s.camera, size);
            counts[i] = counter.read();
        }
        std::printf("waves x%.0f: the far field from %.1f km: fragments not wholly in it %lld at 1.001 x, %lld at "
                    "0.98 x\n",
                    waveScale, h / 1000.0, counts[0], counts[1]);
        EXPECT_EQ(counts[0], 0) << "waves x" << waveScale;
        EXPECT_GT(counts[1], 0) << "waves x" << waveScale;
    }
    Session s = base;
    s.camera = cameraAtGeographic(0.0, 0.0, 2e8, 0.0, -90.0, 60.0, s.scene.planetRadiusM());
    Renderer plain(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    plain.render(s.scene, s.camera, size);
    EXPECT_FALSE(plain.ocean().farField()) << "z_s < 0 out there: the mesh";
    EXPECT_TRUE(test::allFinite(readTextureRGBAF(plain.targets().hdr(), size.x, size.y)));
}
