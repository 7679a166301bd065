// Issue 15: the clouds in the sea's reflection from high up, formed once per grid point rather
// than marched per pixel (src/ocean/flat_mirror.h, shaders/ocean/cloud_reflection.glsl).
// The CPU test that decides it against values worked by hand; where it holds, the frame against
// the one whose every sea pixel marches its own reflected ray; where it does not (the sea seen
// from a ship), the per-pixel march itself.
#include <cmath>

#include "app/session.h"
#include "gl_test_support.h"
#include "ocean/flat_mirror.h"
#include "ocean/ocean_pass.h"
#include "ocean/wave_spectrum.h"
#include "render/image_compare.h"
#include "render/readback.h"
#include "render/renderer.h"

using namespace planet;

TEST(FlatMirror, TheResolvedSlopeIsThatOfTheSinesTheFootprintKeeps) {
    // One sine, A = 0.5 m, 20 m long: k = 2 pi / 20, mean square slope (A k)^2 / 2.
    ocean::GerstnerWave w;
    w.amplitude_m = 0.5;
    w.wavelength_m = 20.0;
    const double ak = 0.5 * 2.0 * M_PI / 20.0;
    const std::vector<ocean::GerstnerWave> waves{w};
    EXPECT_NEAR(ocean::resolvedWaveSlope(waves, 1.0), ak / std::sqrt(2.0), 1e-12);  // 20 footprints: kept
    EXPECT_NEAR(ocean::resolvedWaveSlope(waves, 5.0), ak / std::sqrt(2.0), 1e-12);  // 4: still whole
    EXPECT_NEAR(ocean::resolvedWaveSlope(waves, 20.0 / 3.0), std::sqrt(0.5) * ak / std::sqrt(2.0), 1e-12);  // 3: half
    EXPECT_EQ(ocean::resolvedWaveSlope(waves, 10.0), 0.0);  // 2 footprints: dropped (Nyquist)
    // Two sines: the variances add.
    ocean::GerstnerWave v = w;
    v.amplitude_m = 0.1;
    v.wavelength_m = 2.0;
    const double ak2 = 0.1 * 2.0 * M_PI / 2.0;
    EXPECT_NEAR(ocean::resolvedWaveSlope({w, v}, 0.1), std::sqrt(0.5 * ak * ak + 0.5 * ak2 * ak2), 1e-12);
    EXPECT_NEAR(ocean::resolvedWaveSlope({w, v}, 1.0), ak / std::sqrt(2.0), 1e-12);
}

TEST(FlatMirror, HoldsFromOrbitNotFromAShip) {
    const std::vector<ocean::GerstnerWave> waves = ocean::generateWaves(OceanParams{});
    const double top = 4000.0;  // the earth preset's cloud top, m above the sea
    for (const int height : {270, 720, 1080}) {
        const double pixel = (M_PI / 3.0) / height;  // 60 degrees over the image's height
        EXPECT_TRUE(ocean::seaIsAFlatMirror(waves, 400.0e3, pixel, top)) << height;  // the orbit view
        EXPECT_FALSE(ocean::seaIsAFlatMirror(waves, 30.0, pixel, top)) << height;    // the sea view
        // Where it starts to hold (bisection on the height), and that it holds above.
        double low = 30.0, high = 400.0e3;
        for (int i = 0; i < 60; ++i) {
            const double mid = std::sqrt(low * high);
            (ocean::seaIsAFlatMirror(waves, mid, pixel, top) ? high : low) = mid;
        }
        std::printf("%d px over 60 deg: the sea is a flat mirror from %.1f km up\n", height, high / 1000.0);
        for (double h = high * 1.01; h < 1.0e9; h *= 1.7)
            EXPECT_TRUE(ocean::seaIsAFlatMirror(waves, h, pixel, top)) << h;
        // Its footprint there: the longest wave is barely resolved, so the test is no looser than
        // the waves allow, and finer pixels need a higher camera.
        EXPECT_GT(high * pixel, 0.05 * waves.front().wavelength_m) << height;
    }
    EXPECT_FALSE(ocean::seaIsAFlatMirror(waves, -5.0, 0.004, top));  // under water
    EXPECT_FALSE(ocean::seaIsAFlatMirror(waves, std::nan(""), 0.004, top));
    EXPECT_TRUE(ocean::seaIsAFlatMirror(waves, 9.46e15, 0.004, top));  // a light-year away
    EXPECT_TRUE(ocean::seaIsAFlatMirror({}, 30.0, 0.004, top));        // no waves: a mirror everywhere
}

// A smooth mirror: no wave resolved by any pixel, so no normal tilted at all. It starts where the
// longest wave falls under two of the smallest footprints (gerstnerLod's Nyquist end), worked
// out by hand here, higher than the flat mirror (which allows a small tilt).
TEST(FlatMirror, SmoothWhereTheLongestWaveSpansUnderTwoFootprints) {
    const std::vector<ocean::GerstnerWave> waves = ocean::generateWaves(OceanParams{});
    double longest = 0.0;
    for (const ocean::GerstnerWave& w : waves) longest = std::max(longest, w.wavelength_m);
    for (const int height : {270, 720, 1080}) {
        const double pixel = (M_PI / 3.0) / height;
        const double from = longest / 2.0 / pixel;  // footprint = height above the sea x pixel
        std::printf("%d px over 60 deg: the sea is a smooth mirror from %.1f km up\n", height, from / 1000.0);
        EXPECT_TRUE(ocean::seaIsASmoothMirror(waves, from * 1.0001, pixel)) << height;
        EXPECT_FALSE(ocean::seaIsASmoothMirror(waves, from * 0.99, pixel)) << height;
        EXPECT_TRUE(ocean::seaIsAFlatMirror(waves, from * 1.0001, pixel, 4000.0)) << height;  // flat as well
    }
    const double pixel720 = (M_PI / 3.0) / 720.0;
    EXPECT_TRUE(ocean::seaIsASmoothMirror(waves, 400.0e3, pixel720));  // the orbit view at 1280x720
    EXPECT_FALSE(ocean::seaIsASmoothMirror(waves, 30.0, pixel720));    // the sea view
    EXPECT_FALSE(ocean::seaIsASmoothMirror(waves, -5.0, pixel720));    // under water
    EXPECT_FALSE(ocean::seaIsASmoothMirror(waves, std::nan(""), pixel720));
    EXPECT_TRUE(ocean::seaIsASmoothMirror(waves, 9.46e15, pixel720));  // a light-year away
    EXPECT_TRUE(ocean::seaIsASmoothMirror({}, 30.0, pixel720));        // no waves
}

namespace {

constexpr glm::ivec2 kSize{320, 180};

// Prints how `test` differs from its reference, for the tolerances' record.
void printComparison(const std::string& view, const char* what, const ImageComparison& c) {
    std::printf("%-6s %s: mean %.4f %%, p99 %.3f %%, max %.3f %%, mean luminance %+.4f %%\n", view.c_str(), what,
                100.0 * c.meanRelativeError, 100.0 * c.errorPercentile(99.0), 100.0 * c.maxRelativeError,
                100.0 * c.meanLuminanceDifference);
}

class FlatMirrorFrame : public test::GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    }
    // One full-rate frame of `view` (no history: every frame alike); `samples` false: the clouds in
    // the sea's reflection marched at every pixel (ocean/sea_reflection.glsl), not from samples.
    ImageRGBAF render(const std::string& view, OceanPass::FlatMirror mode, bool samples = true) {
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        renderer->ocean().setFlatMirror(mode);
        renderer->setSeaReflectionSamples(samples);
        renderer->render(s.scene, s.camera, kSize);
        return readTextureRGBAF(renderer->targets().hdr(), kSize.x, kSize.y);
    }
    std::unique_ptr<Renderer> renderer;
};

}  // namespace

TEST_F(FlatMirrorFrame, FromOrbitTheGridsCloudsMatchEveryPixelsOwnMarch) {
    // Tolerances from measurement (orbit, 640x360, the same comparison): the grid's clouds
    // against every pixel's march, mean 0.07 %, p99 1.4 %; the clouds left out of the sea's
    // reflection altogether, mean 0.38 %, p99 4.8 % (so a flat mirror that drops them fails).
    for (const std::string view : {"orbit", "space"}) {
        // (Auto picks the smooth mirror here, a flat one too: the next test.)
        const ImageRGBAF marched = render(view, OceanPass::FlatMirror::Off, false);
        const ImageRGBAF forced = render(view, OceanPass::FlatMirror::On);
        EXPECT_TRUE(renderer->ocean().flatMirror()) << view;
        const ImageComparison c = compareImages(forced, marched);
        printComparison(view, "flat mirror against the per-pixel march", c);
        EXPECT_EQ(c.nonFinitePixels, 0u);
        EXPECT_LT(c.meanRelativeError, 0.002) << view;
        EXPECT_LT(c.errorPercentile(99.0), 0.03) << view;
        EXPECT_LT(std::abs(c.meanLuminanceDifference), 0.003) << view;
    }
}

// Where no pixel resolves a wave (orbit, space), the whole reflected sky comes from the grid's
// points, interpolated: the frame against the flat mirror's, whose fragments look the clear sky
// up along their own rays. Tolerances from measurement (640x360: space mean 0.003 %, p99
// 0.07 %, one pixel at the limb 4.4 %, where a grazing ray's normal is bent towards the viewer;
// orbit mean 0.001 %, p99 0.013 %); the reflection of the clouds alone, without the sky (what
// the flat mirror's grid carries), fails them by far.
TEST_F(FlatMirrorFrame, FromHighUpTheGridsWholeReflectionMatchesEachPixelsOwnSky) {
    for (const std::string view : {"orbit", "space"}) {
        const ImageRGBAF flat = render(view, OceanPass::FlatMirror::On);
        EXPECT_FALSE(renderer->ocean().smoothMirror()) << view;
        const ImageRGBAF automatic = render(view, OceanPass::FlatMirror::Auto);
        EXPECT_TRUE(renderer->ocean().smoothMirror()) << view << ": no pixel resolves a wave";
        EXPECT_TRUE(renderer->ocean().flatMirror()) << view;
        const ImageRGBAF smooth = render(view, OceanPass::FlatMirror::Smooth);
        EXPECT_EQ(automatic.pixels, smooth.pixels) << view;
        const ImageComparison c = compareImages(smooth, flat);
        printComparison(view, "smooth mirror against the flat mirror", c);
        EXPECT_EQ(c.nonFinitePixels, 0u);
        EXPECT_LT(c.meanRelativeError, 2e-4) << view;
        EXPECT_LT(c.errorPercentile(99.0), 3e-3) << view;
        EXPECT_LT(std::abs(c.meanLuminanceDifference), 3e-4) << view;
    }
}

// From a ship the per-pixel program runs (its clouds from the sea reflection pass: tests/
// test_sea_reflection.cpp), to the bit what it is with the flat mirror forced off.
TEST_F(FlatMirrorFrame, FromAShipThePerPixelProgramRuns) {
    for (const std::string view : {"sea", "beach", "clouds"}) {
        const ImageRGBAF automatic = render(view, OceanPass::FlatMirror::Auto);
        EXPECT_FALSE(renderer->ocean().flatMirror()) << view;
        EXPECT_FALSE(renderer->ocean().smoothMirror()) << view;
        const ImageRGBAF marched = render(view, OceanPass::FlatMirror::Off);
        EXPECT_EQ(automatic.pixels, marched.pixels) << view;
    }
}
