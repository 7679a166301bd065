// Issue 15: frames that see the clouds in the far field alone (from space) run programs built
// for it, CLOUD_FAR_FIELD_ONLY (shaders/clouds/cloud_density.glsl): the volume is never read and
// the sun's way through the layer is the closed form. The CPU test that decides it against
// values worked by hand, and the frames against those of the general programs.
#include <cmath>
#include <limits>

#include "app/session.h"
#include "clouds/cloud_block.h"
#include "gl_test_support.h"
#include "render/image_compare.h"
#include "render/readback.h"
#include "render/renderer.h"

using namespace planet;
namespace fs = std::filesystem;

namespace {

// A layer from 6371 + 1.5 to 6371 + 4 km, voxels of 0.25 km, pixels of 1 mrad.
clouds::CloudBlock sampleBlock() {
    clouds::CloudBlock b{};
    b.bottomRadius = 6372.5f;
    b.topRadius = 6375.0f;
    b.voxelKm = 0.25f;
    b.pixelAngle = 1.0e-3f;
    b.enabled = 1;
    return b;
}

}  // namespace

TEST(CloudFarField, HoldsWhereTheNearestPointsFootprintSpansEightVoxels) {
    const clouds::CloudBlock b = sampleBlock();
    // The ground's highest at 6380 km (above the layer's top): the nearest point anything is seen
    // at is (r - 6380) km away, its footprint that times 1 mrad; 8 voxels are 2 km, so from
    // r = 6380 + 2000 = 8380 km, with the 2 % margin 8420 km.
    EXPECT_FALSE(clouds::seenInFarFieldOnly(b, 8380.0, 6380.0));
    EXPECT_FALSE(clouds::seenInFarFieldOnly(b, 8419.0, 6380.0));
    EXPECT_TRUE(clouds::seenInFarFieldOnly(b, 8421.0, 6380.0));
    EXPECT_TRUE(clouds::seenInFarFieldOnly(b, 1.0e9, 6380.0));  // a billion km: far too
    // The ground lower than the layer's top: the top decides, 6375 + 2040 km.
    EXPECT_FALSE(clouds::seenInFarFieldOnly(b, 8414.0, 6371.0));
    EXPECT_TRUE(clouds::seenInFarFieldOnly(b, 8416.0, 6371.0));
    // Twice the pixel angle halves the distance: 6375 + 1020 km.
    clouds::CloudBlock wide = b;
    wide.pixelAngle = 2.0e-3f;
    EXPECT_FALSE(clouds::seenInFarFieldOnly(wide, 7394.0, 6371.0));
    EXPECT_TRUE(clouds::seenInFarFieldOnly(wide, 7396.0, 6371.0));
    // No far field: a layer of constant density, no volume (voxelKm "none"), no pixel angle; and
    // a camera in or under the layer.
    clouds::CloudBlock constant = b;
    constant.constantDensity = 1;
    EXPECT_FALSE(clouds::seenInFarFieldOnly(constant, 1.0e9, 6371.0));
    clouds::CloudBlock noVolume = b;
    noVolume.voxelKm = 1.0e30f;
    EXPECT_FALSE(clouds::seenInFarFieldOnly(noVolume, 1.0e9, 6371.0));
    clouds::CloudBlock noPixel = b;
    noPixel.pixelAngle = 0.0f;
    EXPECT_FALSE(clouds::seenInFarFieldOnly(noPixel, 1.0e9, 6371.0));
    EXPECT_FALSE(clouds::seenInFarFieldOnly(b, 6373.0, 6371.0));
    EXPECT_FALSE(clouds::seenInFarFieldOnly(b, std::numeric_limits<double>::quiet_NaN(), 6371.0));
}

namespace {

constexpr glm::ivec2 kSize{320, 180};

class CloudFarFieldFrame : public test::GLTest {
protected:
    // One frame of `view` with the far field's programs allowed or not, from a renderer of its
    // own (the same frame index, the same history); `temporal`: the reduced rate (its first
    // frame: the full rate, then one from the history).
    ImageRGBAF render(const std::string& view, bool farFieldPrograms, bool temporal) {
        renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = temporal;
        renderer->setCloudFarFieldPrograms(farFieldPrograms);
        renderer->render(s.scene, s.camera, kSize);
        if (temporal) renderer->render(s.scene, s.camera, kSize);
        return readTextureRGBAF(renderer->targets().hdr(), kSize.x, kSize.y);
    }
    std::unique_ptr<Renderer> renderer;
};

}  // namespace

// From orbit (400 km: the nearest clouds' footprint is 2.3 km at this size, 37 voxels) and from
// space (30 000 km) every footprint spans the far field: the frame with its programs is the
// general programs' frame (on llvmpipe to the bit, at both rates; the bounds leave another
// driver its rounding of the general programs' blend, whose weight is exactly 1 there). A
// far-field program that is off by a tenth in the clouds' density fails by far (measured: mean
// 0.3-0.6 %, max 4-5 %).
TEST_F(CloudFarFieldFrame, FromHighUpTheFarFieldsProgramsGiveTheGeneralProgramsFrame) {
    for (const std::string view : {"orbit", "space"}) {
        for (const bool temporal : {false, true}) {
            const ImageRGBAF general = render(view, false, temporal);
            EXPECT_FALSE(renderer->lastPrepare().cloudFarField);
            const ImageRGBAF far = render(view, true, temporal);
            EXPECT_TRUE(renderer->lastPrepare().cloudFarField) << view << ": every footprint is the far field's";
            const ImageComparison c = compareImages(far, general);
            std::printf("%s, %s: far-field programs against the general ones: mean %.6f %%, p99 %.5f %%, max %.4f %%\n",
                        view.c_str(), temporal ? "reduced rate" : "full rate", 100.0 * c.meanRelativeError,
                        100.0 * c.errorPercentile(99.0), 100.0 * c.maxRelativeError);
            EXPECT_EQ(c.nonFinitePixels, 0u);
            EXPECT_LT(c.meanRelativeError, 1e-6) << view << " " << temporal;
            EXPECT_LT(c.maxRelativeError, 1e-4) << view << " " << temporal;
        }
    }
}

// The far field's slices (shaders/clouds/cloud_march.glsl, CLOUD_FAR_FIELD_SLICE_KM): from orbit and
// from space a crossing of the layer seen in the far field takes one atmosphere slice per 10 km of
// its length, where it took the preset's four. Against a copy of the shaders that keeps the four
// (a slice of 1 m), the frames move by a tenth of a percent on average (measured at 320x180, full
// rate: orbit mean 0.08 %, p99 0.8 %, max 4 %; space 0.11 %, 2.2 %, 19 % in a pixel at the disc's
// edge), and not at all where the camera is near or in the layer (its near crossings are not in
// the far field, its far ones are long): the cumulus and deck views to the bit. A rule that did
// nothing would leave the orbit and space frames equal.
TEST_F(CloudFarFieldFrame, AShortCrossingSeenInTheFarFieldTakesOneSlicePerTenKilometres) {
    const fs::path fourSlices = test::shadersWith("planet_test_far_field_slices", "clouds/cloud_march.glsl",
                                                  "const Length CLOUD_FAR_FIELD_SLICE_KM = 10.0;",
                                                  "const Length CLOUD_FAR_FIELD_SLICE_KM = 1.0e-3;");
    for (const std::string view : {"orbit", "space", "cumulus", "deck"}) {
        SCOPED_TRACE(view);
        const ImageRGBAF sliced = render(view, true, false);
        Renderer preset(fourSlices, atmosphere::TableSizes::reduced());
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        preset.render(s.scene, s.camera, kSize);
        const ImageRGBAF four = readTextureRGBAF(preset.targets().hdr(), kSize.x, kSize.y);
        const ImageComparison c = compareImages(sliced, four);
        std::printf("%-8s one slice per 10 km against four: mean %.4f %%, p99 %.3f %%, max %.3f %%\n", view.c_str(),
                    100.0 * c.meanRelativeError, 100.0 * c.errorPercentile(99.0), 100.0 * c.maxRelativeError);
        EXPECT_EQ(c.nonFinitePixels, 0u);
        if (view == "orbit" || view == "space") {
            EXPECT_GT(c.meanRelativeError, 1e-5) << "the rule leaves slices out";
            EXPECT_LT(c.meanRelativeError, 3e-3);
            EXPECT_LT(c.errorPercentile(99.0), 0.03);
        } else {
            EXPECT_EQ(c.maxRelativeError, 0.0);
        }
    }
}

// Under the clouds (the cumulus view) the nearest footprints are finer than a voxel: the far
// field's programs are not used, and the frame is the general programs' to the bit.
TEST_F(CloudFarFieldFrame, UnderTheCloudsTheGeneralProgramsRun) {
    const ImageRGBAF general = render("cumulus", false, false);
    const ImageRGBAF allowed = render("cumulus", true, false);
    EXPECT_FALSE(renderer->lastPrepare().cloudFarField) << "the camera under the layer";
    EXPECT_EQ(allowed.pixels, general.pixels);
}

namespace {

// How a frame comes to have no cloud layer: the preset's clouds off (the sky at full rate), or
// on with no coverage (the cloud block's `enabled` 0 all the same; the reduced rate runs).
enum class NoClouds { PresetOff, NoCoverage };

class CloudsOffFrame : public test::GLTest {
protected:
    // One frame of `view` without clouds, with the CLOUDS_OFF programs allowed or not, from a
    // renderer of its own; with no coverage the temporal march's second frame (from the history).
    ImageRGBAF render(const std::string& view, NoClouds how, bool offPrograms) {
        renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        Session s = loadSession(test::repoPaths(), "earth", view);
        if (how == NoClouds::PresetOff) s.scene.clouds.enabled = false;
        else s.scene.clouds.coverage = 0.0;
        s.scene.render.temporal = true;
        renderer->setCloudsOffPrograms(offPrograms);
        renderer->render(s.scene, s.camera, kSize);
        if (how == NoClouds::NoCoverage) renderer->render(s.scene, s.camera, kSize);
        return readTextureRGBAF(renderer->targets().hdr(), kSize.x, kSize.y);
    }
    std::unique_ptr<Renderer> renderer;
};

}  // namespace

// Issue 15: a frame without clouds runs every program that reads them built without their code
// (CLOUDS_OFF): the clear sky pass at `orbit` on llvmpipe, which ran the layer's code for every
// pixel behind the test of `enabled`, costs half as much (docs/PERFORMANCE.md, sixteenth). The
// frame is the general programs' (on llvmpipe to the bit; the bounds leave another driver its
// rounding), from orbit and at the beach (sea, land, sky), at full rate and at the reduced rate.
TEST_F(CloudsOffFrame, WithoutCloudsTheProgramsBuiltWithoutThemGiveTheGeneralProgramsFrame) {
    for (const std::string view : {"orbit", "beach"}) {
        for (const NoClouds how : {NoClouds::PresetOff, NoClouds::NoCoverage}) {
            const char* name = how == NoClouds::PresetOff ? "clouds off" : "no coverage";
            const ImageRGBAF general = render(view, how, false);
            EXPECT_FALSE(renderer->lastPrepare().cloudsOff);
            EXPECT_EQ(renderer->lastPrepare().reducedRate, how == NoClouds::NoCoverage) << view << " " << name;
            const ImageRGBAF off = render(view, how, true);
            EXPECT_TRUE(renderer->lastPrepare().cloudsOff) << view << " " << name << ": no cloud layer";
            EXPECT_FALSE(renderer->lastPrepare().cloudFarField) << "never with the far field's programs";
            const ImageComparison c = compareImages(off, general);
            std::printf("%s, %s: programs without clouds against the general ones: mean %.6f %%, max %.4f %%\n",
                        view.c_str(), name, 100.0 * c.meanRelativeError, 100.0 * c.maxRelativeError);
            EXPECT_EQ(c.nonFinitePixels, 0u);
            EXPECT_LT(c.meanRelativeError, 1e-6) << view << " " << name;
            EXPECT_LT(c.maxRelativeError, 1e-4) << view << " " << name;
        }
    }
}

// With clouds the general programs run: the programs without them are never picked for a frame
// that has a layer (they would draw a clear sky: the orbit frame's clouds are a third of it).
TEST_F(CloudsOffFrame, WithCloudsTheGeneralProgramsRun) {
    for (const std::string view : {"orbit", "cumulus"}) {
        renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        Session s = loadSession(test::repoPaths(), "earth", view);
        renderer->render(s.scene, s.camera, kSize);
        EXPECT_FALSE(renderer->lastPrepare().cloudsOff) << view;
    }
}
