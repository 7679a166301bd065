// From space at noon the open sea is darker than the land (issue 13): in every satellite
// image the ocean (remote-sensing reflectance of a few per cent) is much darker than land.
// The `space` view with the sun overhead at the point below the camera, clouds off, 160x90,
// reduced tables: pixels classified by the CPU height field at the ray's hit on the sphere
// (open sea: deeper than 500 m; land: higher than 100 m; between: skipped), their mean
// luminance arriving at the camera (air included) compared. Measured: open sea 0.0478 over
// 1740 pixels, land 0.0733 over 872 (0.0667 while coasts were lit as sea floor) (the land's mean includes its snow; the air's path
// radiance, the same over both, is most of the sea's).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/frame_uniforms.h"
#include "render/image_compare.h"
#include "render_support.h"

namespace {

// Where the ray from `origin` along unit `dir` first meets the sphere of `radius`, or nothing.
bool hitSphere(glm::dvec3 origin, glm::dvec3 dir, double radius, glm::dvec3& hit) {
    const double b = glm::dot(origin, dir);
    const double c = glm::dot(origin, origin) - radius * radius;
    const double discriminant = b * b - c;
    if (discriminant < 0.0) return false;
    const double t = -b - std::sqrt(discriminant);
    if (t < 0.0) return false;
    hit = origin + t * dir;
    return true;
}

// The `space` view rendered at `size` (reduced tables), with, for each pixel whose ray meets
// the sphere, the CPU height field's height at the hit and its direction from the centre.
struct SpacePixel {
    int x, y;
    double luminance;  // arriving at the camera, air included
    float height;      // m above sea level at the ray's hit (CPU height field)
    glm::dvec3 up;     // unit direction of the hit from the planet centre
};

struct SpaceFrame {
    planet::ImageRGBAF image;
    std::vector<SpacePixel> pixels;  // those on the planet's disc
    double luminanceAt(int x, int y) const {
        const float* p = &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4];
        return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    }
};

// From space the ocean draws its far field's per-pixel build, not its mesh (src/ocean/far_field.h),
// unless `seaMesh` forces the mesh.
SpaceFrame renderSpace(planet::Session& session, glm::ivec2 size, bool seaMesh = false,
                       const std::filesystem::path& shaders = planet::test::repoPaths().shaders()) {
    using namespace planet;
    Renderer renderer(shaders, atmosphere::TableSizes::reduced(), session.continents);
    renderer.ocean().setFarFieldAllowed(!seaMesh);
    renderer.render(session.scene, session.camera, size);
    SpaceFrame f{readTextureRGBAF(renderer.targets().hdr(), size.x, size.y), {}};
    EXPECT_TRUE(session.ground.ready());
    const FrameUniforms frame = makeFrameUniforms(session.scene, session.camera, size, 0, std::nullopt);
    const double radius = session.scene.planetRadiusM();
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            // Row 0 of the image is the top; NDC y grows upwards.
            const glm::vec2 ndc((x + 0.5f) / size.x * 2.0f - 1.0f, 1.0f - (y + 0.5f) / size.y * 2.0f);
            const glm::vec4 view = frame.viewFromClip * glm::vec4(ndc, 0.5f, 1.0f);
            const glm::dvec3 dir = glm::normalize(glm::dvec3(glm::mat3(frame.worldFromView) * (glm::vec3(view) / view.w)));
            glm::dvec3 hit;
            if (!hitSphere(session.camera.position, dir, radius, hit)) continue;
            const glm::dvec3 up = glm::normalize(hit);
            f.pixels.push_back({x, y, f.luminanceAt(x, y), session.ground.height(glm::vec3(up)), up});
        }
    return f;
}

}  // namespace

class SeaAndLand : public planet::test::GLTest {};

TEST_F(SeaAndLand, FromSpaceAtNoonTheOpenSeaIsDarkerThanTheLand) {
    using namespace planet;
    Session session = loadSession(test::repoPaths(), "earth", "space");
    session.scene.time_s = 0.0;
    session.scene.clouds.enabled = false;
    session.scene.sun.latitude_deg = 20.0;  // overhead at the view's nadir (20 N, 30 E): noon
    session.scene.sun.longitude_deg = 30.0;
    double sea = 0.0, land = 0.0;
    int seaPixels = 0, landPixels = 0;
    for (const SpacePixel& p : renderSpace(session, {160, 90}).pixels) {
        if (p.height < -500.0f) sea += p.luminance, ++seaPixels;
        if (p.height > 100.0f) land += p.luminance, ++landPixels;
    }
    std::printf("space at noon, clouds off: open sea %d pixels, mean luminance %.4g; land %d pixels, %.4g\n",
                seaPixels, seaPixels ? sea / seaPixels : 0.0, landPixels, landPixels ? land / landPixels : 0.0);
    ASSERT_GT(seaPixels, 500);
    ASSERT_GT(landPixels, 300);
    EXPECT_LT(sea / seaPixels, land / landPixels);
}

// From space no land is lit as sea floor: the under-water light comes from the height field's
// depth, not the mesh's point, whose chords sag hundreds of metres below the sphere between
// vertices from afar (coastal land was dimmed as if deep under water: blue-grey combs and
// dashes along every coast). Land pixels (the CPU height field at the ray's hit 20 m or more
// above the sea, the sun more than 30 degrees up) at 320x180, clouds off: the share darker than half the land's median
// luminance. Measured: 15.3 % lit from the mesh's point, 0.0 % from the height.
TEST_F(SeaAndLand, FromSpaceNoLandIsLitAsSeaFloor) {
    using namespace planet;
    Session session = loadSession(test::repoPaths(), "earth", "space");
    session.scene.time_s = 0.0;
    session.scene.clouds.enabled = false;
    const glm::dvec3 sun = session.scene.sunDirection();
    for (const bool seaMesh : {false, true}) {  // the far field's draw, and the sea's mesh (its fragments' far field)
        std::vector<double> land;
        for (const SpacePixel& p : renderSpace(session, {320, 180}, seaMesh).pixels)
            if (p.height >= 20.0f && glm::dot(p.up, sun) >= 0.5) land.push_back(p.luminance);  // the sun 30 deg up or more
        ASSERT_GT(land.size(), 1000u);
        std::vector<double> sorted = land;
        std::sort(sorted.begin(), sorted.end());
        const double median = sorted[sorted.size() / 2];
        const double dark = double(std::count_if(land.begin(), land.end(), [&](double l) { return l < 0.5 * median; }));
        std::printf("space, clouds off, 320x180, %s: %zu land pixels, %.1f %% darker than half their median luminance\n",
                    seaMesh ? "the sea's mesh" : "the sea's far field", land.size(), 100.0 * dark / double(land.size()));
        EXPECT_LT(dark / double(land.size()), 0.01) << (seaMesh ? "the sea's mesh" : "the far field");
    }
}

// From afar the sky's march ends where the ray meets the height field, not the sagging mesh:
// a mesh point hundreds of metres inside the ground ended the clouds' march below cloud tops
// it should have stopped under, and land reaching into the cloud layer showed speckle and
// dashes. The `space` view with clouds at 640x360: the share of land pixels (as above) that
// differ from the median of their 3x3 neighbourhood by more than 20 % (cloud edges and coasts
// are most of what remains). Measured: 1.4 % ending at the mesh, 0.8 % at the height field.
TEST_F(SeaAndLand, FromSpaceCloudsOverLandHaveNoSpeckle) {
    using namespace planet;
    Session session = loadSession(test::repoPaths(), "earth", "space");
    session.scene.time_s = 0.0;
    const glm::ivec2 size(640, 360);
    const glm::dvec3 sun = session.scene.sunDirection();
    const SpaceFrame frame = renderSpace(session, size);
    int land = 0, speckle = 0;
    for (const SpacePixel& p : frame.pixels) {
        if (p.height < 20.0f || glm::dot(p.up, sun) < 0.5) continue;
        if (p.x == 0 || p.y == 0 || p.x + 1 == size.x || p.y + 1 == size.y) continue;
        double around[9];
        int n = 0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) around[n++] = frame.luminanceAt(p.x + dx, p.y + dy);
        std::nth_element(around, around + 4, around + 9);
        ++land;
        speckle += std::abs(p.luminance - around[4]) > 0.2 * around[4];
    }
    ASSERT_GT(land, 1000);
    std::printf("space with clouds, 640x360: %d land pixels, %.1f %% off their 3x3 median by > 20 %%\n", land,
                100.0 * speckle / land);
    EXPECT_LT(double(speckle) / land, 0.01);
}

// The sea floor's dark depths are not lit (shaders/ocean/water.glsl's SEA_FLOOR_DARK_DEPTH_M,
// 400 m: under a millionth of the light reaches there): the surface light leaves them black and
// the terrain's shadow marches none there. The image is the one that lighting them gives (the
// `sea` view; and from 5 m under the beach's water looking down the shelf, where the floor is
// seen through the water itself), and the shadow's samples on the open sea's floor are left
// unmarched (no surface, as the sky's). Able to fail: a depth too shallow darkens the floor seen
// from under the water (from above the sea, in these views, no pixel changes even at 2 m: the
// floor shows through only the shallowest water); no skip at all leaves the sea's samples marched.
TEST_F(SeaAndLand, TheDarkDepthsOfTheSeaFloorAreNotLitAndThatChangesNoPixel) {
    using namespace planet;
    const std::filesystem::path litEverywhere =
        test::shadersWith("planet_test_dark_floor_lit", "ocean/water.glsl", "const float SEA_FLOOR_DARK_DEPTH_M = 400.0;",
                          "const float SEA_FLOOR_DARK_DEPTH_M = 1.0e9;");
    const glm::ivec2 size{160, 90};
    // Samples that say "no surface" (render/sample_spacing.glsl's TERRAIN_SHADOW_NO_SURFACE, -1e30).
    auto unmarched = [](const Renderer& r) {
        const TerrainShadowSamples& samples = r.targets().terrainShadowSamples();
        const ImageRGBAF clearance = readTextureRGBAF(samples.visibility, samples.size.x, samples.size.y);
        int n = 0;
        for (std::size_t i = 0; i < clearance.pixels.size(); i += 4) n += clearance.pixels[i] < -1.0e29f;
        return n;
    };
    for (const char* view : {"sea", "beach"}) {
        SCOPED_TRACE(view);
        Session s = loadSession(test::repoPaths(), "earth", view);
        if (std::string(view) == "beach") {  // out over the water, 5 m under it, looking down the shelf
            View v = s.view;
            v.pitch_deg = -35.0;
            applyView(v, s);
            const glm::dvec3 up = glm::normalize(s.camera.position);
            glm::dvec3 ahead = -glm::dvec3(s.camera.worldFromView()[2]);
            ahead = glm::normalize(ahead - glm::dot(ahead, up) * up);
            for (double out = 0.0; out < 5000.0; out += 50.0) {  // the first place with 15 m of water
                const glm::dvec3 there = glm::normalize(up * s.scene.planetRadiusM() + ahead * out);
                if (s.ground.height(glm::vec3(there)) > s.scene.ocean.sea_level_m - 15.0) continue;
                s.camera.position = there * (s.scene.planetRadiusM() + s.scene.ocean.sea_level_m - 5.0);
                break;
            }
            ASSERT_GT(cameraDepthBelowSeaM(s.scene, s.camera), 0.0);
        }
        // The floor drawn where the sea covers it (the terrain leaves out its dark depths where its
        // patches are small enough for the bound, test_ocean_culling.cpp; not from orbit).
        Renderer skipping(test::repoPaths().shaders(), atmosphere::TableSizes::reduced(), s.continents);
        skipping.setDarkFloorCulling(false);
        skipping.render(s.scene, s.camera, size);
        const ImageRGBAF image = readTextureRGBAF(skipping.targets().hdr(), size.x, size.y);
        Renderer lighting(litEverywhere, atmosphere::TableSizes::reduced(), s.continents);
        lighting.setDarkFloorCulling(false);
        lighting.render(s.scene, s.camera, size);
        const ImageComparison cmp = compareImages(image, readTextureRGBAF(lighting.targets().hdr(), size.x, size.y));
        const int skipped = unmarched(skipping), sky = unmarched(lighting);
        std::printf("%s: %d shadow samples unmarched (%d, the sky's, when every floor is lit); max change %.3g %%\n",
                    view, skipped, sky, 100.0 * cmp.maxRelativeError);
        if (std::string(view) == "sea") {
            EXPECT_GT(skipped, sky + size.x * size.y / 16);  // a quarter of the samples more: the deep floor's
        }
        EXPECT_EQ(cmp.nonFinitePixels, 0u);
        EXPECT_LT(cmp.maxRelativeError, 1e-4);
    }
}

// Issue 15: the surface light marks the sea floor's dark depths in a stencil first (render/
// surface_marks.frag) and runs its lighting program only on the rest, its dark depths' program
// (SEA_FLOOR_DARK: their distance, no light) only on them, so that a software renderer no longer
// shades the whole sea floor masked (`orbit` 1280x720: 30 -> 13 ms, `sea` 71 -> 32;
// docs/PERFORMANCE.md, sixteenth). Where the sea is drawn over them from above (the camera above it)
// the dark depths' program does not run at all: the ocean writes their distance and radiance (from
// orbit most marked pixels have no ground, where it ran its whole body to discard; 9-10 ms at
// 1280x720). The surface radiance before the sea (its colour: 0 at the dark depths either way; the
// alpha, which no pass reads there, is left to the ocean) and the frame are those of the lighting
// program alone, to the bit; and the lighting program never runs on a dark pixel:
// a copy of it that paints the pixels it leaves dark 1000 paints none with the stencil, and
// thousands without it (the test's way to fail: a stencil that keeps nothing off).
TEST_F(SeaAndLand, TheSurfaceLightsStencilKeepsItsLightingOffTheDarkDepthsAndChangesNoPixel) {
    using namespace planet;
    const std::string lit =
        "    if (underSea < SEA_FLOOR_DARK_DEPTH_M) outSurfaceRadiance = vec4(surfaceRadiance(pixel, surface, underSea), 1.0);";
    const std::filesystem::path painting =
        test::shadersWith("planet_test_dark_painted", "render/surface_light.frag", lit,
                          lit + "\n    else outSurfaceRadiance = vec4(1000.0);");
    const glm::ivec2 size{160, 90};
    for (const char* view : {"sea", "orbit", "beach"}) {
        SCOPED_TRACE(view);
        Session s = loadSession(test::repoPaths(), "earth", view);
        struct Frame {
            ImageRGBAF seabed, hdr;
        };
        auto render = [&](const std::filesystem::path& root, bool stencil) {
            Renderer r(root, atmosphere::TableSizes::reduced(), s.continents);
            r.setSeaFloorDarkStencil(stencil);
            r.setDarkFloorCulling(false);  // the floor drawn where the sea covers it (not from orbit anyway)
            r.render(s.scene, s.camera, size);
            return Frame{readTextureRGBAF(r.targets().seabedRadiance(), size.x, size.y),
                         readTextureRGBAF(r.targets().hdr(), size.x, size.y)};
        };
        auto painted = [](const ImageRGBAF& image) {
            int n = 0;
            for (std::size_t i = 0; i < image.pixels.size(); i += 4) n += image.pixels[i] == 1000.0f;
            return n;
        };
        const Frame apart = render(test::repoPaths().shaders(), true);
        const Frame together = render(test::repoPaths().shaders(), false);
        auto colour = [](const ImageRGBAF& image) {
            std::vector<float> rgb;
            for (std::size_t i = 0; i < image.pixels.size(); i += 4)
                rgb.insert(rgb.end(), image.pixels.begin() + std::ptrdiff_t(i), image.pixels.begin() + std::ptrdiff_t(i + 3));
            return rgb;
        };
        EXPECT_EQ(colour(apart.seabed), colour(together.seabed));  // the same program, or 0 from both
        // (The dark depths' distance from the other program: another driver may round it apart.)
        const ImageComparison frame = compareImages(apart.hdr, together.hdr);
        EXPECT_EQ(frame.nonFinitePixels, 0u);
        EXPECT_LT(frame.meanRelativeError, 1e-6);
        EXPECT_LT(frame.maxRelativeError, 1e-4);
        const int paintedApart = painted(render(painting, true).seabed);
        const int paintedTogether = painted(render(painting, false).seabed);
        std::printf("%s: the dark depths painted by the lighting program: %d pixels with the stencil, %d without\n",
                    view, paintedApart, paintedTogether);
        EXPECT_EQ(paintedApart, 0);
        if (std::string(view) != "beach") {
            EXPECT_GT(paintedTogether, size.x * size.y / 10);  // the open sea's floor
        }
    }
}

// From orbit at dusk the sun's glitter on the sea fades out over the terminator as the sun's disc
// sets (the sun's irradiance there, atmosphere/functions.glsl's SunAboveHorizonFraction), with no
// line: ocean/sea_light.frag once cut the glitter where the disc's centre set, at half its
// brightness, a hard line straight across the glitter's column seen from orbit. Looking east from
// 400 km with the sun 5 degrees below the camera's horizon, clouds off, 320x180: the largest
// luminance ratio between vertically adjacent open-sea pixels (the CPU height field 200 m or more
// below the sea at both hits) against a copy of the shaders with the old cut. Measured on llvmpipe:
// 1.14, and 1.45 with the cut.
TEST_F(SeaAndLand, FromOrbitTheGlitterFadesOverTheTerminatorWithoutALine) {
    using namespace planet;
    Session session = loadSession(test::repoPaths(), "earth", "orbit");
    session.scene.time_s = 0.0;
    session.scene.clouds.enabled = false;
    View dusk;
    dusk.latitude_deg = 20.0;
    dusk.longitude_deg = 10.0;
    dusk.altitude_m = 400e3;
    dusk.heading_deg = 90.0;
    dusk.pitch_deg = -28.0;
    dusk.fov_deg = 30.0;
    dusk.sun_elevation_deg = -5.0;
    dusk.sun_azimuth_deg = 90.0;
    applyView(dusk, session);
    const std::filesystem::path cut = test::shadersWith("planet_test_glitter_cut", "ocean/sea_light.frag",
                                                        "bool sunUp = dot(up, sun) > -radius;",
                                                        "bool sunUp = dot(up, sun) > 0.0;");
    const glm::ivec2 size{320, 180};
    double worst[2] = {1.0, 1.0};
    for (int variant = 0; variant < 2; ++variant) {
        const SpaceFrame f = renderSpace(session, size, false, variant == 0 ? test::repoPaths().shaders() : cut);
        std::vector<const SpacePixel*> at(std::size_t(size.x) * size.y, nullptr);
        for (const SpacePixel& p : f.pixels) at[std::size_t(p.y) * size.x + p.x] = &p;
        int pairs = 0;
        for (int y = 0; y + 1 < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const SpacePixel* a = at[std::size_t(y) * size.x + x];
                const SpacePixel* b = at[std::size_t(y + 1) * size.x + x];
                if (!a || !b || a->height > -200.0f || b->height > -200.0f) continue;
                if (std::max(a->luminance, b->luminance) <= 0.0) continue;
                worst[variant] = std::max(worst[variant], std::max(a->luminance, b->luminance) /
                                                              std::max(std::min(a->luminance, b->luminance), 1e-12));
                ++pairs;
            }
        ASSERT_GT(pairs, 5000) << "open sea in view";
    }
    std::printf("orbit at dusk, 320x180: the largest ratio between vertically adjacent sea pixels %.3f (the cut at "
                "the disc's centre: %.3f)\n",
                worst[0], worst[1]);
    EXPECT_LT(worst[0], 1.25);
    EXPECT_GT(worst[1], 1.35) << "the old cut is seen (the test can fail)";
}
