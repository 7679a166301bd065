// Issue 15: the reduced-rate sky march splits off the blocks whose ray meets no cloud (it never enters
// the cloud layer, or crosses it only within the clear sky around the camera; render/sky_no_cloud.frag
// marks them in the lattice's stencil) and marches them with the program built without the clouds' code
// (CLOUDS_OFF; src/render/renderer.cpp, drawSkyMarch), since a software renderer runs that code for
// every pixel, masked, though such a ray's march is one lookup of the air. The march's samples and the
// frame are the same value for value with the split and without it, and the blocks marked are those the
// CPU's own intervals say meet no cloud.
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/session.h"
#include "gl_test_support.h"
#include "no_cloud_rays.h"
#include "render/readback.h"
#include "render/renderer.h"
#include "render/screen_bound.h"

using namespace planet;

namespace {
class SkyMarchSplit : public test::GLTest {};

std::size_t differingValues(const ImageRGBAF& a, const ImageRGBAF& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i] ? 1 : 0;
    return n;
}

}  // namespace

TEST_F(SkyMarchSplit, TheBlocksThatMeetNoCloudAreMarchedWithoutTheCloudsCodeToTheSameValues) {
    const glm::ivec2 size{96, 54};
    for (const std::string view : {"ground", "cumulus", "clouds", "deck", "orbit", "beach"}) {
        Session s = loadSession(test::repoPaths(), "earth", view);
        Renderer split(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        Renderer whole(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        whole.setSkyMarchSplit(false);
        for (int frame = 0; frame < 3; ++frame) {  // (the first without a history may be marched at full rate)
            split.render(s.scene, s.camera, size);
            whole.render(s.scene, s.camera, size);
        }
        ASSERT_TRUE(split.lastPrepare().reducedRate) << view;
        const SparseSky& a = split.targets().sparseSky();
        const SparseSky& b = whole.targets().sparseSky();
        const glm::ivec2 lattice = a.size;
        const std::size_t samples =
            differingValues(readTextureRGBAF(a.inscatter, lattice.x, lattice.y), readTextureRGBAF(b.inscatter, lattice.x, lattice.y)) +
            differingValues(readTextureRGBAF(a.transmittance, lattice.x, lattice.y),
                            readTextureRGBAF(b.transmittance, lattice.x, lattice.y));
        const std::size_t frames = differingValues(readTextureRGBAF(split.targets().hdr(), size.x, size.y),
                                                   readTextureRGBAF(whole.targets().hdr(), size.x, size.y));

        // The marks against the CPU's: a block whose 16 pixels all meet no cloud is marked (its traced
        // pixel is one of them), one whose 16 all reach past the clear sky is not.
        const std::vector<std::uint8_t> marks = test::readStencil(a.stencil, lattice);
        const ImageRGBAF distance = readTextureRGBAF(split.targets().surfaceDistance(), size.x, size.y);
        const double clearKm = split.lastPrepare().clearAxisKm;
        // (The march runs on the blocks around the pixels that can see the air: from orbit, not on space.)
        const ScreenRect drawn = blocksAround(split.lastPrepare().skyBound, 4, lattice);
        std::size_t marked = 0, clear = 0, clearMarked = 0, cloudy = 0, cloudyMarked = 0;
        for (int by = drawn.min.y; by < drawn.max.y; ++by)
            for (int bx = drawn.min.x; bx < drawn.max.x; ++bx) {
                const bool mark = marks[static_cast<std::size_t>(by) * lattice.x + bx] != 0;
                marked += mark;
                int all = 1, none = 1;  // every pixel meets no cloud; every pixel reaches past the clear sky
                for (int py = by * 4; py < std::min(by * 4 + 4, size.y); ++py)
                    for (int px = bx * 4; px < std::min(bx * 4 + 4, size.x); ++px) {
                        const int imageRow = size.y - 1 - py;
                        const float d = test::pixelAt(distance, px, imageRow)[0];
                        const int meets = test::rayMeetsNoCloud(s, split.clouds(), clearKm, size, px, imageRow, d);
                        all &= meets == 1;
                        none &= meets == 0;
                    }
                clear += all;
                clearMarked += all && mark;
                cloudy += none;
                cloudyMarked += none && mark;
            }
        const std::size_t blocks = static_cast<std::size_t>(drawn.area());
        std::printf("%-8s %zu of %zu blocks marked (clear sky %.1f km): %zu of %zu that meet no cloud, %zu of %zu that "
                    "reach past it; %zu sample and %zu frame values differ\n",
                    view.c_str(), marked, blocks, clearKm, clearMarked, clear, cloudyMarked, cloudy, samples, frames);
        EXPECT_EQ(samples, 0u) << view;
        EXPECT_EQ(frames, 0u) << view;
        EXPECT_EQ(clearMarked, clear) << view;
        EXPECT_EQ(cloudyMarked, 0u) << view;
        if (view == "ground") {
            EXPECT_GT(clear, blocks * 4 / 5) << "the meadow and its clear sky";  // (314 of 336 at 96x54)
        }
        if (view == "cumulus" || view == "clouds") {
            EXPECT_GT(cloudy, blocks / 4) << view;
        }
    }
}
