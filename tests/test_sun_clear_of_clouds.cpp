// Issue 15: the surface light's ground whose way to the sun surely meets no cloud is lit by the
// program without the clouds' shadow (render/sun_clear_of_clouds.frag marks it in the stencil;
// src/render/renderer.cpp), since a software renderer ran the shadow's code for every pixel, masked,
// though the clear sky check took no sample. The same decision as the shadow's own
// (CloudSunWaySurelyClear against CloudDensityPathToSun): the pictures the same value for value, under
// a clear sky, under the deck, among the clouds and over the sea's dark depths.
#include <cstdio>
#include <string>

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
        std::printf("%-8s %zu of %zu surface radiance values differ (%zu lit)\n", view.c_str(), differing,
                    images[0].pixels.size(), lit);
        EXPECT_GT(lit, 0u) << view;
        EXPECT_EQ(differing, 0u) << view;
    }
    renderer->setSunClearStencil(true);
}
