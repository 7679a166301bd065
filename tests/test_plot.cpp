// Tests for render/plot: image size, bar geometry read back from the pixels
// (using the layout to find each bar), legend-free zero bars, title text, the
// PNG round trip and argument checks.
#include "render/plot.h"

#include <gtest/gtest.h>

#include <stb_image.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace planet {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

Rgb pixel(const Image8& img, int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * img.width + x) * 3;
    return {img.rgb[i], img.rgb[i + 1], img.rgb[i + 2]};
}

// Pixels of colour c in rect r.
int countColour(const Image8& img, PixelRect r, Rgb c) {
    int n = 0;
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) n += pixel(img, x, y) == c;
    return n;
}

// Pixels of colour c in the middle column of bar `bar`.
int columnCount(const Image8& img, const BarPlotLayout& l, std::size_t bar, Rgb c) {
    const int x = (l.bars[bar].x0 + l.bars[bar].x1) / 2;
    return countColour(img, {x, l.plotArea.y0, x + 1, l.plotArea.y1}, c);
}

bool isDark(Rgb c) { return c[0] < 100 && c[1] < 100 && c[2] < 100; }

int countDark(const Image8& img, PixelRect r) {
    int n = 0;
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) n += isDark(pixel(img, x, y));
    return n;
}

BarPlot twoBars(double first, double second) {
    BarPlot p;
    p.title = "GPU time per pass";
    p.yLabel = "ms";
    p.categories = {"orbit", "surface"};
    p.series = {{"terrain", {first, second}}};
    return p;
}

TEST(Plot, ImageHasRequestedSize) {
    const Image8 img = renderStackedBarPlot(twoBars(1, 2), 640, 360);
    EXPECT_EQ(img.width, 640);
    EXPECT_EQ(img.height, 360);
    EXPECT_EQ(img.rgb.size(), 640u * 360u * 3u);
}

TEST(Plot, FirstSeriesColourFillsFirstBar) {
    const BarPlot p = twoBars(2, 1);
    const Image8 img = renderStackedBarPlot(p);
    const BarPlotLayout l = layoutStackedBarPlot(p);
    ASSERT_EQ(l.bars.size(), 2u);
    const PixelRect& bar = l.bars[0];
    EXPECT_GT(countColour(img, bar, seriesColor(0)), (bar.x1 - bar.x0) * (bar.y1 - bar.y0) / 4);
    // ... and nothing of it between the two bars.
    const PixelRect between{bar.x1, l.plotArea.y0, l.bars[1].x0, l.plotArea.y1};
    EXPECT_EQ(countColour(img, between, seriesColor(0)), 0);
}

TEST(Plot, TallerValueGivesTallerBar) {
    const BarPlot p = twoBars(1, 3);
    const Image8 img = renderStackedBarPlot(p);
    const BarPlotLayout l = layoutStackedBarPlot(p);
    const int low = columnCount(img, l, 0, seriesColor(0));
    const int high = columnCount(img, l, 1, seriesColor(0));
    ASSERT_GT(low, 10);
    EXPECT_NEAR(static_cast<double>(high) / low, 3.0, 0.05);
    // The axis runs to the nice tick above 3, so 3 fills 3/axisTop of the plot height.
    EXPECT_NEAR(high, 3.0 / l.ticks.back() * (l.plotArea.y1 - l.plotArea.y0), 1.0);
}

TEST(Plot, SegmentsStackInSeriesOrder) {
    BarPlot p = twoBars(1, 1);
    p.series.push_back({"ocean", {2, 2}});
    const Image8 img = renderStackedBarPlot(p);
    const BarPlotLayout l = layoutStackedBarPlot(p);
    const int x = (l.bars[0].x0 + l.bars[0].x1) / 2;
    EXPECT_EQ(pixel(img, x, l.plotArea.y1 - 1), seriesColor(0));  // bottom segment: series 0
    const int c0 = columnCount(img, l, 0, seriesColor(0));
    const int c1 = columnCount(img, l, 0, seriesColor(1));
    EXPECT_EQ(pixel(img, x, l.plotArea.y1 - c0 - 1), seriesColor(1));  // series 1 sits on top
    EXPECT_NEAR(static_cast<double>(c1) / c0, 2.0, 0.05);
    EXPECT_NE(seriesColor(0), seriesColor(1));
}

TEST(Plot, ZeroValueDrawsNoSegment) {
    BarPlot p = twoBars(2, 0);
    p.series.push_back({"ocean", {1, 1}});
    const Image8 img = renderStackedBarPlot(p);
    const BarPlotLayout l = layoutStackedBarPlot(p);
    EXPECT_EQ(countColour(img, l.bars[1], seriesColor(0)), 0);
    EXPECT_GT(columnCount(img, l, 1, seriesColor(1)), 10);
    const int x = (l.bars[1].x0 + l.bars[1].x1) / 2;
    EXPECT_EQ(pixel(img, x, l.plotArea.y1 - 1), seriesColor(1));  // ocean starts at the axis
}

TEST(Plot, NaNAndNegativeCountAsZero) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    BarPlot p = twoBars(nan, -5);
    p.series.push_back({"ocean", {1, 1}});
    const Image8 img = renderStackedBarPlot(p);
    const BarPlotLayout l = layoutStackedBarPlot(p);
    EXPECT_EQ(countColour(img, l.bars[0], seriesColor(0)), 0);
    EXPECT_EQ(countColour(img, l.bars[1], seriesColor(0)), 0);
    EXPECT_EQ(columnCount(img, l, 0, seriesColor(1)), columnCount(img, l, 1, seriesColor(1)));
}

TEST(Plot, AllZeroDataGivesUnitAxis) {
    const BarPlot p = twoBars(0, 0);
    const BarPlotLayout l = layoutStackedBarPlot(p);
    EXPECT_DOUBLE_EQ(l.ticks.back(), 1.0);
    const Image8 img = renderStackedBarPlot(p);
    EXPECT_EQ(countColour(img, l.plotArea, seriesColor(0)), 0);
    EXPECT_GT(countDark(img, {0, 0, img.width, img.height}), 0);  // axes and labels still drawn
}

TEST(Plot, TitleDrawsDarkPixelsInTopBand) {
    BarPlot p = twoBars(1, 2);
    const PixelRect band{0, 0, 1200, 640 / 10};
    EXPECT_GT(countDark(renderStackedBarPlot(p), band), 100);
    const BarPlotLayout l = layoutStackedBarPlot(p);
    EXPECT_GT(countDark(renderStackedBarPlot(p), l.title), 50);
    p.title.clear();
    p.series.clear();  // no legend either: the band must then be empty
    EXPECT_EQ(countDark(renderStackedBarPlot(p), {0, 0, 1200, 12}), 0);
}

TEST(Plot, NiceTicks) {
    EXPECT_EQ(niceTicks(3.7), (std::vector<double>{0, 1, 2, 3, 4}));
    EXPECT_EQ(niceTicks(10), (std::vector<double>{0, 2, 4, 6, 8, 10}));
    EXPECT_EQ(niceTicks(0).back(), 1.0);
    EXPECT_EQ(niceTicks(-3).back(), 1.0);
    for (double m = 1e-3; m < 1e6; m *= 1.07) {
        const std::vector<double> t = niceTicks(m);
        ASSERT_GE(t.size(), 4u) << m;
        ASSERT_LE(t.size(), 6u) << m;
        ASSERT_GE(t.back(), m * (1 - 1e-9)) << m;
        const double step = t[1], mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
        EXPECT_TRUE(std::abs(mantissa - 1) < 1e-6 || std::abs(mantissa - 2) < 1e-6 || std::abs(mantissa - 5) < 1e-6)
            << "step " << step << " for " << m;
    }
}

TEST(Plot, ManyCategoriesAndLongNames) {
    BarPlot p;
    p.title = std::string(500, 'T') + "\n\xc3\xa9";  // too long, a newline and UTF-8
    p.yLabel = std::string(300, 'y');
    for (int i = 0; i < 24; ++i) p.categories.push_back(std::string(80, 'c') + std::to_string(i));
    for (int s = 0; s < 14; ++s) p.series.push_back({std::string(60, 's'), std::vector<double>(24, s + 0.5)});
    const Image8 img = renderStackedBarPlot(p);
    EXPECT_EQ(img.rgb.size(), 1200u * 640u * 3u);
    const BarPlotLayout l = layoutStackedBarPlot(p);
    EXPECT_EQ(l.bars.size(), 24u);
    for (const std::string& label : l.categoryLabels) EXPECT_LT(label.size(), 80u);
    for (int w : {1, 7, 64}) EXPECT_NO_THROW(renderStackedBarPlot(p, w, w));
}

TEST(Plot, BadSizeThrows) {
    const BarPlot p = twoBars(1, 2);
    EXPECT_THROW(renderStackedBarPlot(p, 0, 100), std::invalid_argument);
    EXPECT_THROW(renderStackedBarPlot(p, 100, -1), std::invalid_argument);
    EXPECT_THROW(renderStackedBarPlot(p, 8193, 100), std::invalid_argument);
    EXPECT_THROW(renderStackedBarPlot(p, 100, 100000), std::invalid_argument);
    EXPECT_NO_THROW(renderStackedBarPlot(p, 1, 1));
}

TEST(Plot, PngRoundTrip) {
    const Image8 img = renderStackedBarPlot(twoBars(1.5, 4.25), 400, 300);
    const auto path = std::filesystem::path(testing::TempDir()) / "planet_plot_test" / "plot.png";
    writePng(img, path);
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load(path.string().c_str(), &w, &h, &channels, 3);
    ASSERT_NE(data, nullptr) << stbi_failure_reason();
    EXPECT_EQ(w, img.width);
    EXPECT_EQ(h, img.height);
    EXPECT_TRUE(std::equal(img.rgb.begin(), img.rgb.end(), data));
    stbi_image_free(data);
    std::filesystem::remove_all(path.parent_path());
}

TEST(Plot, WritePngRejectsInconsistentImage) {
    Image8 bad;
    bad.width = 4;
    bad.height = 4;
    bad.rgb.resize(10);
    EXPECT_THROW(writePng(bad, std::filesystem::path(testing::TempDir()) / "bad.png"), std::invalid_argument);
    EXPECT_THROW(writePng(Image8{}, std::filesystem::path(testing::TempDir()) / "empty.png"), std::invalid_argument);
}

}  // namespace
}  // namespace planet
