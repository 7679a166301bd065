// The reduced-rate (temporal) march of clouds and air (render/sky_sparse.frag, render/
// sky_temporal.frag): it marches one pixel of each 4x4 block a frame, converges to the
// full-rate frame with a still camera, leaves a still at full rate, resets where the history
// cannot be trusted, and stays near the full-rate frames along the shipped camera path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "app/session.h"
#include "app/temporal_error.h"
#include "no_cloud_rays.h"
#include "render/image_compare.h"
#include "render/readback.h"
#include "render/renderer.h"
#include "render_support.h"

using namespace planet;

namespace {

ImageRGBAF hdrOf(const Renderer& r, glm::ivec2 size) { return readTextureRGBAF(r.targets().hdr(), size.x, size.y); }

class Temporal : public test::GLTest {
protected:
    static void SetUpTestSuite() {
        GLTest::SetUpTestSuite();
        temporal = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        reference = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    }
    static void TearDownTestSuite() {
        temporal.reset();
        reference.reset();
        GLTest::TearDownTestSuite();
    }
    void TearDown() override { temporal->setFullRateOnReset(true); }
    static Session session(const std::string& view) { return loadSession(test::repoPaths(), "earth", view); }
    // The full-rate frame of a scene (render.temporal off).
    static ImageRGBAF fullRate(Scene scene, const Camera& camera, glm::ivec2 size) {
        scene.render.temporal = false;
        reference->render(scene, camera, size);
        return hdrOf(*reference, size);
    }
    // Frames [first, last) of the shipped takeoff path at `size`, each against its full-rate
    // frame (app/temporal_error.h), the temporal renderer's history starting at `first`. Two new
    // renderers: the terrain's and the sea's grids stay anchored where earlier cameras were
    // (Michelic's persistent grid), so renderers with different pasts draw slightly different
    // surfaces (the suite's own pair: 0.4 % mean error in a frame both march at full rate).
    static std::vector<TemporalFrameError> takeoffErrors(int first, int last, glm::ivec2 size) {
        Session s = session("beach");
        const CameraPath path = loadSessionPath(test::repoPaths(), "takeoff", s);
        Renderer withHistory(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        Renderer atFullRate(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        return measureTemporalError(withHistory, atFullRate, s, path, pathFrameCount(path.file(), std::nullopt), first,
                                    last, size);
    }
    static inline std::unique_ptr<Renderer> temporal;
    static inline std::unique_ptr<Renderer> reference;
};

}  // namespace

TEST_F(Temporal, AFrameWithoutHistoryIsMarchedAtFullRate) {
    // A still (and the first frame of a sequence) is the full-rate frame, pixel for pixel; the
    // next frame of the same camera is marched at the reduced rate.
    const glm::ivec2 size{96, 54};
    Session s = session("cumulus");
    s.scene.time_s = 7.0;  // a scene no other test left in the history
    temporal->render(s.scene, s.camera, size);
    EXPECT_FALSE(temporal->lastPrepare().reducedRate);
    const ImageRGBAF first = hdrOf(*temporal, size);
    const ImageRGBAF full = fullRate(s.scene, s.camera, size);
    EXPECT_EQ(first.pixels, full.pixels);
    temporal->render(s.scene, s.camera, size);
    EXPECT_TRUE(temporal->lastPrepare().reducedRate);
}

TEST_F(Temporal, TheReducedRateMarchesOnePixelOfEach4x4Block) {
    // The march's own count of the pixels it marched (the statistics buffer): the full frame
    // at full rate, one of each 4x4 block (rounded up at the edges) at the reduced rate.
    const glm::ivec2 size{98, 54};  // 25 x 14 blocks, the last column partial
    Session s = session("clouds");
    temporal->setCloudStatistics(true);
    temporal->render(s.scene, s.camera, size);
    EXPECT_FALSE(temporal->lastPrepare().reducedRate);
    EXPECT_EQ(temporal->clouds().marchStatistics().pixels, 98u * 54u);
    temporal->render(s.scene, s.camera, size);
    EXPECT_TRUE(temporal->lastPrepare().reducedRate);
    EXPECT_EQ(temporal->clouds().marchStatistics().pixels, 25u * 14u);
    temporal->setCloudStatistics(false);
}

TEST_F(Temporal, AStillCameraConvergesToTheFullRateFrame) {
    // From the sparse samples alone (the explorer's reset), 32 frames of a still camera:
    // every pixel traced twice, each time with another jitter. Mean relative error in linear
    // luminance under 1 % (image_compare.h). Measured on llvmpipe at 160x90: 0.24-0.68 %
    // after 32 frames (p99 2.5-5.5 %), 2.8-18 % after the first (the spatial estimate alone).
    // From space, the rays that never enter the air skip the reconstruction (T = 1, S = 0):
    // adding a thousandth to their radiance fails this by a factor of 900.
    const glm::ivec2 size{160, 90};
    for (const char* view : {"clouds", "cumulus", "deck", "cloud_sunset", "mountains", "space"}) {
        Session s = session(view);
        const ImageRGBAF reference = fullRate(s.scene, s.camera, size);
        temporal->setFullRateOnReset(false);
        double first = 0.0, last = 0.0;
        for (int frame = 0; frame < 32; ++frame) {
            temporal->render(s.scene, s.camera, size);
            ASSERT_TRUE(temporal->lastPrepare().reducedRate);
            ASSERT_EQ(temporal->lastPrepare().historyValid, frame > 0) << view << " frame " << frame;
            if (frame == 0) first = compareImages(hdrOf(*temporal, size), reference).meanRelativeError;
        }
        const ImageComparison c = compareImages(hdrOf(*temporal, size), reference);
        last = c.meanRelativeError;
        std::printf("%-12s first frame mean %.2f %%, after 32: mean %.3f %%, p99 %.2f %%\n", view, 100 * first,
                    100 * last, 100 * c.errorPercentile(99));
        EXPECT_LT(last, 0.01) << view;
        EXPECT_LT(last, 0.25 * first) << view << ": the history must add what the sparse samples miss";
        EXPECT_EQ(c.nonFinitePixels, 0u);
    }
}

TEST_F(Temporal, PixelsTheHistoryCannotRebuildAreMarchedAtFullRateAndAStillFrameMarksNone) {
    // A still frame marks nothing (the still views of the clouds suite pay nothing for the
    // refine pass: its depth test drops every pixel before the shader runs); a frame after a turn and a climb marks some pixels, not all, and each marked
    // pixel is exactly the full-rate frame's (the same march with the same start).
    const glm::ivec2 size{96, 54};
    Session s = session("clouds");
    s.scene.time_s = 11.0;  // a scene no other test left in the history
    temporal->render(s.scene, s.camera, size);
    temporal->render(s.scene, s.camera, size);
    ASSERT_TRUE(temporal->lastPrepare().reducedRate);
    EXPECT_TRUE(refinedPixels(*temporal, size).empty());
    // The reference from the same first place: the terrain's and the sea's grids stay anchored
    // where a camera was (Michelic's persistent grid), so two renderers show the same surface
    // only after the same camera moves.
    (void)fullRate(s.scene, s.camera, size);

    s.camera.position += 40.0 * s.camera.up();
    s.camera.orientation = glm::angleAxis(glm::radians(1.0), s.camera.up()) * s.camera.orientation;
    s.scene.time_s += 1.0 / 30.0;
    temporal->render(s.scene, s.camera, size);
    ASSERT_TRUE(temporal->lastPrepare().reducedRate);
    ASSERT_TRUE(temporal->lastPrepare().historyValid);
    const std::vector<std::size_t> marked = refinedPixels(*temporal, size);
    std::printf("marked for a full-rate march after a 1 degree turn and a 40 m climb: %zu of %d pixels\n",
                marked.size(), size.x * size.y);
    EXPECT_GT(marked.size(), 0u);
    EXPECT_LT(marked.size(), static_cast<std::size_t>(size.x * size.y) / 2);
    const ImageRGBAF a = hdrOf(*temporal, size);
    const ImageRGBAF b = fullRate(s.scene, s.camera, size);
    // The same march in another program (a compute shader, render/sky_refine.comp, against the
    // full-rate fragment pass): a compiler may contract its arithmetic otherwise. On llvmpipe the
    // difference is 0; with the ray formed from an interpolated NDC instead of the pixel's centre
    // in both, 2.6e-3 (a march's step decisions turn on the rounding).
    double worst = 0.0;
    for (std::size_t i : marked)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(double(a.pixels[4 * i + c]) - b.pixels[4 * i + c]) /
                                        std::max(double(std::abs(b.pixels[4 * i + c])), 1.0e-6));
    std::printf("largest relative difference from the full-rate frame in a marked pixel: %.2e\n", worst);
    EXPECT_LT(worst, 1.0e-3);

    // render.temporal_refine_error 1: only the pixels with nothing to reproject, on an edge, or
    // with a history read across a line or an edge (most of them after this turn).
    Session fewer = session("clouds");
    fewer.scene.time_s = 11.0;
    fewer.scene.render.temporal_refine_error = 1.0;
    temporal->render(fewer.scene, fewer.camera, size);
    temporal->render(fewer.scene, fewer.camera, size);
    fewer.camera = s.camera;
    fewer.scene.time_s = s.scene.time_s;
    temporal->render(fewer.scene, fewer.camera, size);
    ASSERT_TRUE(temporal->lastPrepare().historyValid);
    const std::size_t edgesOnly = refinedPixels(*temporal, size).size();
    std::printf("with render.temporal_refine_error = 1: %zu\n", edgesOnly);
    EXPECT_LT(edgesOnly, marked.size());
}

TEST_F(Temporal, AStillFrameRunsTheStillProgramAndItIsTheGeneralOnesImage) {
    // Where nothing moved, the reconstruction runs its still-frame program (STILL_FRAME: the
    // history's own texel, and the traced pixel's running mean); the general program gives the
    // same frames, pixel for pixel, over 20 still frames (more than a pixel's 16-sample mean),
    // after a first frame at full rate (stills, sequences) or reconstructed from its samples
    // alone (the explorer's reset: its pixels hold no sample of their own until traced); and
    // with the explorer's anti-aliasing moving its sub-pixel jitter every frame, where a pixel at
    // an edge sees another surface from frame to frame (space: the limb). Without the jitter, its
    // build for a jitter that stood (STILL_FRAME_UNJITTERED), with it the one that tests each
    // pixel's surface against its history's. Not when the clock ran
    // (but from high above the clouds, where their drift is far under a pixel).
    const glm::ivec2 size{64, 36};
    for (const char* view : {"cumulus", "space", "clouds"}) {
        const bool fullRateOnReset = view != std::string("clouds");
        Session s = session(view);
        Renderer still(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        Renderer general(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        general.setStillFrameProgram(false);
        still.setFullRateOnReset(fullRateOnReset);
        general.setFullRateOnReset(fullRateOnReset);
        std::size_t differing = 0;
        for (int frame = 0; frame < 20; ++frame) {
            still.render(s.scene, s.camera, size);
            general.render(s.scene, s.camera, size);
            ASSERT_EQ(still.lastPrepare().stillFrame, frame > 0) << view << " frame " << frame;
            ASSERT_EQ(still.lastPrepare().jitterStood, frame > 0) << view << " frame " << frame;  // STILL_FRAME_UNJITTERED
            ASSERT_EQ(still.lastPrepare().reducedRate, frame > 0 || !fullRateOnReset);
            const ImageRGBAF a = hdrOf(still, size), b = hdrOf(general, size);
            for (std::size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i];
        }
        std::size_t differingJittered = 0, surfaceChanged = 0;  // pixels that saw sky, then a surface, or back
        ImageRGBAF distance = readTextureRGBAF(still.targets().surfaceDistance(), size.x, size.y);
        for (int frame = 0; frame < 20; ++frame) {
            for (Renderer* r : {&still, &general}) {
                r->setJitter(glm::dvec2(subPixelJitter(frame)));
                r->render(s.scene, s.camera, size);
            }
            ASSERT_TRUE(still.lastPrepare().stillFrame) << view << " jittered frame " << frame;
            ASSERT_FALSE(still.lastPrepare().jitterStood) << view << " jittered frame " << frame;  // STILL_FRAME
            const ImageRGBAF a = hdrOf(still, size), b = hdrOf(general, size);
            for (std::size_t i = 0; i < a.pixels.size(); ++i) differingJittered += a.pixels[i] != b.pixels[i];
            const ImageRGBAF now = readTextureRGBAF(still.targets().surfaceDistance(), size.x, size.y);
            for (std::size_t i = 0; i < now.pixels.size(); i += 4)
                surfaceChanged += (now.pixels[i] > 0.0f) != (distance.pixels[i] > 0.0f);
            distance = now;
        }
        std::printf("%-8s values that differ between the still and the general program over 20 frames: %zu; 20 "
                    "jittered ones: %zu (pixels whose surface changed: %zu)\n",
                    view, differing, differingJittered, surfaceChanged);
        EXPECT_EQ(differing, 0u) << view;
        EXPECT_EQ(differingJittered, 0u) << view;
        if (view != std::string("clouds")) {
            EXPECT_GT(surfaceChanged, 0u) << view << ": the jitter moved an edge";
        }
        still.setJitter(glm::dvec2(0.0));

        s.scene.time_s += 1.0 / 30.0;
        still.render(s.scene, s.camera, size);
        // From space the clock moves the clouds by a hundred-thousandth of a pixel a frame: still
        // (render/frame_uniforms.h, kStillCloudDriftPx); from under them it moves the frame.
        EXPECT_EQ(still.lastPrepare().stillFrame, view == std::string("space")) << view << ": the clock ran";
    }
}

TEST_F(Temporal, PassesScissoredToTheAirAndTheGroundGiveTheWholeFramesImage) {
    // From orbit and space the sky passes run only on the rectangle that holds the air's sphere
    // (render/screen_bound.h), space drawn around it (render/sky_space.frag), and the terrain
    // shadow and the surface light on the one that holds the ground's highest: the frames are
    // those of the passes run over the whole frame, value for value, at full rate, still, with
    // the clock running and after a move and a turn (which the history must follow across the
    // bound's edge), and from space turned to the sun (no air in view: space and the sun's disc
    // alone); and the rectangle is well inside the frame (else it saves nothing).
    const glm::ivec2 size{96, 54};
    for (const char* view : {"space", "orbit", "sun"}) {
        const bool sun = view == std::string("sun");
        Session s = session(sun ? "space" : view);
        if (sun) {  // from space, turned to the sun: no air in view (an empty bound), the sun's disc on screen
            const glm::dvec3 forward = s.scene.sunDirection();
            const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 0.0, 1.0)));
            s.camera.orientation = orientationFromAxes(right, glm::cross(right, forward), forward);
            s.camera.fovY_rad = glm::radians(5.0);  // the disc (0.27 degrees across) over a few pixels
        }
        Renderer bounded(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        Renderer whole(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        whole.setScreenBounds(false);
        std::size_t differing = 0;
        double share = 0.0, groundShare = 0.0;
        for (int frame = 0; frame < 12; ++frame) {
            if (frame >= 4) s.scene.time_s += 1.0 / 30.0;
            if (frame >= 8) {
                s.camera.position *= 1.002;
                s.camera.orientation = glm::angleAxis(glm::radians(0.5), s.camera.up()) * s.camera.orientation;
            }
            bounded.render(s.scene, s.camera, size);
            whole.render(s.scene, s.camera, size);
            ASSERT_EQ(bounded.lastPrepare().reducedRate, frame > 0);
            ASSERT_TRUE(whole.lastPrepare().skyBound.coversScreen(size));
            share = std::max(share, double(bounded.lastPrepare().skyBound.area()) / (size.x * size.y));
            groundShare = std::max(groundShare, double(bounded.lastPrepare().groundBound.area()) / (size.x * size.y));
            ASSERT_TRUE(whole.lastPrepare().groundBound.coversScreen(size));
            const ImageRGBAF a = hdrOf(bounded, size), b = hdrOf(whole, size);
            for (std::size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i];
        }
        std::printf("%-6s the bounds: the sky passes' at most %.0f %% of the frame, the ground's %.0f %%; values that "
                    "differ from the whole frame's over 12 frames: %zu\n", view, 100 * share, 100 * groundShare, differing);
        EXPECT_EQ(differing, 0u) << view;
        const double most = sun ? 0.0 : view == std::string("space") ? 0.4 : 0.65;
        EXPECT_LE(share, most) << view;
        EXPECT_LE(groundShare, share) << view;
        if (sun) {
            const ImageRGBAF a = hdrOf(bounded, size);
            EXPECT_GT(*std::max_element(a.pixels.begin(), a.pixels.end()), 1000.0f) << "the sun's disc is in view";
        }
    }
}

TEST_F(Temporal, SkyProgramsBuiltForWhatTheirPixelsSeeGiveTheWholeProgramsImage) {
    // The sky passes run, off the sun's disc's rectangle on screen, a build without the disc
    // (NO_SUN_DISC), and where the camera is in the air, one without space's code (CAMERA_IN_AIR):
    // render/sky_air.glsl. The frames are the whole programs' (setScreenBounds(false)), value for
    // value, at full rate and at the reduced rate still, with the clock running and after a move and
    // a turn: at `ground` (the sun off the view: no disc anywhere), at `ground` turned to the sun
    // (its rectangle a few pixels, the programs with and without the disc side by side) and from
    // orbit (the camera above the air).
    const glm::ivec2 size{96, 54};
    for (const char* view : {"ground", "sun", "orbit"}) {
        const bool sun = view == std::string("sun");
        Session s = session(sun ? "ground" : view);
        if (sun) {  // turned to the sun, 3 degrees across: the disc (0.54 degrees) over ten pixels
            const glm::dvec3 forward = s.scene.sunDirection();
            const glm::dvec3 right = glm::normalize(glm::cross(forward, s.camera.up()));
            s.camera.orientation = orientationFromAxes(right, glm::cross(right, forward), forward);
            s.camera.fovY_rad = glm::radians(3.0);
        }
        Renderer bounded(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        Renderer whole(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        whole.setScreenBounds(false);
        std::size_t differing = 0;
        for (int frame = 0; frame < 13; ++frame) {
            if (frame >= 5) s.scene.time_s += 1.0 / 30.0;
            if (frame >= 9) {
                s.camera.position *= 1.0 + 1.0e-7;
                s.camera.orientation = glm::angleAxis(glm::radians(0.05), s.camera.up()) * s.camera.orientation;
            }
            bounded.render(s.scene, s.camera, size);
            whole.render(s.scene, s.camera, size);
            const PrepareReport& p = bounded.lastPrepare();
            ASSERT_EQ(p.reducedRate, frame > 0) << view;  // the first without a history: at full rate (render/sky.frag)
            ASSERT_EQ(p.cameraInAir, view != std::string("orbit")) << view;
            ASSERT_FALSE(whole.lastPrepare().cameraInAir);
            ASSERT_TRUE(whole.lastPrepare().sunDiscBound.coversScreen(size));
            if (sun) {
                ASSERT_FALSE(p.sunDiscBound.empty());
                ASSERT_LT(p.sunDiscBound.area(), size.x * size.y / 20) << "a few pixels around the disc";
            } else if (view == std::string("ground")) {
                ASSERT_TRUE(p.sunDiscBound.empty()) << "the sun is off the view";
            }
            const ImageRGBAF a = hdrOf(bounded, size), b = hdrOf(whole, size);
            for (std::size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i];
            if (sun && frame == 12) {
                EXPECT_GT(*std::max_element(a.pixels.begin(), a.pixels.end()), 1000.0f) << "the sun's disc is in view";
            }
        }
        std::printf("%-6s values that differ from the whole programs' over 13 frames: %zu\n", view, differing);
        EXPECT_EQ(differing, 0u) << view;
    }
}

TEST_F(Temporal, WithOnlyTheClockRunningOnlyTheSamplesErrorsMarkPixels) {
    // The explorer's clock runs while the camera stands: only the clouds move, with the wind, a
    // small fraction of a pixel a frame. The reconstruction marks for a full-rate march only the
    // pixels around a sample its history missed, not every edge and line as in a moving view
    // (there the cumulus field's edges and lines are half of the pixels), and the frames stay
    // near the full-rate ones; there a sample marks at three times the error of a moving frame
    // (its error is mostly its jitter's noise). Measured on llvmpipe at 96x54 over 40 frames:
    // 3.3 % of the pixels a frame, last frame mean 0.54 %; at the moving frame's error (and the
    // history scaled by the samples' noisy gain), 6.9 % (0.59 %); with the edges and lines marked
    // as for a moving camera, 54 % (0.21 %). Since the rays under the layer are rebuilt by the
    // still program (the next test), none a frame, the last frame's mean error the same (0.546 %
    // against 0.545 %): the pixels marked were the meadow's, under the layer.
    const glm::ivec2 size{96, 54};
    Session s = session("cumulus");
    s.scene.time_s = 17.0;  // a scene no other test left in the history
    temporal->render(s.scene, s.camera, size);
    double refined = 0.0;
    constexpr int kFrames = 40;
    for (int frame = 0; frame < kFrames; ++frame) {
        s.scene.time_s += 1.0 / 30.0;
        temporal->render(s.scene, s.camera, size);
        ASSERT_TRUE(temporal->lastPrepare().reducedRate);
        ASSERT_TRUE(temporal->lastPrepare().historyValid);
        refined += static_cast<double>(refinedPixels(*temporal, size).size()) / (size.x * size.y) / kFrames;
    }
    const ImageComparison c = compareImages(hdrOf(*temporal, size), fullRate(s.scene, s.camera, size));
    std::printf("clock running, camera still: %.1f %% of the pixels marched again a frame; last frame mean %.3f %%, "
                "p99 %.2f %%\n", 100 * refined, 100 * c.meanRelativeError, 100 * c.errorPercentile(99));
    EXPECT_LT(refined, 0.05);
    EXPECT_LT(c.meanRelativeError, 0.01);
    EXPECT_EQ(c.nonFinitePixels, 0u);
}

TEST_F(Temporal, WithOnlyTheClockRunningTheRaysThatMeetNoCloudAreRebuiltAsInAStillFrame) {
    // The clock moves only the clouds: a ray that never enters the layer (from under it, to a surface
    // point under it too; from above it, passing above its top) sees nothing it moved, and the still
    // program rebuilds it (src/render/renderer.cpp, drawSkyTemporalSplit): with the clock running,
    // the meadow of the `ground` view is the same, value for value, as with the clock stopped, and
    // so is the sky above the deck of the `deck` view (6 km up, the layer's top at 4 km; the general
    // program gave each traced pixel its newest sample alone: fewer of them are the same). So is a ray
    // that crosses the layer only within the clear sky, around the camera or around where it enters
    // (render/sky_no_cloud.frag: the `ground` view's sky but for a band at the horizon, whose rays reach
    // past it; llvmpipe, 64x36: 1091 of 1091 sky pixels that meet no cloud, 37 of 61 past the clear sky,
    // where the general program leaves many the same by chance; a rule that marked them all would leave
    // all 61). From within the layer (`clouds`, 2.5 km up) no pixel is split off.
    const glm::ivec2 size{64, 36};
    for (const char* view : {"ground", "deck"}) {
        Session s = session(view);
        s.scene.time_s = 27.0;  // a scene no other test left in the history
        Renderer clock(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        Renderer stopped(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        Renderer general(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        general.setStillFrameProgram(false);
        Scene running = s.scene;
        for (int frame = 0; frame < 20; ++frame) {
            if (frame > 0) running.time_s += 1.0 / 30.0;
            clock.render(running, s.camera, size);
            general.render(running, s.camera, size);
            stopped.render(s.scene, s.camera, size);
            if (frame > 0) {
                ASSERT_TRUE(clock.lastPrepare().clockOnlyOffLayer) << view << " frame " << frame;
                ASSERT_FALSE(clock.lastPrepare().stillFrame) << view << " frame " << frame;
                ASSERT_TRUE(stopped.lastPrepare().stillFrame) << view << " frame " << frame;
            }
        }
        const ImageRGBAF distance = readTextureRGBAF(clock.targets().surfaceDistance(), size.x, size.y);
        const ImageRGBAF a = hdrOf(clock, size), b = hdrOf(stopped, size), c = hdrOf(general, size);
        std::size_t ground = 0, same = 0, sameGround = 0, sameGeneral = 0;
        for (std::size_t i = 0; i < distance.pixels.size(); i += 4) {
            const bool equal = std::equal(&a.pixels[i], &a.pixels[i] + 4, &b.pixels[i]);
            same += equal;
            sameGeneral += std::equal(&c.pixels[i], &c.pixels[i] + 4, &b.pixels[i]);
            if (!(distance.pixels[i] > 0.0f)) continue;
            ++ground;
            sameGround += equal;
        }
        // The sky's pixels whose ray crosses the layer and meets no cloud by the CPU's rules (tests/no_cloud_rays.h:
        // within 2 % of a clear distance left out), and those whose ray reaches past the clear sky.
        const double clearKm = clock.lastPrepare().clearAxisKm;
        std::size_t clearSky = 0, sameClearSky = 0, pastClear = 0, samePastClear = 0;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const std::size_t i = (static_cast<std::size_t>(y) * size.x + x) * 4;
                if (distance.pixels[i] > 0.0f) continue;
                const int meets = test::rayMeetsNoCloud(s, clock.clouds(), clearKm, size, x, y, 0.0f);
                const bool equal = std::equal(&a.pixels[i], &a.pixels[i] + 4, &b.pixels[i]);
                clearSky += meets == 1;
                sameClearSky += meets == 1 && equal;
                pastClear += meets == 0;
                samePastClear += meets == 0 && equal;
            }
        std::printf("%s, clock running: %zu of %zu pixels as with the clock stopped (%zu of %zu surface pixels; %zu of "
                    "%zu sky pixels that meet no cloud (the camera's clear sky %.1f km), %zu of %zu past the clear sky; "
                    "the general program alone: %zu)\n",
                    view, same, a.pixels.size() / 4, sameGround, ground, sameClearSky, clearSky, clearKm, samePastClear,
                    pastClear, sameGeneral);
        const std::size_t pixels = static_cast<std::size_t>(size.x) * size.y;
        EXPECT_EQ(compareImages(a, b).nonFinitePixels, 0u) << view;
        if (view == std::string("ground")) {
            EXPECT_GT(ground, pixels / 4);
            EXPECT_EQ(sameGround, ground);
            // The clear sky over the meadow: its rays meet no cloud in any frame (the weather stands), so the
            // still program rebuilds them too; those that reach past it into the clouds' sky it must not.
            EXPECT_GT(clearSky, pixels / 4);
            EXPECT_GT(pastClear, 10u);
            EXPECT_LT(samePastClear, pastClear * 3 / 4);
        } else {
            EXPECT_GT(same, pixels / 4) << "the sky above the deck";
        }
        EXPECT_EQ(sameClearSky, clearSky) << view;
        EXPECT_GT(same, sameGeneral + pixels / 8) << view;  // (llvmpipe, 64x36: ground 2280 against 648, deck 1028 against 569)
    }

    Renderer clock(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    Session within = session("clouds");
    within.scene.time_s = 27.0;
    clock.render(within.scene, within.camera, size);
    within.scene.time_s += 1.0 / 30.0;
    clock.render(within.scene, within.camera, size);
    EXPECT_TRUE(clock.lastPrepare().historyValid);
    EXPECT_FALSE(clock.lastPrepare().clockOnlyOffLayer) << "the camera within the layer";
}

TEST_F(Temporal, WithTheExplorersAntiAliasingAStillCameraWithTheClockOnStaysNearTheFullRate) {
    // The explorer anti-aliases: its sub-pixel jitter moves every frame. With the camera and the
    // sun still, that is no motion of the scene: the history's texels are taken for their own
    // pixels (render/sky_history.glsl), and only the samples' errors mark pixels for the full-rate
    // march, as when only the clock runs without the jitter; a pixel at an edge that sees another
    // surface under the jitter finds no history of it and is marched again. A still camera under
    // the cumulus with the clock on stays near a renderer that marches every pixel and
    // anti-aliases the same way (the same jitter each frame). Measured on llvmpipe at 192x108 over
    // 40 frames, frames 16-39: 15.9 % of the pixels marched again a frame, worst mean 1.43 %, worst
    // 99th percentile 10.8 %; with the jitter's frames taken for moving ones (the edges and lines
    // marked, the history read across texels), 41 % and 0.42 %, 3.2 % (at 96x54: 62 %; at 480x270
    // along cumulus_wind: 19 % against 5.8 %, the sky passes 0.72 against 0.33 of the full rate).
    // The error left is each pixel's last sample's noise and sub-pixel place, held until its next
    // visit, against the full-rate renderer's mean over the last ten or so jittered frames; it
    // shrinks with the pixels (at 480x270 along cumulus_wind: mean 0.83 %, p99 6.1 %).
    const glm::ivec2 size{192, 108};
    Session s = session("cumulus");
    s.scene.time_s = 19.0;
    Renderer explorer(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    Renderer everyPixel(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    explorer.setTemporalAntialiasing(true);
    everyPixel.setTemporalAntialiasing(true);
    Scene full = s.scene;
    full.render.temporal = false;
    explorer.render(s.scene, s.camera, size);
    everyPixel.render(full, s.camera, size);
    double refined = 0.0, worstMean = 0.0, worstP99 = 0.0;
    constexpr int kFrames = 40;
    for (int frame = 0; frame < kFrames; ++frame) {
        s.scene.time_s += 1.0 / 30.0;
        full.time_s = s.scene.time_s;
        explorer.render(s.scene, s.camera, size);
        everyPixel.render(full, s.camera, size);
        ASSERT_TRUE(explorer.lastPrepare().reducedRate);
        ASSERT_TRUE(explorer.lastPrepare().historyValid);
        ASSERT_FALSE(explorer.lastPrepare().stillFrame);
        refined += static_cast<double>(refinedPixels(explorer, size).size()) / (size.x * size.y) / kFrames;
        const ImageComparison c = compareImages(hdrOf(explorer, size), hdrOf(everyPixel, size));
        EXPECT_EQ(c.nonFinitePixels, 0u);
        if (frame < 16) continue;  // after the history's first visits
        worstMean = std::max(worstMean, c.meanRelativeError);
        worstP99 = std::max(worstP99, c.errorPercentile(99));
    }
    std::printf("anti-aliased, clock running, camera still: %.1f %% of the pixels marched again a frame; against "
                "the anti-aliased full rate, frames 16-39: worst mean %.3f %%, worst p99 %.2f %%\n",
                100 * refined, 100 * worstMean, 100 * worstP99);
    EXPECT_LT(refined, 0.25);
    EXPECT_LT(worstMean, 0.02);  // the bars for a path: 3 % and 15 %
    EXPECT_LT(worstP99, 0.15);
}

TEST_F(Temporal, TheHistoryResetsOnAJumpAResizeAParameterChangeAndASunJump) {
    // Each reset makes the next frame a full-rate one (the default policy); a small turn of
    // the sun (a path through dusk) and the clock keep the history.
    const glm::ivec2 size{64, 36};
    Session s = session("deck");
    auto reduced = [&](const Session& x, glm::ivec2 sz = {64, 36}) {
        temporal->render(x.scene, x.camera, sz);
        return temporal->lastPrepare().reducedRate;
    };
    reduced(s);
    EXPECT_TRUE(reduced(s));
    s.scene.time_s += 1.0 / 30.0;
    EXPECT_TRUE(reduced(s)) << "the clock";
    EXPECT_FALSE(reduced(s, {66, 36})) << "resize";
    EXPECT_TRUE(reduced(s, {66, 36}));
    Session far = session("orbit");
    EXPECT_FALSE(reduced(far, {66, 36})) << "jump";
    EXPECT_TRUE(reduced(far, {66, 36}));
    far.scene.clouds.coverage = 0.6;
    EXPECT_FALSE(reduced(far, {66, 36})) << "parameter change";
    EXPECT_TRUE(reduced(far, {66, 36}));
    far.scene.sun.longitude_deg += 0.5;
    EXPECT_TRUE(reduced(far, {66, 36})) << "a half-degree turn of the sun";
    far.scene.sun.longitude_deg += 5.0;
    EXPECT_FALSE(reduced(far, {66, 36})) << "a five-degree jump of the sun";
    far.scene.render.exposure *= 2.0;
    EXPECT_TRUE(reduced(far, {66, 36})) << "the exposure is applied after the history";
    (void)size;
}

TEST_F(Temporal, TheSwitchMarchesEveryPixelEveryFrame) {
    // render.temporal off (--no-temporal, the panel): never the reduced rate, and a camera
    // that stays gives the same frame again.
    const glm::ivec2 size{64, 36};
    Session s = session("clouds");
    s.scene.render.temporal = false;
    temporal->render(s.scene, s.camera, size);
    const ImageRGBAF a = hdrOf(*temporal, size);
    for (int i = 0; i < 3; ++i) {
        temporal->render(s.scene, s.camera, size);
        EXPECT_FALSE(temporal->lastPrepare().reducedRate);
    }
    EXPECT_EQ(hdrOf(*temporal, size).pixels, a.pixels);
}

TEST_F(Temporal, AlongTheTakeoffPathTheFramesStayNearTheFullRateOnes) {
    // The first 1.5 s of the shipped path (the beach, lifting off and pitching up), every frame
    // with the history of the ones before against its full-rate frame, at 160x90: the issue's
    // bar, mean relative error under 3 % and its 99th percentile under 15 % in every frame.
    // Measured on llvmpipe: worst frame 0.19 % and 3.4 %, with a quarter of the pixels marched
    // again at full rate (render/sky_refine.comp). Without that refinement: 4.6-5.6 % and
    // 60-70 %, in the band of distant clouds at the horizon, where a pixel spans many voxels
    // along a grazing ray and no reprojection can predict the full-rate frame's point sample.
    // The share marched again is bounded too (a refinement of every pixel would pass the error
    // bar at the full rate's cost).
    const std::vector<TemporalFrameError> errors = takeoffErrors(0, 46, {160, 90});
    double worstMean = 0.0, worstP99 = 0.0;
    for (const TemporalFrameError& e : errors) {
        EXPECT_EQ(e.reducedRate, e.frame > 0) << "frame " << e.frame;
        EXPECT_LT(e.refinedShare, 0.4) << "frame " << e.frame;
        worstMean = std::max(worstMean, e.meanRelative);
        worstP99 = std::max(worstP99, e.p99Relative);
    }
    std::printf("takeoff frames 0-45 at 160x90: worst mean %.2f %%, worst p99 %.1f %%\n", 100 * worstMean, 100 * worstP99);
    EXPECT_LT(worstMean, 0.03);
    EXPECT_LT(worstP99, 0.15);
}

TEST_F(Temporal, ClimbingAboveTheDeckTheHistoryFollowsTheLight) {
    // 13.3-14.3 s of the shipped path, just above the deck's tops and climbing: the whole frame
    // brightens by a few per cent a frame while the points hardly move, and the pixels between
    // the samples keep a history that lags behind (samples 4 pixels apart, each visited every
    // 16th frame). The reconstruction scales that history by how much the nearest samples
    // found the scene changed (sky_temporal.frag's gain). Judged over the second half, when the
    // history has been built up: the mean relative error averaged over those frames. Measured on
    // llvmpipe: 0.38 %; 1.54 % without the gain.
    const std::vector<TemporalFrameError> errors = takeoffErrors(400, 430, {96, 54});
    double sum = 0.0, worst = 0.0;
    int judged = 0;
    for (const TemporalFrameError& e : errors) {
        if (e.frame < 415) continue;
        ASSERT_TRUE(e.reducedRate) << "frame " << e.frame;
        sum += e.meanRelative;
        worst = std::max(worst, e.meanRelative);
        ++judged;
    }
    std::printf("takeoff frames 415-429 at 96x54: mean error %.2f %% on average, worst %.2f %%\n", 100 * sum / judged,
                100 * worst);
    EXPECT_LT(sum / judged, 0.01);
}
