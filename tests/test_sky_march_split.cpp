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
#include "clouds/cloud_model.h"
#include "gl_test_support.h"
#include "render/readback.h"
#include "render/renderer.h"
#include "render/screen_bound.h"

using namespace planet;

namespace {
class SkyMarchSplit : public test::GLTest {};

std::vector<std::uint8_t> readStencil(const gl::Texture& texture, glm::ivec2 size) {
    std::vector<std::uint8_t> values(static_cast<std::size_t>(size.x) * size.y);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture.id(), 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, static_cast<GLsizei>(values.size()),
                      values.data());
    return values;  // rows from the bottom, as GL keeps them
}

std::size_t differingValues(const ImageRGBAF& a, const ImageRGBAF& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i] ? 1 : 0;
    return n;
}

// Whether the ray through pixel (x, imageRow) to its surface point (`distanceM`, 0: none) meets no cloud by
// the CPU's intervals and the clear distance, with a margin of 2 % of it either way: 1 it meets none, 0 it
// reaches past the clear sky, -1 too near the edge to say.
int meetsNoCloud(const Session& s, const clouds::CloudBlock& block, double clearKm, glm::ivec2 size, int x,
                 int imageRow, float distanceM) {
    const glm::dvec3 camera = s.camera.position / 1000.0;
    const glm::dvec3 dir = test::pixelRay(s.camera, size, x, imageRow);
    const double r = glm::length(camera);
    glm::dvec2 first, second;
    const int crossings = clouds::glsl::CloudLayerIntervals(r, glm::dot(camera, dir) / r,
                                                            distanceM > 0.0f ? distanceM / 1000.0 : 1.0e30,
                                                            block.bottomRadius, block.topRadius, first, second);
    if (crossings == 0) return 1;
    const double axisKm = (crossings == 2 ? second.y : first.y) * glm::length(glm::cross(camera, dir)) / r;
    return axisKm < 0.98 * clearKm ? 1 : axisKm > 1.02 * clearKm ? 0 : -1;
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
        const std::vector<std::uint8_t> marks = readStencil(a.stencil, lattice);
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
                        const int meets = meetsNoCloud(s, split.clouds().block(), clearKm, size, px, imageRow, d);
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
            EXPECT_GT(clear, blocks * 4 / 5) << "the meadow and its clear sky";  // (290 of 336 at 96x54)
        }
        if (view == "cumulus" || view == "clouds") {
            EXPECT_GT(cloudy, blocks / 4) << view;
        }
    }
}
