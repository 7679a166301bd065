// Image comparison metrics (render/image_compare.h) on hand-made images: known
// answers for identical images, a uniform scale, a single outlier, black pixels
// under the floor, non-finite pixels, a size mismatch; the difference images; and
// `planet compare` on files written from them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include <stb_image.h>

#include "process.h"
#include "render/image_compare.h"
#include "test_util.h"

using namespace planet;

namespace {

// A w x h image with a smooth ramp of grey-ish radiance in (0.1, 1.1), never black.
ImageRGBAF ramp(int w, int h) {
    ImageRGBAF image{w, h, std::vector<float>(static_cast<std::size_t>(w) * h * 4)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = &image.pixels[(static_cast<std::size_t>(y) * w + x) * 4];
            const float v = 0.1f + float(x + y * w) / float(w * h);
            p[0] = v;
            p[1] = 0.8f * v;
            p[2] = 0.6f * v;
            p[3] = 1.0f;
        }
    return image;
}

ImageRGBAF scaled(ImageRGBAF image, float s) {
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        if (i % 4 != 3) image.pixels[i] *= s;
    return image;
}

float* pixel(ImageRGBAF& image, int x, int y) { return &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4]; }

}  // namespace

TEST(ImageCompare, IdenticalImagesHaveNoError) {
    const ImageRGBAF a = ramp(40, 30);
    const ImageComparison c = compareImages(a, a);
    EXPECT_EQ(c.meanRelativeError, 0.0);
    EXPECT_EQ(c.maxRelativeError, 0.0);
    EXPECT_EQ(c.errorPercentile(99.0), 0.0);
    EXPECT_EQ(c.errorPercentile(99.9), 0.0);
    EXPECT_EQ(c.meanLuminanceDifference, 0.0);
    EXPECT_EQ(c.nonFinitePixels, 0u);
    EXPECT_GT(c.meanLuminanceReference, 0.1);
}

TEST(ImageCompare, UniformScaleOfOnePercentIsOnePercentEverywhere) {
    const ImageRGBAF reference = ramp(40, 30);
    const ImageComparison c = compareImages(scaled(reference, 1.01f), reference);
    EXPECT_NEAR(c.meanRelativeError, 0.01, 1e-6);
    EXPECT_NEAR(c.errorPercentile(99.0), 0.01, 1e-6);
    EXPECT_NEAR(c.errorPercentile(99.9), 0.01, 1e-6);
    EXPECT_NEAR(c.meanLuminanceDifference, 0.01, 1e-6);
    // Darker test image: signed mean difference, unsigned error.
    const ImageComparison d = compareImages(scaled(reference, 0.99f), reference);
    EXPECT_NEAR(d.meanLuminanceDifference, -0.01, 1e-6);
    EXPECT_NEAR(d.meanRelativeError, 0.01, 1e-6);
}

TEST(ImageCompare, OneOutlierMovesThe999thPercentileOnlyWhenAboveATenthOfAPercentOfPixels) {
    // 50 x 40 = 2000 pixels: one is 0.05 % of them, below the 0.1 % the 99.9th percentile ignores.
    for (const auto& [w, h, moves] : {std::tuple{50, 40, false}, std::tuple{25, 20, true}}) {
        const ImageRGBAF reference = ramp(w, h);
        ImageRGBAF test = reference;
        float* p = pixel(test, 7, 3);
        for (int ch = 0; ch < 3; ++ch) p[ch] *= 3.0f;  // +200 %
        const ImageComparison c = compareImages(test, reference);
        EXPECT_NEAR(c.maxRelativeError, 2.0, 1e-5);
        EXPECT_NEAR(c.meanRelativeError, 2.0 / (w * h), 1e-6);
        EXPECT_EQ(c.errorPercentile(99.0), 0.0) << w << "x" << h;
        if (moves)
            EXPECT_GT(c.errorPercentile(99.9), 0.1) << w << "x" << h << " (1 pixel = 0.2 %)";
        else
            EXPECT_EQ(c.errorPercentile(99.9), 0.0) << w << "x" << h << " (1 pixel = 0.05 %)";
    }
}

TEST(ImageCompare, BlackPixelsAreJudgedAgainstTheFloor) {
    ImageRGBAF reference = ramp(20, 10);
    for (int x = 0; x < 20; ++x)
        for (int ch = 0; ch < 3; ++ch) pixel(reference, x, 0)[ch] = 0.0f;  // a row of black space
    ImageRGBAF test = reference;
    pixel(test, 3, 0)[0] = pixel(test, 3, 0)[1] = pixel(test, 3, 0)[2] = 1e-6f;  // a faint speck
    const ImageComparison c = compareImages(test, reference);
    EXPECT_NEAR(c.floor, kDefaultLuminanceFloorFraction * c.meanLuminanceReference, 1e-12);
    EXPECT_NEAR(c.maxRelativeError, 1e-6 / c.floor, 1e-6);  // finite, and small
    EXPECT_LT(c.maxRelativeError, 1e-3);
    // A black reference and a black test: no error, no division by zero.
    ImageRGBAF black = ramp(4, 4);
    for (std::size_t i = 0; i < black.pixels.size(); ++i) black.pixels[i] = 0.0f;
    const ImageComparison z = compareImages(black, black);
    EXPECT_EQ(z.meanRelativeError, 0.0);
    EXPECT_EQ(z.meanLuminanceDifference, 0.0);
}

TEST(ImageCompare, NonFinitePixelsAreCountedAndLeftOut) {
    const ImageRGBAF reference = ramp(10, 10);
    ImageRGBAF test = reference;
    pixel(test, 1, 1)[0] = std::numeric_limits<float>::quiet_NaN();
    pixel(test, 2, 1)[1] = std::numeric_limits<float>::infinity();
    const ImageComparison c = compareImages(test, reference);
    EXPECT_EQ(c.nonFinitePixels, 2u);
    EXPECT_EQ(c.meanRelativeError, 0.0);
    EXPECT_EQ(c.errorPercentile(99.9), 0.0);
    EXPECT_TRUE(std::isnan(c.relativeError[11]));
}

TEST(ImageCompare, SizeMismatchIsAnError) {
    try {
        compareImages(ramp(16, 9), ramp(9, 16));
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("16x9"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("9x16"), std::string::npos) << e.what();
    }
    ImageRGBAF broken = ramp(4, 4);
    broken.pixels.pop_back();
    EXPECT_THROW(compareImages(broken, ramp(4, 4)), std::invalid_argument);
    EXPECT_THROW(compareImages(ImageRGBAF{}, ImageRGBAF{}), std::invalid_argument);
}

TEST(ImageCompare, DifferenceImagesArePngInFalseColourAndLinearExr) {
    const std::filesystem::path dir = std::filesystem::path(PLANET_TEST_OUT) / "ImageCompare";
    std::filesystem::create_directories(dir);
    const ImageRGBAF reference = ramp(20, 10);
    ImageRGBAF test = reference;
    pixel(test, 5, 5)[0] += 1.0f;  // one bright error; everything else identical
    const ImageComparison c = compareImages(test, reference);

    writeDifferenceImage(c, test, reference, dir / "diff.png");
    int w = 0, h = 0, n = 0;
    unsigned char* png = stbi_load((dir / "diff.png").c_str(), &w, &h, &n, 4);
    ASSERT_NE(png, nullptr);
    EXPECT_EQ(w, 20);
    EXPECT_EQ(h, 10);
    const unsigned char* bad = png + (5 * 20 + 5) * 4;
    const unsigned char* good = png + (2 * 20 + 2) * 4;
    EXPECT_GT(bad[0], 200);                       // > 10 %: yellow to red
    EXPECT_EQ(good[0], good[1]);                  // no error: the reference in grey
    EXPECT_LT(good[0], 100);
    stbi_image_free(png);

    writeDifferenceImage(c, test, reference, dir / "diff.exr");
    const ImageRGBAF exr = readExr(dir / "diff.exr");
    ASSERT_EQ(exr.width, 20);
    EXPECT_NEAR(exr.pixels[(5 * 20 + 5) * 4 + 0], 1.0f, 1e-3f);                    // R: test - reference
    EXPECT_NEAR(exr.pixels[(5 * 20 + 5) * 4 + 3], c.relativeError[5 * 20 + 5], 1e-2);  // A: e (half)
    EXPECT_EQ(exr.pixels[(2 * 20 + 2) * 4 + 0], 0.0f);

    EXPECT_THROW(writeDifferenceImage(c, test, reference, dir / "diff.jpg"), std::invalid_argument);
}

namespace {
using CompareCommand = planet::test::CliFixture;
using planet::test::contains;
using planet::test::runCommand;
}  // namespace

TEST_F(CompareCommand, PrintsTheMetricsAndFailsPastItsLimits) {
    const ImageRGBAF reference = ramp(40, 30);
    writeExr(reference, dir / "b.exr", 1.0);
    writeExr(scaled(reference, 1.02f), dir / "a.exr", 1.0);
    writeExr(ramp(30, 40), dir / "other.exr", 1.0);

    const auto same = runCommand(planet("compare b.exr b.exr --max-mean 0 --max-p99 0 --max-p999 0 --max-mean-luminance 0"));
    EXPECT_EQ(same.exitCode, 0) << same.output;
    for (const char* word : {"mean luminance difference", "p99 ", "p99.9", "non-finite pixels  0"})
        EXPECT_TRUE(contains(same.output, word)) << word << "\n" << same.output;

    // 2 % brighter (up to half-float rounding): within 5 %, not within 1 %.
    const auto loose = runCommand(planet("compare a.exr b.exr --max-mean 0.05 --max-p999 0.05 --diff d.png"));
    EXPECT_EQ(loose.exitCode, 0) << loose.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "d.png"));
    const auto tight = runCommand(planet("compare a.exr b.exr --max-p999 0.05 --max-mean-luminance 0.01"));
    EXPECT_EQ(tight.exitCode, 1) << tight.output;
    EXPECT_TRUE(contains(tight.output, "planet: error:")) << tight.output;
    EXPECT_TRUE(contains(tight.output, "--max-mean-luminance")) << tight.output;
    EXPECT_FALSE(contains(tight.output, "exceeds --max-p999")) << tight.output;

    for (const char* args : {"compare a.exr missing.exr", "compare a.exr other.exr",
                                    "compare a.exr b.exr --max-mean -1", "compare a.exr b.exr --diff d.jpg"}) {
        const auto bad = runCommand(planet(args));
        EXPECT_EQ(bad.exitCode, 1) << args << "\n" << bad.output;
        EXPECT_TRUE(contains(bad.output, "planet: error:")) << args << "\n" << bad.output;
    }
}
