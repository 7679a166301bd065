// Image comparison metrics and difference images; see image_compare.h.
#include "render/image_compare.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "render/stats.h"

namespace planet {

namespace {

std::string sizeText(const ImageRGBAF& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

void checkImage(const ImageRGBAF& image, const char* which) {
    if (image.width <= 0 || image.height <= 0)
        throw std::invalid_argument(std::string("compareImages: the ") + which + " image is empty");
    if (image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4)
        throw std::invalid_argument(std::string("compareImages: the ") + which +
                                    " image's pixels do not match its size " + sizeText(image));
}

double luminance(const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

bool finitePixel(const float* p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(p[3]);
}

// False colour of a relative error e, one stop per decade from 1e-4 to 1 (see the header).
std::array<std::uint8_t, 3> errorColour(double e, double background) {
    using Rgb = std::array<double, 3>;
    const Rgb grey{background, background, background};
    const Rgb stops[] = {grey, {40, 80, 255}, {0, 220, 255}, {255, 230, 0}, {255, 0, 0}};
    const double t = std::clamp(std::log10(std::max(e, 1e-30)) + 4.0, 0.0, 4.0);
    const int i = std::min(static_cast<int>(t), 3);
    const double f = t - i;
    std::array<std::uint8_t, 3> rgb{};
    for (int c = 0; c < 3; ++c)
        rgb[c] = static_cast<std::uint8_t>(std::lround(stops[i][c] + f * (stops[i + 1][c] - stops[i][c])));
    return rgb;
}

}  // namespace

double ImageComparison::errorPercentile(double p) const {
    return percentile(std::vector<double>(relativeError.begin(), relativeError.end()), p);
}

ImageComparison compareImages(const ImageRGBAF& test, const ImageRGBAF& reference, double floorFraction) {
    checkImage(test, "test");
    checkImage(reference, "reference");
    if (test.width != reference.width || test.height != reference.height)
        throw std::invalid_argument("the images differ in size: " + sizeText(test) + " and " + sizeText(reference));
    if (!(floorFraction > 0.0 && std::isfinite(floorFraction)))
        throw std::invalid_argument("compareImages: the luminance floor fraction must be > 0");

    ImageComparison r;
    r.width = test.width;
    r.height = test.height;
    r.floorFraction = floorFraction;
    const std::size_t n = static_cast<std::size_t>(r.width) * r.height;
    std::vector<char> finite(n);
    double sumTest = 0.0, sumReference = 0.0;
    std::size_t finiteCount = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const float* a = &test.pixels[i * 4];
        const float* b = &reference.pixels[i * 4];
        finite[i] = finitePixel(a) && finitePixel(b);
        if (!finite[i]) continue;
        sumTest += luminance(a);
        sumReference += luminance(b);
        ++finiteCount;
    }
    r.nonFinitePixels = n - finiteCount;
    if (finiteCount > 0) {
        r.meanLuminanceTest = sumTest / static_cast<double>(finiteCount);
        r.meanLuminanceReference = sumReference / static_cast<double>(finiteCount);
    }
    r.meanLuminanceDifference =
        r.meanLuminanceReference != 0.0 ? (r.meanLuminanceTest - r.meanLuminanceReference) / r.meanLuminanceReference
        : r.meanLuminanceTest == 0.0    ? 0.0
                                        : std::numeric_limits<double>::infinity();
    // FLT_MIN keeps an all-black reference from dividing by zero (0 / FLT_MIN = 0).
    r.floor = std::max(floorFraction * r.meanLuminanceReference, static_cast<double>(FLT_MIN));

    r.relativeError.assign(n, std::numeric_limits<float>::quiet_NaN());
    double sumError = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!finite[i]) continue;
        const double y = luminance(&reference.pixels[i * 4]);
        const double e = std::abs(luminance(&test.pixels[i * 4]) - y) / std::max(y, r.floor);
        r.relativeError[i] = static_cast<float>(e);
        sumError += e;
        r.maxRelativeError = std::max(r.maxRelativeError, e);
    }
    if (finiteCount > 0) r.meanRelativeError = sumError / static_cast<double>(finiteCount);
    return r;
}

void writeDifferenceImage(const ImageComparison& comparison, const ImageRGBAF& test, const ImageRGBAF& reference,
                          const std::filesystem::path& path) {
    const std::size_t n = static_cast<std::size_t>(comparison.width) * comparison.height;
    if (comparison.relativeError.size() != n || test.pixels.size() != n * 4 || reference.pixels.size() != n * 4)
        throw std::invalid_argument("writeDifferenceImage: the images do not match the comparison");
    const std::string ext = path.extension().string();
    if (ext == ".exr") {
        ImageRGBAF diff{comparison.width, comparison.height, std::vector<float>(n * 4)};
        for (std::size_t i = 0; i < n; ++i) {
            for (int c = 0; c < 3; ++c) diff.pixels[i * 4 + c] = test.pixels[i * 4 + c] - reference.pixels[i * 4 + c];
            diff.pixels[i * 4 + 3] = comparison.relativeError[i];
        }
        writeExr(diff, path, 1.0);
        return;
    }
    if (ext != ".png") throw std::invalid_argument("difference image '" + path.string() + "': use .png or .exr");
    // Background: the reference tone-mapped so that its mean luminance is mid grey, dimmed.
    const double k = std::log(2.0) / std::max(comparison.meanLuminanceReference, static_cast<double>(FLT_MIN));
    ImageRGBA8 image{comparison.width, comparison.height, std::vector<std::uint8_t>(n * 4, 255)};
    for (std::size_t i = 0; i < n; ++i) {
        const float e = comparison.relativeError[i];
        std::array<std::uint8_t, 3> rgb{255, 0, 255};  // non-finite
        if (!std::isnan(e)) {
            const double y = std::max(luminance(&reference.pixels[i * 4]), 0.0);
            rgb = errorColour(e, 90.0 * (1.0 - std::exp(-k * y)));
        }
        std::copy(rgb.begin(), rgb.end(), image.pixels.begin() + static_cast<std::ptrdiff_t>(i * 4));
    }
    writePng(image, path);
}

ImageRGBAF boxDownsample(const ImageRGBAF& image, int factor) {
    checkImage(image, "downsampled");
    if (factor < 1) throw std::invalid_argument("boxDownsample: the factor must be >= 1");
    if (image.width % factor != 0 || image.height % factor != 0)
        throw std::invalid_argument("boxDownsample: " + sizeText(image) + " is not a multiple of " +
                                    std::to_string(factor) + " in both sides");
    ImageRGBAF out{image.width / factor, image.height / factor, {}};
    out.pixels.assign(static_cast<std::size_t>(out.width) * out.height * 4, 0.0f);
    const double weight = 1.0 / (static_cast<double>(factor) * factor);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int c = 0; c < 4; ++c) {
                double sum = 0.0;  // NaN and Inf pass through the sum
                for (int j = 0; j < factor; ++j)
                    for (int i = 0; i < factor; ++i)
                        sum += image.pixels[(static_cast<std::size_t>(y * factor + j) * image.width + (x * factor + i)) * 4 + c];
                out.pixels[(static_cast<std::size_t>(y) * out.width + x) * 4 + c] = static_cast<float>(sum * weight);
            }
    return out;
}

}  // namespace planet
