// Issue 15: the surface light's ground whose way to the sun surely meets no cloud is lit by the
// program without the clouds' shadow (render/surface_marks.frag marks it in the stencil;
// src/render/renderer.cpp), since a software renderer ran the shadow's code for every pixel, masked,
// though the clear sky check took no sample. The same decision as the shadow's own
// (CloudSunWaySurelyClear against CloudDensityPathToSun): the pictures the same value for value, under
// a clear sky, under the deck, among the clouds and over the sea's dark depths.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/session.h"
#include "gl_test_support.h"
#include "render/readback.h"
#include "render/renderer.h"

using namespace planet;

namespace {
class SunClearOfClouds : public test::GLTest {};
}  // namespace

TEST_F(SunClearOfClouds, TheProgramWithoutTheCloudsShadowLightsTheClearGroundTheSame) {
    auto renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    const glm::ivec2 size{160, 90};
    for (const std::string view : {"ground", "deck", "clouds", "cumulus", "orbit", "beach"}) {
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        ImageRGBAF images[2];
        for (int split = 0; split < 2; ++split) {
            renderer->setSunClearStencil(split == 1);
            renderer->render(s.scene, s.camera, size);
            images[split] = readTextureRGBAF(renderer->targets().surfaceRadiance(), size.x, size.y);
        }
        std::size_t differing = 0, lit = 0;
        for (std::size_t i = 0; i < images[0].pixels.size(); ++i) {
            differing += images[0].pixels[i] != images[1].pixels[i] ? 1 : 0;
            lit += images[0].pixels[i] > 0.0f ? 1 : 0;
        }
        std::printf("%-8s %zu of %zu surface radiance values differ (%zu lit); clear sky depth %g\n", view.c_str(),
                    differing, images[0].pixels.size(), lit, double(renderer->lastPrepare().clearSkyDepth));
        EXPECT_GT(lit, 0u) << view;
        EXPECT_EQ(differing, 0u) << view;
    }
    renderer->setSunClearStencil(true);
}

// The marks themselves, each fragment's own stencil value from one pass (render/surface_marks.frag): at
// `ground` the meadow is the clear sun's (0x40) and the sky above it, with no ground, the dark depths' (1); at
// `sea` (no clear sky at the camera) the dark depths' (the whole floor in view lies deep) and nothing of the
// clear sun's.
// Where the GL has no ARB_shader_stencil_export, a pass per mark; the marks are the same.
TEST_F(SunClearOfClouds, OnePassMarksTheDarkDepthsAndTheClearSunWithTheirOwnValues) {
    auto renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    auto perMark = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    perMark->setStencilExport(false);
    const glm::ivec2 size{160, 90};
    const auto readMarks = [&](const Renderer& r) { return test::readStencil(r.targets().surfaceStencil(), size); };
    std::printf("ARB_shader_stencil_export: %s\n",
                epoxy_has_gl_extension("GL_ARB_shader_stencil_export") ? "yes (one pass)" : "no (a pass per mark)");
    for (const std::string view : {"ground", "sea"}) {
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        renderer->render(s.scene, s.camera, size);
        perMark->render(s.scene, s.camera, size);
        const std::vector<std::uint8_t> marks = readMarks(*renderer);
        EXPECT_TRUE(marks == readMarks(*perMark)) << view << ": the marks of a pass per mark";
        const ImageRGBAF distance = readTextureRGBAF(renderer->targets().surfaceDistance(), size.x, size.y);
        std::size_t ground = 0, clear = 0, dark = 0, other = 0, darkOnGround = 0;
        for (std::size_t i = 0; i < marks.size(); ++i) {
            const int y = static_cast<int>(i) / size.x, x = static_cast<int>(i) % size.x;
            const bool hasGround = test::pixelAt(distance, x, size.y - 1 - y)[0] > 0.0f;  // (the stencil's rows from the bottom)
            ground += hasGround;
            clear += marks[i] == 0x40;
            dark += marks[i] == 1;
            darkOnGround += marks[i] == 1 && hasGround;
            other += marks[i] != 0 && marks[i] != 1 && marks[i] != 0x40;
        }
        std::printf("%-6s %zu ground pixels: %zu marked clear of the clouds' shadow, %zu dark (%zu with ground), %zu "
                    "other\n", view.c_str(), ground, clear, dark, darkOnGround, other);
        EXPECT_EQ(other, 0u) << view;
        if (view == "ground") {
            // (all but the farthest hills at the horizon, past the clear sky's reach: 7183 of 7184 at 160x90)
            EXPECT_GE(clear, ground * 99 / 100) << "the meadow, nearer than the clear sky's reach";
            EXPECT_GT(dark, marks.size() / 4) << "the sky over the meadow: no ground";
            EXPECT_EQ(darkOnGround, 0u);
        } else {
            EXPECT_EQ(clear, 0u);
            EXPECT_GT(dark, 0u);
        }
    }
}

// The meadow under a lower sun, whose ways to the sun run farther through the layer: the depth within which
// the clear sky around the camera covers every way moves nearer as the sun sinks (26 km out along the view's
// axis at 15 degrees, 43 at 60), and the pictures stay the same value for value. What this cannot show: the
// meadow's clear sky reaches past all the ground in view, so a rule that marked every pixel would pass here
// too (tried); the views with clouds near the camera (deck, clouds, cumulus) have no clear sky at it and mark
// none. A view whose clear sky ends within sight is still to be found.
TEST_F(SunClearOfClouds, UnderALowerSunTheMarkedDepthComesNearerAndTheLightStaysTheSame) {
    auto renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    const glm::ivec2 size{160, 90};
    Session s = loadSession(test::repoPaths(), "earth", "ground");
    s.scene.render.temporal = false;
    const glm::dvec3 up = glm::normalize(s.camera.position);
    const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0.0, 0.0, 1.0), up));
    float previousDepth = 0.0f;
    for (const double elevationDeg : {60.0, 30.0, 15.0}) {
        const double zenith = glm::radians(90.0 - elevationDeg);
        const glm::dvec3 sun = std::cos(zenith) * up + std::sin(zenith) * east;
        s.scene.sun.latitude_deg = glm::degrees(std::asin(sun.z));
        s.scene.sun.longitude_deg = glm::degrees(std::atan2(sun.y, sun.x));
        ImageRGBAF images[2];
        float depth = 1.0f;
        for (int split = 0; split < 2; ++split) {
            renderer->setSunClearStencil(split == 1);
            renderer->render(s.scene, s.camera, size);
            images[split] = readTextureRGBAF(renderer->targets().surfaceRadiance(), size.x, size.y);
            depth = renderer->lastPrepare().clearSkyDepth;
        }
        std::size_t differing = 0;
        for (std::size_t i = 0; i < images[0].pixels.size(); ++i) differing += images[0].pixels[i] != images[1].pixels[i] ? 1 : 0;
        std::printf("sun %4.0f deg up: clear sky depth %g (%.1f km out along the view's axis); %zu values differ\n",
                    elevationDeg, double(depth), depth < 1.0f ? s.camera.near_m / depth / 1000.0 : 0.0, differing);
        EXPECT_EQ(differing, 0u) << elevationDeg;
        EXPECT_LT(depth, 1.0f) << elevationDeg << ": the clear sky around the meadow marks none of it";
        EXPECT_GT(depth, previousDepth) << elevationDeg << ": a lower sun, a nearer depth (larger, reversed-Z)";
        previousDepth = depth;
    }
    renderer->setSunClearStencil(true);
}
