// Stacked bar chart rasteriser; see plot.h.
//
// Organisation: pixel primitives (fillRect, text from stb_easy_font quads,
// upright or rotated 90°), then number formatting and axis ticks, then the
// layout (title band, legend rows, axis margins, bar columns), then one small
// draw function per chart element, then PNG output.
#include "render/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include "render/image_io.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wconversion"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace planet {

namespace {

using Rgb = std::array<std::uint8_t, 3>;

constexpr Rgb kBackground{255, 255, 255};
constexpr Rgb kText{33, 33, 33};
constexpr Rgb kAxis{90, 90, 90};
constexpr Rgb kGrid{226, 226, 226};

constexpr int kScale = 2;       // text scale for everything but the title
constexpr int kTitleScale = 3;  // used when the title fits at this size
constexpr int kGlyphH = 7;      // cap height of stb_easy_font, font pixels
constexpr int kPad = 12;        // outer margin, pixels
constexpr int kGap = 8;         // between an axis and its labels, pixels
constexpr double kBarFill = 0.6;  // bar width / category slot width

// ---------------------------------------------------------------- pixels

void fillRect(Image8& img, PixelRect r, Rgb c) {
    const int x0 = std::max(r.x0, 0), x1 = std::min(r.x1, img.width);
    const int y0 = std::max(r.y0, 0), y1 = std::min(r.y1, img.height);
    for (int y = y0; y < y1; ++y) {
        auto* row = img.rgb.data() + (static_cast<std::size_t>(y) * img.width) * 3;
        for (int x = x0; x < x1; ++x) std::memcpy(row + static_cast<std::size_t>(x) * 3, c.data(), 3);
    }
}

// ---------------------------------------------------------------- text

// stb_easy_font indexes a table by (c - 32) and reads one entry past it, so
// only 32 … 126 are safe; everything else (UTF-8 bytes, newlines) becomes '?'.
std::string printable(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c < 32 || c > 126) c = '?';
    return out;
}

int textWidth(const std::string& s, int scale) {
    std::string copy = printable(s);  // stb wants a mutable char*
    return stb_easy_font_width(copy.data()) * scale;
}

// s shortened to at most maxWidth pixels by cutting out its middle, so that
// names sharing a prefix ("mountains sunrise", "mountains sunset") stay apart:
// "mountai..sunset". "" if not even ".." fits.
std::string fitText(std::string_view s, int maxWidth, int scale) {
    const std::string full = printable(s);
    if (textWidth(full, scale) <= maxWidth) return full;
    for (std::size_t keep = full.size(); keep-- > 0;) {
        const std::size_t head = (keep + 1) / 2;
        std::string cut = full.substr(0, head) + ".." + full.substr(full.size() - (keep - head));
        if (textWidth(cut, scale) <= maxWidth) return cut;
    }
    return {};
}

struct Quad {
    int u0, v0, u1, v1;  // font pixels, u right, v down
};

std::vector<Quad> glyphQuads(const std::string& s) {
    std::string text = printable(s);
    std::vector<char> buffer(text.size() * 1024 + 64);  // ~270 bytes per glyph on average
    const int n = stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, buffer.data(),
                                      static_cast<int>(buffer.size()));
    std::vector<Quad> quads;
    for (int q = 0; q < n; ++q) {
        float v0[2], v2[2];  // corners 0 and 2 of the quad; vertices are 16 bytes, x y first
        std::memcpy(v0, buffer.data() + q * 64, sizeof v0);
        std::memcpy(v2, buffer.data() + q * 64 + 32, sizeof v2);
        quads.push_back({static_cast<int>(v0[0]), static_cast<int>(v0[1]),
                         static_cast<int>(v2[0]), static_cast<int>(v2[1])});
    }
    return quads;
}

// Upright text with its top-left corner at (x, y).
void drawText(Image8& img, int x, int y, const std::string& s, Rgb c, int scale) {
    for (const Quad& q : glyphQuads(s))
        fillRect(img, {x + q.u0 * scale, y + q.v0 * scale, x + q.u1 * scale, y + q.v1 * scale}, c);
}

// Text turned 90° counter-clockwise, reading bottom to top: it starts at
// yBottom and the glyph tops face left, at column x.
void drawTextUp(Image8& img, int x, int yBottom, const std::string& s, Rgb c, int scale) {
    for (const Quad& q : glyphQuads(s))
        fillRect(img, {x + q.v0 * scale, yBottom - q.u1 * scale, x + q.v1 * scale, yBottom - q.u0 * scale}, c);
}

void drawTextCentred(Image8& img, int cx, int y, const std::string& s, Rgb c, int scale) {
    drawText(img, cx - textWidth(s, scale) / 2, y, s, c, scale);
}

// ---------------------------------------------------------------- numbers

std::string format(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

std::string formatTick(double v, double step) {
    if (v == 0.0) return "0";
    if (step < 1e-4 || v >= 1e7) return format("%g", v);
    if (step >= 1.0) return format("%.0f", v);
    const int decimals = static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// About three significant digits: 0.42, 3.14, 16.7, 123, 4096.
std::string formatTotal(double v) {
    if (v == 0.0) return "0";
    if (v >= 1e7 || v < 0.01) return format("%.3g", v);
    if (v >= 100.0) return format("%.0f", v);
    if (v >= 10.0) return format("%.1f", v);
    return format("%.2f", v);
}

double cleanValue(const BarSeries& s, std::size_t category) {
    if (category >= s.values.size()) return 0.0;
    const double v = s.values[category];
    return std::isfinite(v) && v > 0.0 ? v : 0.0;
}

std::vector<double> stackTotals(const BarPlot& plot) {
    std::vector<double> totals(plot.categories.size(), 0.0);
    for (std::size_t c = 0; c < totals.size(); ++c)
        for (const BarSeries& s : plot.series) totals[c] += cleanValue(s, c);
    return totals;
}

// ---------------------------------------------------------------- layout

void checkSize(int width, int height) {
    if (width <= 0 || height <= 0 || width > kMaxPlotSize || height > kMaxPlotSize)
        throw std::invalid_argument("plot size " + std::to_string(width) + "x" + std::to_string(height) +
                                    " outside 1.." + std::to_string(kMaxPlotSize));
}

int textHeight(int scale) { return kGlyphH * scale; }

// Title band; returns the y below it.
int layoutTitle(const BarPlot& plot, BarPlotLayout& out) {
    const int avail = out.width - 2 * kPad;
    const int scale = textWidth(plot.title, kTitleScale) <= avail ? kTitleScale : kScale;
    const std::string text = fitText(plot.title, avail, scale);
    if (text.empty()) return kPad;
    const int w = textWidth(text, scale);
    const int x = (out.width - w) / 2;
    out.title = {x, kPad, x + w, kPad + textHeight(scale)};
    return out.title.y1 + 2 * kGap;
}

// Legend items flow left to right from x = left, wrapping at the right margin.
// Returns the y below the last row.
int layoutLegend(const BarPlot& plot, int left, int top, BarPlotLayout& out) {
    const int box = textHeight(kScale), rowH = box + 10, right = out.width - kPad;
    int x = left, y = top;
    for (const BarSeries& s : plot.series) {
        const std::string name = fitText(s.name, std::max(right - left - box - kGap, 0), kScale);
        const int itemW = box + kGap + textWidth(name, kScale);
        if (x > left && x + itemW > right) {
            x = left;
            y += rowH;
        }
        out.swatches.push_back({x, y, x + box, y + box});
        x += itemW + 3 * box / 2;
    }
    return plot.series.empty() ? top : y + rowH;
}

int yAxisMargin(const BarPlot& plot, const std::vector<double>& ticks) {
    int widest = 0;
    for (double t : ticks) widest = std::max(widest, textWidth(formatTick(t, ticks[1]), kScale));
    const int labelW = plot.yLabel.empty() ? 0 : textHeight(kScale) + kGap;
    return kPad + labelW + widest + kGap;
}

// Chooses upright or rotated category labels and returns the space they need below the axis.
int layoutCategoryLabels(const BarPlot& plot, int slotW, BarPlotLayout& out) {
    int widest = 0;
    for (const std::string& c : plot.categories) widest = std::max(widest, textWidth(c, kScale));
    // Rotate only when that shortens the labels less than fitting them upright would.
    const int uprightLen = slotW - 6, rotatedLen = out.height / 3;
    out.rotatedLabels = widest > uprightLen && rotatedLen > uprightLen;
    const int maxLen = out.rotatedLabels ? rotatedLen : uprightLen;
    for (const std::string& c : plot.categories) out.categoryLabels.push_back(fitText(c, maxLen, kScale));
    if (plot.categories.empty()) return kGap;
    return kGap + (out.rotatedLabels ? std::min(widest, maxLen) : textHeight(kScale));
}

void layoutBars(std::size_t count, BarPlotLayout& out) {
    const PixelRect& a = out.plotArea;
    const double slot = static_cast<double>(a.x1 - a.x0) / static_cast<double>(std::max<std::size_t>(count, 1));
    const int barW = std::max(1, static_cast<int>(std::lround(slot * kBarFill)));
    for (std::size_t i = 0; i < count; ++i) {
        const int cx = a.x0 + static_cast<int>(std::lround((static_cast<double>(i) + 0.5) * slot));
        out.bars.push_back({cx - barW / 2, a.y0, cx - barW / 2 + barW, a.y1});
    }
}

}  // namespace

std::vector<double> niceTicks(double maxValue) {
    if (!(maxValue > 0.0) || !std::isfinite(maxValue)) maxValue = 1.0;
    const double base = std::pow(10.0, std::floor(std::log10(maxValue / 5.0)));
    double step = 50.0 * base;
    for (double m : {1.0, 2.0, 5.0, 10.0, 20.0}) {
        if (std::ceil(maxValue / (m * base) - 1e-9) <= 5.0) {
            step = m * base;
            break;
        }
    }
    // The smallest step with <= 5 intervals leaves at least 3 (steps grow by <= 2.5x).
    const int intervals = std::max(1, static_cast<int>(std::ceil(maxValue / step - 1e-9)));
    std::vector<double> ticks;
    for (int i = 0; i <= intervals; ++i) ticks.push_back(i * step);
    return ticks;
}

std::array<std::uint8_t, 3> seriesColor(std::size_t i) {
    // Tableau 10: distinct hues that stay apart for most colour-blind viewers.
    static constexpr Rgb kPalette[10] = {
        {78, 121, 167}, {242, 142, 43}, {225, 87, 89},   {118, 183, 178}, {89, 161, 79},
        {237, 201, 72}, {176, 122, 161}, {255, 157, 167}, {156, 117, 95},  {186, 176, 172}};
    Rgb c = kPalette[i % 10];
    const int darken = static_cast<int>((i / 10) % 3);  // later cycles get darker
    for (auto& ch : c) ch = static_cast<std::uint8_t>(ch * (4 - darken) / 4);
    return c;
}

BarPlotLayout layoutStackedBarPlot(const BarPlot& plot, int width, int height) {
    checkSize(width, height);
    BarPlotLayout out;
    out.width = width;
    out.height = height;
    const std::vector<double> totals = stackTotals(plot);
    out.ticks = niceTicks(totals.empty() ? 0.0 : *std::max_element(totals.begin(), totals.end()));

    const int left = yAxisMargin(plot, out.ticks);
    const int right = std::max(width - kPad - kGap, left);
    const int legendBottom = layoutLegend(plot, left, layoutTitle(plot, out), out);
    const int top = legendBottom + textHeight(kScale) + kGap;  // room for the totals above bars
    const int slotW = (right - left) / static_cast<int>(std::max<std::size_t>(plot.categories.size(), 1));
    const int bottom = std::max(height - kPad - layoutCategoryLabels(plot, slotW, out), top);
    out.plotArea = {left, top, right, bottom};
    layoutBars(plot.categories.size(), out);
    return out;
}

namespace {

// ---------------------------------------------------------------- drawing

int valueToY(const BarPlotLayout& l, double v) {
    const double top = l.ticks.back();
    double frac = top > 0.0 && std::isfinite(top) ? v / top : 0.0;
    if (!(frac >= 0.0)) frac = 0.0;
    frac = std::min(frac, 1.0);
    const PixelRect& a = l.plotArea;
    return a.y1 - static_cast<int>(std::lround(frac * (a.y1 - a.y0)));
}

void drawGrid(Image8& img, const BarPlotLayout& l) {
    const PixelRect& a = l.plotArea;
    const double step = l.ticks.size() > 1 ? l.ticks[1] : 1.0;
    for (double t : l.ticks) {
        const int y = valueToY(l, t);
        if (t > 0.0) fillRect(img, {a.x0, y, a.x1, y + 1}, kGrid);
        fillRect(img, {a.x0 - 6, y, a.x0, y + 1}, kAxis);  // tick mark
        const std::string label = formatTick(t, step);
        drawText(img, a.x0 - kGap - textWidth(label, kScale), y - textHeight(kScale) / 2, label, kText, kScale);
    }
}

void drawAxes(Image8& img, const BarPlotLayout& l) {
    const PixelRect& a = l.plotArea;
    fillRect(img, {a.x0 - 2, a.y0, a.x0, a.y1 + 2}, kAxis);
    fillRect(img, {a.x0 - 2, a.y1, a.x1, a.y1 + 2}, kAxis);
}

// Returns the stack total of category c.
double drawBar(Image8& img, const BarPlotLayout& l, const BarPlot& plot, std::size_t c) {
    double sum = 0.0;
    for (std::size_t s = 0; s < plot.series.size(); ++s) {
        const double v = cleanValue(plot.series[s], c);
        if (v <= 0.0) continue;
        const int yLow = valueToY(l, sum);
        sum += v;
        fillRect(img, {l.bars[c].x0, valueToY(l, sum), l.bars[c].x1, yLow}, seriesColor(s));
    }
    return sum;
}

void drawBars(Image8& img, const BarPlotLayout& l, const BarPlot& plot) {
    for (std::size_t c = 0; c < l.bars.size(); ++c) {
        const double total = drawBar(img, l, plot, c);
        const PixelRect& b = l.bars[c];
        const int cx = (b.x0 + b.x1) / 2;
        const int slotW = l.bars.size() > 1 ? l.bars[1].x0 - l.bars[0].x0 : l.plotArea.x1 - l.plotArea.x0;
        const std::string label = formatTotal(total);
        // Shrink to 1x when the 2x label would run into the next bar's label; drop it if even that does.
        const int scale = textWidth(label, kScale) <= slotW - 4 ? kScale : 1;
        if (textWidth(label, scale) > slotW - 2) continue;
        drawTextCentred(img, cx, valueToY(l, total) - textHeight(scale) - 6, label, kText, scale);
    }
}

void drawCategoryLabels(Image8& img, const BarPlotLayout& l) {
    const int y = l.plotArea.y1 + kGap + 2;
    for (std::size_t c = 0; c < l.bars.size(); ++c) {
        const int cx = (l.bars[c].x0 + l.bars[c].x1) / 2;
        const std::string& s = l.categoryLabels[c];
        if (l.rotatedLabels)
            drawTextUp(img, cx - textHeight(kScale) / 2, y + textWidth(s, kScale), s, kText, kScale);
        else
            drawTextCentred(img, cx, y, s, kText, kScale);
    }
}

void drawYLabel(Image8& img, const BarPlotLayout& l, const BarPlot& plot) {
    const PixelRect& a = l.plotArea;
    const std::string s = fitText(plot.yLabel, std::max(a.y1 - a.y0, 0), kScale);
    drawTextUp(img, kPad, (a.y0 + a.y1 + textWidth(s, kScale)) / 2, s, kText, kScale);
}

void drawTitle(Image8& img, const BarPlotLayout& l, const BarPlot& plot) {
    const PixelRect& t = l.title;
    const int scale = (t.y1 - t.y0) / kGlyphH;
    if (scale > 0) drawText(img, t.x0, t.y0, fitText(plot.title, t.x1 - t.x0, scale), kText, scale);
}

void drawLegend(Image8& img, const BarPlotLayout& l, const BarPlot& plot) {
    const int avail = l.width - kPad - l.plotArea.x0;
    for (std::size_t s = 0; s < l.swatches.size(); ++s) {
        const PixelRect& box = l.swatches[s];
        fillRect(img, box, seriesColor(s));
        const std::string name = fitText(plot.series[s].name, std::max(avail - (box.x1 - box.x0) - kGap, 0), kScale);
        drawText(img, box.x1 + kGap, box.y0, name, kText, kScale);
    }
}

}  // namespace

Image8 renderStackedBarPlot(const BarPlot& plot, int width, int height) {
    const BarPlotLayout layout = layoutStackedBarPlot(plot, width, height);
    Image8 img;
    img.width = width;
    img.height = height;
    img.rgb.resize(static_cast<std::size_t>(width) * height * 3);
    fillRect(img, {0, 0, width, height}, kBackground);
    drawGrid(img, layout);
    drawBars(img, layout, plot);
    drawAxes(img, layout);
    drawCategoryLabels(img, layout);
    drawYLabel(img, layout, plot);
    drawTitle(img, layout, plot);
    drawLegend(img, layout, plot);
    return img;
}

void writePng(const Image8& image, const std::filesystem::path& path) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3)
        throw std::invalid_argument("writePng: image is empty or its pixel buffer does not match its size");
    writePng(image.rgb.data(), image.width, image.height, 3, path);
}

}  // namespace planet
