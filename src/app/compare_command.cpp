// `planet compare A.exr B.exr`: how far a linear HDR still A is from a reference B
// (render/image_compare.h for the metrics), with optional limits that make it
// fail, and an optional difference image. Used to check stills before and after
// a change of the frame, and by the reference-image test's failure message.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "app/commands.h"
#include "render/image_compare.h"
#include "scene/toml_error.h"
#include "util/file_util.h"

namespace planet {

namespace {

std::string percent(double fraction, bool sign = false) {
    char text[64];
    std::snprintf(text, sizeof text, sign ? "%+.3f %%" : "%.3f %%", 100.0 * fraction);
    return text;
}

void printComparison(const ImageComparison& c, const CompareOptions& o, std::ostream& out) {
    char floor[128];
    std::snprintf(floor, sizeof floor, "floor %.3g = %g %% of the reference's mean luminance", c.floor,
                  100.0 * c.floorFraction);
    out << "test       " << o.test << "  " << c.width << "x" << c.height << ", mean luminance "
        << c.meanLuminanceTest << "\n"
        << "reference  " << o.reference
        << (o.referenceScale != 1 ? "  averaged " + std::to_string(o.referenceScale) + "x" +
                                        std::to_string(o.referenceScale) + " down"
                                  : std::string())
        << "  mean luminance " << c.meanLuminanceReference << "\n"
        << "mean luminance difference  " << percent(c.meanLuminanceDifference, true) << "\n"
        << "relative luminance error (" << floor << ")\n"
        << "  mean   " << percent(c.meanRelativeError) << "\n"
        << "  p99    " << percent(c.errorPercentile(99.0)) << "\n"
        << "  p99.9  " << percent(c.errorPercentile(99.9)) << "\n"
        << "  max    " << percent(c.maxRelativeError) << "\n"
        << "non-finite pixels  " << c.nonFinitePixels << "\n";
}

}  // namespace

int runCompare(const CompareOptions& o) {
    for (const auto& [name, limit] : {std::pair{"--max-mean", o.maxMean}, {"--max-p99", o.maxP99},
                                      {"--max-p999", o.maxP999}, {"--max-mean-luminance", o.maxMeanLuminance}})
        if (limit && !(*limit >= 0.0 && std::isfinite(*limit)))
            throw InputError(std::string(name) + " must be a finite fraction >= 0 (0.01 = 1 %)");
    if (!o.diff.empty()) {
        const std::string ext = std::filesystem::path(o.diff).extension().string();
        if (ext != ".png" && ext != ".exr") throw InputError("--diff '" + o.diff + "': use .png or .exr");
    }
    const ImageRGBAF test = readExr(o.test);
    ImageRGBAF reference = readExr(o.reference);
    ImageComparison c;
    try {
        if (o.referenceScale != 1) reference = boxDownsample(reference, o.referenceScale);
        c = compareImages(test, reference);
    } catch (const std::invalid_argument& e) {
        throw InputError(o.test + " and " + o.reference + ": " + e.what());
    }
    printComparison(c, o, std::cout);
    if (!o.diff.empty()) {
        writeDifferenceImage(c, test, reference, o.diff);
        std::cout << "wrote " << std::filesystem::absolute(o.diff).lexically_normal().string() << "\n";
    }

    std::vector<std::string> failures;
    const auto check = [&](const char* what, double value, const std::optional<double>& limit, const char* option) {
        if (limit && !(value <= *limit))
            failures.push_back(std::string(what) + " " + percent(value) + " exceeds " + option + " " + percent(*limit));
    };
    check("mean relative error", c.meanRelativeError, o.maxMean, "--max-mean");
    check("99th percentile", c.errorPercentile(99.0), o.maxP99, "--max-p99");
    check("99.9th percentile", c.errorPercentile(99.9), o.maxP999, "--max-p999");
    check("mean luminance difference", std::abs(c.meanLuminanceDifference), o.maxMeanLuminance,
          "--max-mean-luminance");
    if (c.nonFinitePixels > 0) failures.push_back(std::to_string(c.nonFinitePixels) + " pixels are NaN or Inf");
    if (failures.empty()) return 0;
    std::string message = o.test + " differs from " + o.reference + ": ";
    for (std::size_t i = 0; i < failures.size(); ++i) message += (i ? "; " : "") + failures[i];
    throw std::runtime_error(message);
}

}  // namespace planet
