// The explorer's render scale (app/render_scale.h): auto keeps a software renderer's frame
// near 320x180 pixels and leaves a hardware renderer's alone; explicit scales are checked.
#include <gtest/gtest.h>

#include <stdexcept>

#include "app/render_scale.h"

using planet::parseRenderScale;
using planet::renderScaleFor;
using planet::scaledSize;

namespace {
const std::string kLlvmpipe = "llvmpipe (LLVM 15.0.6, 256 bits) (Mesa/X.org), OpenGL 4.5 (Core Profile) Mesa 22.3.6";
const std::string kGpu = "NVIDIA H200/PCIe/SSE2, OpenGL 4.6.0 NVIDIA 550.54";
}  // namespace

TEST(RenderScale, AutoRendersAboutThreeHundredByOneEightyOnASoftwareRenderer) {
    EXPECT_DOUBLE_EQ(renderScaleFor(std::nullopt, kLlvmpipe, {1280, 720}), 0.25);
    EXPECT_EQ(scaledSize({1280, 720}, 0.25), glm::ivec2(320, 180));
    EXPECT_EQ(scaledSize({1920, 1080}, renderScaleFor(std::nullopt, kLlvmpipe, {1920, 1080})), glm::ivec2(320, 180));
    EXPECT_EQ(scaledSize({640, 360}, renderScaleFor(std::nullopt, kLlvmpipe, {640, 360})), glm::ivec2(320, 180));
    // A window already that small, or smaller, is rendered whole.
    EXPECT_DOUBLE_EQ(renderScaleFor(std::nullopt, kLlvmpipe, {320, 180}), 1.0);
    EXPECT_DOUBLE_EQ(renderScaleFor(std::nullopt, kLlvmpipe, {160, 90}), 1.0);
    // Never below the slider's floor, whatever the window.
    EXPECT_DOUBLE_EQ(renderScaleFor(std::nullopt, kLlvmpipe, {7680, 4320}), planet::kMinRenderScale);
    // A minimised window (0x0) gets 1, not a division by zero.
    EXPECT_DOUBLE_EQ(renderScaleFor(std::nullopt, kLlvmpipe, {0, 0}), 1.0);
}

TEST(RenderScale, AutoRendersEveryPixelOnAGpuAndAnExplicitScaleIsKept) {
    EXPECT_DOUBLE_EQ(renderScaleFor(std::nullopt, kGpu, {3840, 2160}), 1.0);
    EXPECT_DOUBLE_EQ(renderScaleFor(0.5, kGpu, {1280, 720}), 0.5);
    EXPECT_DOUBLE_EQ(renderScaleFor(1.0, kLlvmpipe, {1280, 720}), 1.0);
    EXPECT_EQ(scaledSize({1281, 721}, 0.5), glm::ivec2(641, 361));  // rounded, not truncated
    EXPECT_EQ(scaledSize({5, 3}, 0.1), glm::ivec2(1, 1));           // at least a pixel
}

TEST(RenderScale, ChoicesAreAutoOrANumberFromATenthToOne) {
    EXPECT_FALSE(parseRenderScale("auto").has_value());
    EXPECT_DOUBLE_EQ(*parseRenderScale("0.5"), 0.5);
    EXPECT_DOUBLE_EQ(*parseRenderScale("1"), 1.0);
    EXPECT_DOUBLE_EQ(*parseRenderScale("0.1"), 0.1);
    for (const char* bad : {"0", "0.05", "1.5", "-1", "nan", "inf", "abc", "0.5x", "", "Auto"})
        EXPECT_THROW(parseRenderScale(bad), std::invalid_argument) << bad;
    try {
        parseRenderScale("2");
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("auto or a number from 0.1 to 1"), std::string::npos) << e.what();
    }
}
