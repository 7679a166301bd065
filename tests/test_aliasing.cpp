// Aliasing (issue 13): the small version of scripts/aliasing.sh, on the `planet render`
// command as a user runs it.
//
// Method: a view is rendered at 160x90 (the still judged) and at 640x360 with one
// unjittered sample (the reference); the reference is averaged 4x4 down (boxDownsample:
// 16 samples on a regular grid in each small pixel, a box filter) and the still's mean
// relative luminance error against it is measured (render/image_compare.h, floor 1 % of
// the mean). The error is what a pixel's single point sample misses of the mean over its
// area -- edges of the planet's limb, ridges, the sea's glints, materials that change
// faster than a pixel -- plus whatever the two sizes draw differently (the terrain's and
// the sea's grids are denser at 640x360, the clouds' march follows the pixel footprint),
// which no filter in the small frame removes; the bounds below sit above that floor.
//
// The still is rendered twice: with --samples 1 (one unjittered frame, the frame without
// anti-aliasing) and with the command's default (kStillSamples jittered frames averaged in
// linear HDR, render_command.cpp). Both errors are printed; the default's must stay under
// an absolute bound per view and under a fraction of the single sample's, so a still that
// stops being anti-aliased (jitter not applied, applied differently in different passes,
// samples not averaged) fails. Measured when the bounds were set (llvmpipe, reduced
// tables, the shaders of 3cd79eb; docs/PERFORMANCE.md "Aliasing (issue 13)"):
//
//   view        --samples 1   default (4)   16 samples
//   mountains   3.50 %        3.03 %        2.87 %
//   space       1.99 %        1.04 %
//
// In `mountains` most of the error is not aliasing that a pixel filter removes: 16 samples
// still leave 2.87 %, what 160x90 and 640x360 draw differently (the terrain's tessellation
// and its noise octaves follow the pixel size; the small frame is 1 % darker on average).
// The default removes three quarters of the part that sampling can remove (3.50 -> 3.03 of
// 3.50 -> 2.87), hence a bound of 3.25 % there, which the single sample fails. In `space`
// the limb and the clouds are the aliasing: 1.5 %, and at most 0.8 x the single sample's
// (the limb is geometry that only the samples smooth). Mountains has no share-of-single
// check: footprint filtering of the terrain's materials and normals (issue 13,
// shaders/terrain) removes from the single sample the same error the samples remove, so
// the two columns will approach each other; it lowers both, so lower the bounds with it.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "app/commands.h"
#include "process.h"
#include "render/frame_uniforms.h"
#include "render/image_compare.h"
#include "render/image_io.h"
#include "scene/camera.h"

namespace fs = std::filesystem;

namespace {

using planet::test::runCommand;

// Bounds on the default still's mean relative luminance error at 160x90 against 640x360
// averaged 4x4, absolute and as a share of the single sample's (figures: the top of the file).
// Measured 3.03 % (--samples 1: 3.50 %); 3.04 % with the footprint filtering and shadows (the
// mountains without the ground detail: MountainsStillIsAntiAliased).
constexpr double kMountainsBound = 0.0325;
constexpr double kSpaceBound = 0.015;        // measured 1.04 % (--samples 1: 1.99 %)
constexpr double kSpaceShareOfSingle = 0.8;  // measured 0.52

class AliasingTest : public planet::test::CliFixture {
protected:
    void SetUp() override {
        CliFixture::SetUp();
        shareCloudCache();
    }

    // Renders `view` with `args` to NAME.exr in the test's folder and reads it back.
    planet::ImageRGBAF render(const std::string& view, const std::string& size, const std::string& args,
                              const std::string& name) {
        const auto r = runCommand(planet("render --tables reduced --view " + view + " --size " + size + " " + args +
                                         " --out " + name + ".exr"));
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return planet::readExr(dir / (name + ".exr"));
    }

    // The shipped preset with terrain.detail set to `on`, written to the test's folder: its path.
    std::string earthWithDetail(bool on) {
        std::ifstream in(std::string(PLANET_SOURCE_DIR) + "/assets/presets/earth.toml");
        std::string preset((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::size_t at = preset.find("\ndetail = true\n");
        EXPECT_NE(at, std::string::npos) << "earth.toml has no 'detail = true' line";
        if (at != std::string::npos) preset.replace(at, 15, on ? "\ndetail = true\n" : "\ndetail = false\n");
        const fs::path path = dir / (on ? "detail-on.toml" : "detail-off.toml");
        std::ofstream(path) << preset;
        return path.string();
    }

    struct Errors {
        double singleSample = 0.0;  // --samples 1
        double accumulated = 0.0;   // the default
    };
    // `small` is judged against 4x its size (`large`) averaged 4x4.
    Errors measure(const std::string& view, const std::string& args = "", const std::string& small = "160x90",
                   const std::string& large = "640x360") {
        const planet::ImageRGBAF reference =
            planet::boxDownsample(render(view, large, args + " --samples 1", view + "-reference"), 4);
        const planet::ImageRGBAF single = render(view, small, args + " --samples 1", view + "-s1");
        const planet::ImageRGBAF accumulated = render(view, small, args, view + "-default");
        const planet::ImageComparison a = planet::compareImages(single, reference);
        const planet::ImageComparison b = planet::compareImages(accumulated, reference);
        EXPECT_EQ(a.nonFinitePixels, 0u);
        EXPECT_EQ(b.nonFinitePixels, 0u);
        planet::writeDifferenceImage(b, accumulated, reference, dir / (view + "-default-error.png"));
        std::printf("aliasing %s %s against %s averaged 4x4: mean relative luminance error %.2f %% with "
                    "--samples 1, %.2f %% with the default (%d samples)\n",
                    view.c_str(), small.c_str(), large.c_str(), 100.0 * a.meanRelativeError, 100.0 * b.meanRelativeError,
                    planet::kStillSamples);
        return {a.meanRelativeError, b.meanRelativeError};
    }
};

}  // namespace

TEST(StillJitterTest, SamplesAreCentredOnThePixelAndInsideIt) {
    EXPECT_EQ(planet::stillSampleJitter(0, 1), glm::dvec2(0.0));  // one sample: unjittered
    for (int n : {2, 4, 8, 16, 32}) {
        glm::dvec2 mean(0.0);
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 j = planet::stillSampleJitter(i, n);
            EXPECT_LT(std::abs(j.x), 0.75) << n;
            EXPECT_LT(std::abs(j.y), 0.75) << n;
            mean += j / double(n);
        }
        EXPECT_NEAR(mean.x, 0.0, 1e-12) << n;
        EXPECT_NEAR(mean.y, 0.0, 1e-12) << n;
    }
}

TEST(StillJitterTest, EveryPassSeesTheSameJitteredProjection) {
    // A point in front of the camera lands jitter pixels from where the unjittered frame
    // puts it, and the ray the full-screen passes cast through a pixel (viewFromClip) is the
    // ray through the point the rasteriser samples there.
    planet::Scene scene;
    planet::Camera camera;
    camera.position = glm::dvec3(6371.0e3 + 500.0, 0.0, 0.0);
    camera.orientation = planet::orientationFromAxes({0, 1, 0}, {1, 0, 0}, glm::normalize(glm::dvec3(-0.1, 0.0, -1.0)));
    const glm::ivec2 size{160, 90};
    const glm::dvec2 jitter(0.3, -0.2);
    const planet::FrameUniforms plain = planet::makeFrameUniforms(scene, camera, size, 0, std::nullopt);
    const planet::FrameUniforms moved = planet::makeFrameUniforms(scene, camera, size, 0, std::nullopt, jitter);
    EXPECT_EQ(plain.jitter, glm::vec2(0.0f));
    EXPECT_EQ(moved.jitter, glm::vec2(jitter));
    const glm::vec4 view(2.0f, -1.0f, -50.0f, 1.0f);
    const glm::vec4 a = plain.clipFromView * view, b = moved.clipFromView * view;
    const glm::vec2 pixelsA = (glm::vec2(a) / a.w) * 0.5f * glm::vec2(size);
    const glm::vec2 pixelsB = (glm::vec2(b) / b.w) * 0.5f * glm::vec2(size);
    EXPECT_NEAR(pixelsB.x - pixelsA.x, jitter.x, 1e-3);
    EXPECT_NEAR(pixelsB.y - pixelsA.y, jitter.y, 1e-3);
    EXPECT_NEAR(b.z / b.w, a.z / a.w, 1e-7);  // depth is not moved
    // worldRayFromNdc: viewFromClip at a pixel centre's NDC, depth 0.5.
    const glm::vec2 ndc = glm::vec2(b) / b.w;
    const glm::vec4 back = moved.viewFromClip * glm::vec4(ndc, 0.5f, 1.0f);
    const glm::vec3 ray = glm::normalize(glm::vec3(back) / back.w);
    EXPECT_GT(glm::dot(ray, glm::normalize(glm::vec3(view))), 1.0f - 1e-6f);
    // The previous frame's jitter goes into its reprojection.
    const planet::FrameUniforms next =
        planet::makeFrameUniforms(scene, camera, size, 1, planet::PreviousFrame{camera, size, 0.0, {}, jitter});
    const glm::vec4 world = moved.worldFromView * view;
    const glm::vec4 p = next.previousClipFromWorld * glm::vec4(glm::vec3(world), 1.0f);
    EXPECT_NEAR(p.x / p.w, ndc.x, 1e-5);
    EXPECT_NEAR(p.y / p.w, ndc.y, 1e-5);
}

TEST(BoxDownsampleTest, AveragesEachBlock) {
    planet::ImageRGBAF image{4, 2, std::vector<float>(4 * 2 * 4)};
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(i / 4);  // pixel index, all channels
    const planet::ImageRGBAF half = planet::boxDownsample(image, 2);
    ASSERT_EQ(half.width, 2);
    ASSERT_EQ(half.height, 1);
    EXPECT_FLOAT_EQ(half.pixels[0], (0 + 1 + 4 + 5) / 4.0f);
    EXPECT_FLOAT_EQ(half.pixels[4], (2 + 3 + 6 + 7) / 4.0f);
    EXPECT_THROW(planet::boxDownsample(image, 3), std::invalid_argument);
    EXPECT_THROW(planet::boxDownsample(image, 0), std::invalid_argument);
}

// The frame's anti-aliasing without the ground detail (terrain.detail, on by default): at
// 160x90 the detail's 32 m scale puts 1-2 m waves at the frame's Nyquist limit 20-90 m from
// the camera, which a mip filter cannot match to a box (next test); its own check is at the
// issue's sizes, below.
TEST_F(AliasingTest, MountainsStillIsAntiAliased) {
    const Errors e = measure("mountains", "--preset " + earthWithDetail(false));
    EXPECT_LT(e.accumulated, kMountainsBound);
    EXPECT_LT(e.accumulated, e.singleSample);
}

// With the ground detail (the default), at the issue's own sizes: 640x360 against 2560x1440
// averaged 4x4, under the figure the issue was filed with (2.9 %, no detail and no
// filtering). Measured 2.29 % (2.33 % with medium tables; docs/PERFORMANCE.md, 2026-12-05; the
// detail off: 1.01 %). At
// 160x90 against 640x360 the detail is 4.3 % off (3.0 % without): the frame is too small for
// its 32 m scale (above). History at 160x90: 7.96 % as first built, 5.85 % before its filter
// handed the slopes' removed spread to the lighting (the expected clamped cosine,
// terrain/rough_cosine.glsl) and the tile's longest waves were dropped, 4.95 % after, 3.84 %
// once the slopes were gentle enough for the lighting to be linear in them, 4.0-4.3 % with
// two anisotropic taps instead of four and one Newton step, only where the finest scale
// shows, instead of up to four everywhere (the terrain pass 2.3-3.7x -> 1.7-2.3x the
// pass without the detail; docs/PERFORMANCE.md, 2026-12-05).
constexpr double kMountainsWithDetailAtIssueSizeBound = 0.026;

TEST_F(AliasingTest, MountainsStillWithTheGroundDetailAtTheIssuesSizes) {
    const Errors e = measure("mountains", "--preset " + earthWithDetail(true), "640x360", "2560x1440");
    EXPECT_LT(e.accumulated, kMountainsWithDetailAtIssueSizeBound);
    EXPECT_LT(e.accumulated, e.singleSample);
}

TEST_F(AliasingTest, SpaceStillIsAntiAliased) {
    const Errors e = measure("space");
    EXPECT_LT(e.accumulated, kSpaceBound);
    EXPECT_LT(e.accumulated, kSpaceShareOfSingle * e.singleSample);
}

namespace {

// Rows [first, first + count) of an image.
planet::ImageRGBAF rowBand(const planet::ImageRGBAF& image, int first, int count) {
    planet::ImageRGBAF band;
    band.width = image.width;
    band.height = count;
    const auto begin = image.pixels.begin() + std::ptrdiff_t(first) * image.width * 4;
    band.pixels.assign(begin, begin + std::ptrdiff_t(count) * image.width * 4);
    return band;
}

}  // namespace

// The shoreline at grazing views (issue 13: "no jagged streaks where sand bars meet the sea"):
// the band of rows just below the horizon of `sunset` and `beach`, where the sand bars and the
// shallow water alternate, in one sample at 160x90 against 640x360 averaged 4x4. One sample
// on both sides: what one frame draws is judged, not the accumulation of jittered frames.
// Measured (llvmpipe, reduced tables): sunset 40.2 -> 34.3 %, beach 5.39 -> 4.39 %. Before,
// the sea's screen-space reflections compared their rays with the depth at the centre of the
// pixel they crossed, which at these views spans hundreds of metres of depth, so rays rising
// from shallow water were found behind the sea floor under them or not by the jitter of their
// steps: a checker of dark dots along the shore (now the depth is read filtered at the ray's
// point); the waterline's pixels were all sea or all sand (now ocean.frag covers them by the
// share of the pixel under water, from the terrain's slope across it). What remains is the
// sand bars' silhouettes, which one sample cannot anti-alias. Without the ground detail (as
// MountainsStillIsAntiAliased: at 160x90 its sand is texture at the frame's Nyquist limit,
// which one sample aliases: `beach` 5.22 % with it); the waterline and the wet sand are not
// the detail's and stay in.
constexpr double kShorelineSunsetBound = 0.37;
constexpr double kShorelineBeachBound = 0.049;
TEST_F(AliasingTest, ShorelineAtGrazingViewsIsAntiAliased) {
    struct Case {
        const char* view;
        int firstRow;  // the horizon's row at 160x90 (pitch, fov 60)
        double bound;
    };
    for (const Case c : {Case{"sunset", 44, kShorelineSunsetBound}, Case{"beach", 38, kShorelineBeachBound}}) {
        const std::string view = c.view;
        const std::string args = "--samples 1 --preset " + earthWithDetail(false);
        const planet::ImageRGBAF reference = planet::boxDownsample(render(view, "640x360", args, view + "-reference"), 4);
        const planet::ImageRGBAF single = render(view, "160x90", args, view + "-s1");
        const planet::ImageComparison e =
            planet::compareImages(rowBand(single, c.firstRow, 16), rowBand(reference, c.firstRow, 16));
        EXPECT_EQ(e.nonFinitePixels, 0u);
        planet::writeDifferenceImage(e, rowBand(single, c.firstRow, 16), rowBand(reference, c.firstRow, 16),
                                     dir / (view + "-shore-error.png"));
        std::printf("shoreline %s, rows %d-%d of 160x90 against 640x360 averaged 4x4: mean relative luminance "
                    "error %.2f %%, p99 %.1f %%\n",
                    c.view, c.firstRow, c.firstRow + 15, 100.0 * e.meanRelativeError, 100.0 * e.errorPercentile(99));
        EXPECT_LT(e.meanRelativeError, c.bound) << c.view;
    }
}
