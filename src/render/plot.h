// A small CPU rasteriser for the stacked bar charts of `planet bench`.
//
// No GL: the chart is drawn into an 8-bit RGB image and written as PNG, so a
// benchmark run on a headless machine still leaves a picture behind. One bar
// per category (a bench view), one stacked segment per series (a render
// pass), bottom-up in series order. Text is stb_easy_font's segment font
// rasterised at 2x.
//
// The work is split in two: layoutStackedBarPlot() measures everything and
// returns pixel rectangles, renderStackedBarPlot() fills them. Tests use the
// layout to find the bars in the image.
//
// Data rules: NaN, infinite or negative values count as 0; an all-zero chart
// still draws, with the y axis running to 1. Names too long for their slot are
// shortened with "..".
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace planet {

struct Image8 {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;  // width*height*3, row 0 = top
};

struct BarSeries {
    std::string name;
    std::vector<double> values;  // one per category; missing entries count as 0
};

struct BarPlot {
    std::string title;
    std::string yLabel;  // e.g. "GPU time (ms)"
    std::vector<std::string> categories;
    std::vector<BarSeries> series;
};

// Pixel rectangle [x0, x1) × [y0, y1), y down.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct BarPlotLayout {
    int width = 0, height = 0;
    PixelRect title;                  // band holding the title text
    std::vector<PixelRect> swatches;  // legend colour box per series
    PixelRect plotArea;               // inside the axes: value 0 at y1, ticks.back() at y0
    std::vector<PixelRect> bars;      // per category: bar columns × plotArea rows
    std::vector<double> ticks;        // y tick values, 0 first, last = axis top
    std::vector<std::string> categoryLabels;  // shortened to fit
    bool rotatedLabels = false;       // category labels read bottom-to-top
};

// Image size limits for every function below; outside → std::invalid_argument.
inline constexpr int kMaxPlotSize = 8192;  // pixels, per side

// 4-6 tick values 0, s, 2s, … with s = {1, 2, 5} × 10^k, the last >= maxValue.
// maxValue <= 0 or not finite gives {0, 0.2, …, 1}.
std::vector<double> niceTicks(double maxValue);

// Fill colour of series i (a qualitative palette, repeating darker after 10).
std::array<std::uint8_t, 3> seriesColor(std::size_t i);

BarPlotLayout layoutStackedBarPlot(const BarPlot& plot, int width = 1200, int height = 640);
Image8 renderStackedBarPlot(const BarPlot& plot, int width = 1200, int height = 640);

// Encodes as PNG in memory, then writes it with writeFileAtomic. Throws
// std::invalid_argument for an empty or inconsistent image, FileError when
// encoding or writing fails.
void writePng(const Image8& image, const std::filesystem::path& path);

}  // namespace planet
