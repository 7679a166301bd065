// The ground up close has texture (issue 13): local contrast in the lower third of the
// ground-level views. Before the detail (3cd79eb) the meadow, the beach and the sunset's
// foreground were one flat colour each.
//
// Measure: the frame's luminance Y (Rec. 709 weights, linear HDR as `render` writes it) over
// 16x16-pixel windows tiling the lower third; in each window the standard deviation of Y over
// its mean (relative, so exposure and the sun's colour do not enter); the mean over the windows.
// 320x180, one unjittered sample, reduced atmosphere tables. To measure another version's
// shaders: PLANET_ROOT=<its tree> ./tests/planet_tests --gtest_filter='GroundDetail.*'.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "process.h"
#include "render/image_io.h"

namespace {

using planet::test::runCommand;

// Mean relative luminance contrast of 16x16 windows in the lower third of `image`.
double lowerThirdLocalContrast(const planet::ImageRGBAF& image) {
    const int window = 16;
    double sum = 0.0;
    int windows = 0;
    for (int y0 = image.height - window; y0 >= image.height * 2 / 3; y0 -= window)
        for (int x0 = 0; x0 + window <= image.width; x0 += window) {
            double mean = 0.0, square = 0.0;
            for (int y = y0; y < y0 + window; ++y)
                for (int x = x0; x < x0 + window; ++x) {
                    const float* p = &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4];
                    const double luminance = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
                    mean += luminance, square += luminance * luminance;
                }
            const double n = window * window;
            mean /= n;
            const double deviation = std::sqrt(std::max(0.0, square / n - mean * mean));
            sum += mean > 0.0 ? deviation / mean : 0.0;
            ++windows;
        }
    return windows ? sum / windows : 0.0;
}

// The spread (standard deviation) over the 16x16 windows of the lower third of `image` of
// each window's blue share of its mean colour, b / (r + g + b): how much the hue of the
// ground changes from patch to patch.
double lowerThirdBlueShareSpread(const planet::ImageRGBAF& image) {
    const int window = 16;
    std::vector<double> shares;
    for (int y0 = image.height - window; y0 >= image.height * 2 / 3; y0 -= window)
        for (int x0 = 0; x0 + window <= image.width; x0 += window) {
            double rgb[3] = {0.0, 0.0, 0.0};
            for (int y = y0; y < y0 + window; ++y)
                for (int x = x0; x < x0 + window; ++x)
                    for (int c = 0; c < 3; ++c)
                        rgb[c] += image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4 + c];
            const double sum = rgb[0] + rgb[1] + rgb[2];
            if (sum > 0.0) shares.push_back(rgb[2] / sum);
        }
    double mean = 0.0, square = 0.0;
    for (double v : shares) mean += v, square += v * v;
    mean /= double(shares.size());
    return std::sqrt(std::max(0.0, square / double(shares.size()) - mean * mean));
}

class GroundDetail : public planet::test::CliFixture {
protected:
    void SetUp() override {
        CliFixture::SetUp();
        shareCloudCache();
    }
    // The view's still, 320x180, one unjittered sample, with the preset (terrain.detail on).
    planet::ImageRGBAF still(const std::string& view, const std::string& preset = "earth") {
        const auto r = runCommand(planet("render --tables reduced --samples 1 --preset " + preset + " --view " + view +
                                         " --size 320x180 --out " + view + ".exr"));
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return planet::readExr(dir / (view + ".exr"));
    }
    double contrastOf(const std::string& view) {
        const double c = lowerThirdLocalContrast(still(view));
        std::printf("local contrast in the lower third of '%s' (320x180): %.4f\n", view.c_str(), c);
        return c;
    }
};

}  // namespace

TEST(GroundDetailMeasure, AFlatImageHasNoContrastAndACheckerboardHasItsOwn) {
    planet::ImageRGBAF flat{64, 48, std::vector<float>(64 * 48 * 4, 0.5f)};
    EXPECT_EQ(lowerThirdLocalContrast(flat), 0.0);
    planet::ImageRGBAF checker = flat;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c) checker.pixels[(y * 64 + x) * 4 + c] = (x + y) % 2 ? 1.5f : 0.5f;
    EXPECT_NEAR(lowerThirdLocalContrast(checker), 0.5, 1e-9);  // std 0.5 over mean 1
}

// Floors: about a third of what the detail gives, far above what the flat frames had.
// Measured with this test: 3cd79eb's shaders (no detail) 0.0003, 0.0000, 0.0005; with the
// detail placed where the ray meets the height field (terrainRayHitNear) 0.320, 0.074, 0.066.
TEST_F(GroundDetail, GroundLevelViewsHaveLocalContrast) {
    EXPECT_GT(contrastOf("ground"), 0.10);
    EXPECT_GT(contrastOf("beach"), 0.025);
    EXPECT_GT(contrastOf("sunset"), 0.02);
}

// On a dry world (Mars: no sea) the lowlands are dust, not grass: the detail's tints vary them
// in brightness, but the meadow's dry and lush patches (a yellower and a bluer green) are not
// applied (terrain/detail.glsl, `vegetated`). With them, Mars's ground had grey-blue blotches:
// the windows' blue share spread by 0.030 (linear radiance); without them by 0.0005 (this test).
TEST_F(GroundDetail, ADryWorldsLowlandsHaveNoGrassPatches) {
    const planet::ImageRGBAF mars = still("ground", "mars");
    const double spread = lowerThirdBlueShareSpread(mars);
    std::printf("Mars 'ground': the blue share of the lower third's windows spreads by %.4f\n", spread);
    EXPECT_GT(lowerThirdLocalContrast(mars), 0.02);  // the detail is there
    EXPECT_LT(spread, 0.005);
}
