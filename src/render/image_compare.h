// Comparing two linear HDR images (a rendered still against a reference): the
// metrics `planet compare` prints and tests/test_reference_images.cpp checks.
//
// Everything is measured on linear luminance, Y = 0.2126 R + 0.7152 G + 0.0722 B
// (Rec. 709 / sRGB primaries, the renderer's working space); alpha is ignored.
// Per pixel the relative error is
//
//     e = |Y_test - Y_ref| / max(Y_ref, floor),   floor = floorFraction * mean(Y_ref),
//
// so a pixel is judged against its own brightness, except pixels darker than the
// floor (black space, deep shadow), whose error is judged against the floor: a
// 1e-6 absolute difference on a zero-radiance pixel would otherwise be an
// infinite relative error. With the default floor (1 % of the reference's mean),
// a black pixel must stay within 1e-4 of the mean to count as a 1 % error.
//
// Percentiles of e use the same linear interpolation between ranks as
// numpy.percentile (render/stats.h): with N pixels a single bad pixel reaches
// the p-th percentile only when it is more than (100 - p) % of the image, i.e.
// the 99.9th percentile ignores up to N / 1000 outliers.
//
// A pixel that is NaN or Inf in either image is counted in nonFinitePixels and
// left out of every other statistic (which then describe the finite pixels).
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "render/image_io.h"

namespace planet {

struct ImageComparison {
    int width = 0, height = 0;
    double floorFraction = 0.0;       // as passed
    double floor = 0.0;               // floorFraction * meanLuminanceReference (at least FLT_MIN)
    double meanLuminanceTest = 0.0;   // mean linear luminance of the finite pixels
    double meanLuminanceReference = 0.0;
    double meanLuminanceDifference = 0.0;  // (test - reference) / reference, signed; 0 when both are 0
    double meanRelativeError = 0.0;        // mean of e over the finite pixels
    double maxRelativeError = 0.0;
    std::size_t nonFinitePixels = 0;  // NaN or Inf in either image
    // e per pixel, row 0 at the top; NaN where a pixel is non-finite.
    std::vector<float> relativeError;

    // p-th percentile of e over the finite pixels, p in [0, 100]; NaN when there are none.
    double errorPercentile(double p) const;
};

constexpr double kDefaultLuminanceFloorFraction = 0.01;  // of the reference's mean luminance

// Throws std::invalid_argument when the sizes differ (naming both), an image is
// empty or its pixel buffer does not match its size, or floorFraction is not > 0.
ImageComparison compareImages(const ImageRGBAF& test, const ImageRGBAF& reference,
                              double floorFraction = kDefaultLuminanceFloorFraction);

// The difference image, chosen by extension:
//   .png  false colour of e on a log scale, one colour per decade: below 0.01 % the
//         reference's luminance in dim grey (to see where one is), then blue (0.1 %),
//         cyan (1 %), yellow (10 %), red (100 % and above); non-finite pixels magenta.
//   .exr  linear half float: RGB = test - reference per channel (signed), A = e.
// Throws std::invalid_argument for another extension, FileError when it cannot write.
void writeDifferenceImage(const ImageComparison& comparison, const ImageRGBAF& test,
                          const ImageRGBAF& reference, const std::filesystem::path& path);

// The mean of each factor x factor block of pixels (all four channels): a still rendered
// at factor times the size, box-filtered down to the size of a test image, is the
// reference of the aliasing check (scripts/aliasing.sh, tests/test_aliasing.cpp): it
// estimates the pixel's mean radiance with factor^2 samples where the test has its own.
// A NaN or Inf anywhere in a block makes that pixel NaN. Throws std::invalid_argument
// when factor < 1 or the image's sides are not multiples of it.
ImageRGBAF boxDownsample(const ImageRGBAF& image, int factor);

}  // namespace planet
