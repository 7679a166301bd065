// Screen-space reflections of the terrain in the sea (issue 13; shaders/ocean/
// screen_space_reflections.glsl), against a CPU ray test.
//
// The scene: the high valley of the 'mountains' view flooded to 2600 m, a lake reaching
// 6.5 km east of the camera with the range rising 2.5 km above it beyond the far shore
// (the 5.1 km summit 17 km away), the lake flat (no waves: a mirror, what the CPU assumes)
// and no clouds; the camera 20 m above the water looking east across it at the range. It is rendered twice, with the reflections and without them (a
// copy of the shader tree with OCEAN_SCREEN_SPACE_REFLECTIONS 0: the sky and clouds alone,
// as before). For every sea pixel the CPU follows the camera's ray to the flat lake and the
// mirror ray on over the terrain's own height field (terrain::HeightField, the GLSL compiled
// as C++):
//   - "land": the mirror ray meets terrain that the camera sees well inside the image: there
//     the reflections must change the pixel, towards the colour of that land;
//   - "sky": the mirror ray clears every mountain by a margin: the pixel must be what it was.
// Pixels within 2 px of the other class are not judged (the GPU's terrain mesh and the
// pixel's own footprint blur the line).
#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <variant>
#include <vector>

#include "app/session.h"
#include "gl_test_support.h"
#include "render/image_compare.h"
#include "render/image_io.h"
#include "render/readback.h"
#include "render/renderer.h"
#include "scene/scene_params.h"

using namespace planet;
namespace fs = std::filesystem;

namespace {

constexpr glm::ivec2 kSize{160, 90};
constexpr double kLakeLevelM = 2600.0;
constexpr double kCameraAboveLakeM = 20.0;

enum class Mirror { Unjudged, Land, Sky };

struct MirrorPixel {
    Mirror kind = Mirror::Unjudged;
    glm::ivec2 land{0};  // Land: the pixel where the camera sees the point the mirror ray meets
};

// The lake: the mountains view's valley with the sea raised into it, flat, without clouds.
Session mountainLake() {
    Session s = loadSession(test::repoPaths(), "earth", "mountains");
    s.scene.clouds.enabled = false;
    // Terrain shadows, where the build has them, only cost time here (the range is lit).
    for (const ParamSpec& spec : sceneParams()) {
        if (spec.path() != "terrain.shadows") continue;
        ParamRef ref = spec.field(s.scene);
        if (bool** on = std::get_if<bool*>(&ref)) **on = false;
    }
    s.scene.ocean.sea_level_m = kLakeLevelM;
    s.scene.waves.clear();
    View v = s.view;
    v.latitude_deg = 41.0;
    v.longitude_deg = -105.452;  // 4 km east of the view's valley, over the flooded floor
    v.heading_deg = 90.0;
    v.pitch_deg = -1.0;
    v.fov_deg = 40.0;
    applyView(v, s);
    // The view's altitude is above the (flooded) ground; the camera belongs above the water.
    const glm::dvec3 up = glm::normalize(s.camera.position);
    s.camera.position = up * (s.scene.planetRadiusM() + kLakeLevelM + kCameraAboveLakeM);
    return s;
}

// The shader tree with the screen-space reflections compiled out, in a temporary folder.
fs::path shadersWithoutReflections() {
    return test::shadersWith("planet_test_ssr_off", "ocean/terrain_reflection_reach.glsl",
                             "#define OCEAN_SCREEN_SPACE_REFLECTIONS 1", "#define OCEAN_SCREEN_SPACE_REFLECTIONS 0");
}

class OceanReflections : public test::GLTest {
protected:
    ImageRGBAF render(const fs::path& shaders, const Session& s) {
        Renderer renderer(shaders, atmosphere::TableSizes::reduced(), s.continents);
        renderer.render(s.scene, s.camera, kSize);
        return readTextureRGBAF(renderer.targets().hdr(), kSize.x, kSize.y);
    }
};

// The CPU's view of the scene: rays through pixels, the terrain along them.
class MirrorRays {
public:
    explicit MirrorRays(const Session& s)
        : s_(s), radius_(s.scene.planetRadiusM()), maxHeight_(s.scene.terrain.max_height_m) {}

    // World direction through the centre of pixel (x, glRow), rows counted from the bottom.
    glm::dvec3 pixelRay(int x, int glRow) const { return test::pixelRay(s_.camera, kSize, x, kSize.y - 1 - glRow); }
    // The pixel a world point is seen in (rows from the bottom); false when behind the camera.
    bool pixelOf(const glm::dvec3& point, glm::dvec2& pixel) const {
        const glm::dvec3 v = glm::transpose(s_.camera.worldFromView()) * (point - s_.camera.position);
        if (v.z >= 0.0) return false;
        const double t = std::tan(0.5 * s_.camera.fovY_rad), aspect = double(kSize.x) / kSize.y;
        const glm::dvec2 ndc(v.x / (-v.z * t * aspect), v.y / (-v.z * t));
        pixel = (ndc * 0.5 + 0.5) * glm::dvec2(kSize);
        return true;
    }
    double clearance(const glm::dvec3& p) const {
        return glm::length(p) - radius_ - s_.ground.height(glm::vec3(glm::normalize(p)));
    }
    // How far along `dir` from `origin` the ray first enters the terrain (-1: never, before
    // it climbs above the highest mountain or runs maxM). `minAngle` is the least clearance
    // over distance on the way: how narrowly it missed.
    double terrainHit(const glm::dvec3& origin, const glm::dvec3& dir, double maxM, double& minAngle) const {
        minAngle = 1.0;
        for (double t = 1.0; t < maxM;) {
            const glm::dvec3 p = origin + t * dir;
            const double c = clearance(p);
            if (c < 0.0) return t;
            if (glm::length(p) - radius_ > maxHeight_ && glm::dot(dir, glm::normalize(p)) > 0.0) return -1.0;
            minAngle = std::min(minAngle, c / t);
            t += std::clamp(0.4 * c, 2.0, 2000.0);
        }
        return -1.0;
    }
    // The mirror ray of pixel (x, glRow) on the flat lake: Land where it meets terrain seen
    // at least `margin` of the image inside its edges, Sky where it clears every mountain by
    // `skyAngle`, else Unjudged (including pixels that are not lake).
    MirrorPixel classify(int x, int glRow, double margin, double skyAngle) const {
        MirrorPixel out;
        const glm::dvec3 camera = s_.camera.position, dir = pixelRay(x, glRow);
        const double lake = radius_ + kLakeLevelM;
        const double b = glm::dot(camera, dir), c = glm::dot(camera, camera) - lake * lake;
        if (b * b - c < 0.0) return out;
        const double toLake = -b - std::sqrt(b * b - c);
        if (toLake <= 0.0) return out;
        double unused = 0.0;
        if (terrainHit(camera, dir, toLake, unused) >= 0.0) return out;  // land in front of the water
        const glm::dvec3 point = camera + toLake * dir, up = glm::normalize(point);
        // Lake depth under 2 m: the shore's fade, not the mirror. (The first version tested
        // the height above the floor "> -2": true for every lake pixel, hence its 0 pixels.)
        if (kLakeLevelM - s_.ground.height(glm::vec3(up)) < 2.0) return out;
        const glm::dvec3 mirror = dir - 2.0 * glm::dot(dir, up) * up;
        double missedBy = 0.0;
        const double hit = terrainHit(point + 0.01 * up, mirror, 400000.0, missedBy);
        if (hit < 0.0) {
            if (missedBy > skyAngle) out.kind = Mirror::Sky;
            return out;
        }
        const glm::dvec3 land = point + hit * mirror;
        glm::dvec2 pixel;
        if (!pixelOf(land, pixel)) return out;
        const glm::dvec2 lo = margin * glm::dvec2(kSize), hi = (1.0 - margin) * glm::dvec2(kSize);
        if (pixel.x < lo.x || pixel.y < lo.y || pixel.x > hi.x || pixel.y > hi.y) return out;
        const glm::dvec3 toLand = land - camera;
        const double distance = glm::length(toLand);
        if (terrainHit(camera, toLand / distance, distance - 0.01 * distance, unused) >= 0.0) return out;  // hidden
        out.kind = Mirror::Land;
        out.land = glm::ivec2(pixel);
        return out;
    }

private:
    const Session& s_;
    double radius_, maxHeight_;
};

const float* at(const ImageRGBAF& image, glm::ivec2 glPixel) {
    return test::pixelAt(image, glPixel.x, image.height - 1 - glPixel.y);
}
double distanceRgb(const float* a, const float* b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}
double luminance(const float* a) { return 0.2126 * a[0] + 0.7152 * a[1] + 0.0722 * a[2]; }
double normRgb(const float* a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

}  // namespace

// Measured (160x90, about 5 s): 858 land pixels, all changed by more than 10 % (mean 0.54),
// 805 (94 %) closer to the land's colour, luminance correlation with the mirrored land
// 0.90; 4478 sky pixels, none changed at all. Able to fail, each seen:
//   - the search's last jittered step short of the segment's end (the shader before this
//     test was enabled): the mountains' reflections are speckle, 476 of 858 changed;
//   - the terrain's radiance fetched 0.1 NDC (4.5 px) above the hit: 628 closer, correlation -0.33;
//   - no reflections at all: nothing changes.
// (The "closer" misses are where the mirror grazes the snowy summits, whose colour is
// near the sky's.)
TEST_F(OceanReflections, TheLakeMirrorsTheMountainsWhereTheMirrorRayMeetsThem) {
    const Session s = mountainLake();
    const ImageRGBAF on = render(test::repoPaths().shaders(), s);
    const ImageRGBAF off = render(shadersWithoutReflections(), s);
    ASSERT_TRUE(test::allFinite(on));
    ASSERT_TRUE(test::allFinite(off));
    fs::create_directories(PLANET_TEST_OUT);
    writeExr(on, fs::path(PLANET_TEST_OUT) / "ocean_reflections_on.exr", s.scene.render.exposure);
    writeExr(off, fs::path(PLANET_TEST_OUT) / "ocean_reflections_off.exr", s.scene.render.exposure);

    // Classify every pixel (the land's edge 15 % in from the image's, where the search fades
    // out, plus 5 %; the sky's margin two pixels' angle), then keep those whose neighbours
    // 2 px away agree.
    const MirrorRays rays(s);
    const double pixelAngle = s.camera.fovY_rad / kSize.y;
    std::vector<MirrorPixel> kinds(kSize.x * kSize.y);
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) kinds[y * kSize.x + x] = rays.classify(x, y, 0.2, 2.0 * pixelAngle);
    auto kindAt = [&](int x, int y) {
        return x < 0 || y < 0 || x >= kSize.x || y >= kSize.y ? Mirror::Unjudged : kinds[y * kSize.x + x].kind;
    };
    auto settled = [&](int x, int y) {
        const Mirror k = kindAt(x, y);
        for (int dy = -2; dy <= 2; dy += 2)
            for (int dx = -2; dx <= 2; dx += 2)
                if (kindAt(x + dx, y + dy) != k) return false;
        return k != Mirror::Unjudged;
    };

    int land = 0, landChanged = 0, landCloser = 0, sky = 0, skyKept = 0;
    double sumW = 0.0, sumM = 0.0, sumWW = 0.0, sumMM = 0.0, sumWM = 0.0;  // luminance: water, the land it mirrors
    double worstSky = 0.0, landChange = 0.0;
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) {
            if (!settled(x, y)) continue;
            const glm::ivec2 p(x, y);
            const double change = distanceRgb(at(on, p), at(off, p)) / std::max(normRgb(at(off, p)), 1e-30);
            if (kinds[y * kSize.x + x].kind == Mirror::Land) {
                ++land;
                landChange += change;
                landChanged += change > 0.1;
                const float* seen = at(on, kinds[y * kSize.x + x].land);  // the land itself, as the camera sees it
                landCloser += distanceRgb(at(on, p), seen) < distanceRgb(at(off, p), seen);
                const double water = luminance(at(on, p)), mirrored = luminance(seen);
                sumW += water;
                sumM += mirrored;
                sumWW += water * water;
                sumMM += mirrored * mirrored;
                sumWM += water * mirrored;
            } else {
                ++sky;
                worstSky = std::max(worstSky, change);
                skyKept += change < 0.01;
            }
        }
    std::printf("land reflections: %d pixels, mean relative change %.3f, %d changed > 10 %%, %d closer to the land\n",
                land, landChange / std::max(land, 1), landChanged, landCloser);
    const double n = std::max(land, 1);
    const double covariance = sumWM / n - sumW / n * (sumM / n);
    const double correlation =
        covariance / std::sqrt(std::max((sumWW / n - sumW / n * (sumW / n)) * (sumMM / n - sumM / n * (sumM / n)), 1e-60));
    std::printf("  luminance correlation of the water with the land it mirrors %.3f\n", correlation);
    std::printf("sky reflections: %d pixels, worst relative change %.2e, %d within 1 %%\n", sky, worstSky, skyKept);
    ASSERT_GE(land, 40) << "the scene no longer shows the range across the lake";
    ASSERT_GE(sky, 40) << "the scene no longer shows open sky in the lake";
    // Where the mirror meets the land, the reflection shows it: nine in ten pixels change by
    // more than 10 % and move towards the land's colour.
    EXPECT_GE(landChanged, 0.9 * land);
    EXPECT_GE(landCloser, 0.9 * land);
    // And it is that land, not some other part of the image: bright snow mirrors bright,
    // dark rock dark, so the water's luminance follows the luminance of the land the CPU
    // says it mirrors.
    EXPECT_GE(correlation, 0.7);
    // Where it meets only sky, nothing changes: the search found nothing there.
    EXPECT_GE(skyKept, 0.99 * sky);
    EXPECT_LT(worstSky, 0.05);
}

namespace {

// One frame of `s` with the shader tree `shaders`: the terrain reflection's list and the image.
struct ListedFrame {
    std::size_t listed = 0;
    ImageRGBAF image;
    bool landOnScreen = false;  // as the surface light marked it
};
ListedFrame renderListed(const fs::path& shaders, const Session& s) {
    Renderer r(shaders, atmosphere::TableSizes::reduced(), s.continents);
    r.render(s.scene, s.camera, kSize);
    return {r.targets().readTerrainReflectionList().size(), readTextureRGBAF(r.targets().hdr(), kSize.x, kSize.y),
            r.targets().readLandOnScreen()};
}

// The shader tree where rays whose reach spans under a pixel are searched too.
fs::path shadersWithoutPixelReach() {
    return test::shadersWith("planet_test_ssr_pixel_reach_off", "ocean/terrain_reflection_reach.glsl",
                             "#define TERRAIN_REFLECTION_PIXEL_REACH 1", "#define TERRAIN_REFLECTION_PIXEL_REACH 0");
}

}  // namespace

// The terrain reflection pass searches only the sea pixels where land may lie within the
// reflected ray's reach (shaders/ocean/screen_space_reflections.glsl's terrainMayBeReflected,
// the continents map's slope bound; issue 15): the image is the one that searching every sea
// pixel gives (to 0.1 % of a pixel's luminance: from space a searched pixel where the height
// field has no land within reach can meet the coarse terrain mesh's chords across a coast,
// 0.014 % in one pixel), and from orbit and from space far fewer are searched (measured: 10 %
// and 11 % at 160x90, where the highest mountain's reach listed 20 % and 38 %: the land within
// the reach of a coast's rays is low, terrainHeightBound; at sea level nearly every ray's long
// reach has land within it, all of the beach's), and with no ground above the sea on screen
// (the `sea` view) none at all (the every-pixel search lists 11680 there). The beach, where the land is reflected, is what fails
// (7.5 %) when the bound lists too few; orbit and space, when it lists too many.
TEST_F(OceanReflections, OnlyPixelsWithLandWithinReachAreSearchedAndThatChangesNoPixel) {
    const fs::path searchAll = test::shadersWith("planet_test_ssr_all", "ocean/terrain_reflection_reach.glsl",
                                                 "#define TERRAIN_REFLECTION_SEARCH_ALL 0",
                                                 "#define TERRAIN_REFLECTION_SEARCH_ALL 1");
    const fs::path withoutPixelReach = shadersWithoutPixelReach();
    struct Case {
        const char* view;
        double maxShare;  // listed by the bound / listed when all are searched, at most
    };
    for (const Case& c : {Case{"orbit", 0.15}, Case{"space", 0.2}, Case{"beach", 1.0}, Case{"sea", 0.0}}) {
        SCOPED_TRACE(c.view);
        const Session s = loadSession(test::repoPaths(), "earth", c.view);
        const ListedFrame bounded = renderListed(withoutPixelReach, s);
        const ListedFrame every = renderListed(searchAll, s);
        const std::size_t listed = bounded.listed, all = every.listed;
        const ImageComparison cmp = compareImages(bounded.image, every.image);
        std::printf("%s: %zu of %zu sea pixels searched; max change %.3g %%\n", c.view, listed, all,
                    100.0 * cmp.maxRelativeError);
        EXPECT_GT(all, std::size_t(kSize.x * kSize.y / 10));  // the sea is in view
        EXPECT_EQ(bounded.landOnScreen, std::string(c.view) != "sea");
        EXPECT_LE(double(listed), c.maxShare * double(all));
        EXPECT_EQ(cmp.nonFinitePixels, 0u);
        EXPECT_LT(cmp.maxRelativeError, 1e-3);
    }
}

// Nor are the rays whose reach below the land near them spans under a pixel on screen (the same
// file's terrainMayBeReflected: a segment of length L seen from at least D - L away subtends at
// most L / (D - L)): the search could only meet the pixel it starts from. From space (pixels of
// 180 km at 160x90, against a reach of a few km) that is nearly every pixel the slope bound lists
// (since the reach is below the land's bound, reachBelowLand, the search finds nothing at those
// either: the image is the same); from orbit a few (the reach below a coast's lowlands spans
// under a 1.2 km pixel at grazing views), at sea level (the beach) none, and there the images are
// the same to the bit. Where it changes anything, it is the coast's pixels, which took the land
// they hold or touch for a reflection over the whole pixel (the true reflection covers its few km
// of the pixel's 180), and nothing else.
TEST_F(OceanReflections, RaysWhoseReachSpansUnderAPixelAreNotSearched) {
    const fs::path withoutPixelReach = shadersWithoutPixelReach();
    for (const char* view : {"space", "orbit", "beach"}) {
        SCOPED_TRACE(view);
        const Session s = loadSession(test::repoPaths(), "earth", view);
        Renderer withRule(test::repoPaths().shaders(), atmosphere::TableSizes::reduced(), s.continents);
        withRule.render(s.scene, s.camera, kSize);
        const std::size_t listed = withRule.targets().readTerrainReflectionList().size();
        const ListedFrame without = renderListed(withoutPixelReach, s);
        const std::size_t listedWithout = without.listed;
        const ImageComparison cmp =
            compareImages(readTextureRGBAF(withRule.targets().hdr(), kSize.x, kSize.y), without.image);
        const auto over = std::count_if(cmp.relativeError.begin(), cmp.relativeError.end(),
                                        [](float e) { return e > 1e-3f; });
        std::printf("%s: %zu searched, %zu without the rule; mean change %.4f %%, max %.3g %% (%td pixels over 0.1 %%)\n",
                    view, listed, listedWithout, 100.0 * cmp.meanRelativeError, 100.0 * cmp.maxRelativeError, over);
        EXPECT_EQ(cmp.nonFinitePixels, 0u);
        // Changed: only pixels within two of ground above the sea (the G-buffer's height, which
        // the sea leaves as the terrain's; without the rule the search, its steps a pixel or more,
        // took land two pixels (360 km) off for what a ray of a few km's reach met, in 3 pixels).
        const ImageRGBAF ground = readTextureRGBAF(withRule.targets().gbuffer().normal, kSize.x, kSize.y);
        const auto isLand = [&](int x, int y) {
            x = std::clamp(x, 0, kSize.x - 1);
            y = std::clamp(y, 0, kSize.y - 1);
            return ground.pixels[4 * std::size_t(y * kSize.x + x) + 3] > s.scene.ocean.sea_level_m;
        };
        std::size_t changedAwayFromLand = 0;
        for (int y = 0; y < kSize.y; ++y)
            for (int x = 0; x < kSize.x; ++x) {
                if (!(cmp.relativeError[std::size_t(y * kSize.x + x)] > 1e-4f)) continue;
                bool nearLand = false;
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) nearLand = nearLand || isLand(x + dx, y + dy);
                if (!nearLand) ++changedAwayFromLand;
            }
        EXPECT_EQ(changedAwayFromLand, 0u);
        if (std::string(view) == "space") {  // nearly every listed ray reaches under a pixel
            EXPECT_GT(listedWithout, std::size_t(100));
            EXPECT_LE(double(listed), 0.05 * double(listedWithout));
            EXPECT_LT(cmp.meanRelativeError, 5e-4);
        } else {  // from 400 km (1.2 km pixels) nearly every listed ray spans pixels, at sea level all
            if (std::string(view) == "beach") {
                EXPECT_EQ(listed, listedWithout);
            }
            EXPECT_LE(listed, listedWithout);
            EXPECT_GE(double(listed), 0.8 * double(listedWithout));
            EXPECT_EQ(cmp.maxRelativeError, 0.0);
        }
    }
}

// The grid's reflection (ocean/grid_reflection.comp, the sea's sky and clouds from high up) is
// not marched at points where no sea can lie in the four cells around them (land above the
// highest crest as far as the farthest neighbour, by the continents' slope bound) nor where those
// cells lie off screen: no fragment reads them. The frames are the same as with every point
// marched, from orbit and over a continent's interior 400 km up, with 1870 and 1304 of the 6400
// points marched (the grid reaches behind the camera and past the view's sides; the land bound
// alone skipped none of them in these views: its cells are 60 km across). Able to fail: a bound
// that skips a point on screen leaves its pixels without their sky (tried: planes 30 km inside the
// view's, 2.2 % and 10.5 %).
TEST_F(OceanReflections, TheGridsReflectionIsNotMarchedWhereNoSeaCanLieAndThatChangesNoPixel) {
    const fs::path everyPoint = test::shadersWith("planet_test_grid_reflection_all", "ocean/grid_reflection.comp",
                                                  "k < (mayBeReadAround(x, y, n) ? 1 : 0)", "k < 1");
    Session inland = loadSession(test::repoPaths(), "earth", "orbit");
    View v = inland.view;
    v.latitude_deg = 30.0;  // the `ground` view's meadow, from orbit, looking down
    v.longitude_deg = -84.0;
    v.pitch_deg = -60.0;
    applyView(v, inland);
    const Session orbit = loadSession(test::repoPaths(), "earth", "orbit");
    for (const Session* s : std::vector<const Session*>{&orbit, &inland}) {
        SCOPED_TRACE(s == &orbit ? "orbit" : "inland");
        Renderer gated(test::repoPaths().shaders(), atmosphere::TableSizes::reduced(), s->continents);
        gated.render(s->scene, s->camera, kSize);
        Renderer all(everyPoint, atmosphere::TableSizes::reduced(), s->continents);
        all.render(s->scene, s->camera, kSize);
        const ImageComparison cmp = compareImages(readTextureRGBAF(gated.targets().hdr(), kSize.x, kSize.y),
                                                  readTextureRGBAF(all.targets().hdr(), kSize.x, kSize.y));
        const auto marched = [](Renderer& r) {
            const int n = r.ocean().gridSize();
            const ImageRGBAF points = readTextureRGBAF(r.ocean().gridReflection(), n, n);
            std::size_t count = 0;
            for (std::size_t i = 0; i < points.pixels.size(); i += 4)
                count += points.pixels[i] != 0.0f || points.pixels[i + 1] != 0.0f || points.pixels[i + 2] != 0.0f;
            return count;
        };
        const std::size_t gatedPoints = marched(gated), allPoints = marched(all);
        std::printf("%s: %zu of %zu points marched; max change %.3g %%\n", s == &orbit ? "orbit" : "inland",
                    gatedPoints, allPoints, 100.0 * cmp.maxRelativeError);
        EXPECT_EQ(cmp.nonFinitePixels, 0u);
        EXPECT_EQ(cmp.maxRelativeError, 0.0);
        EXPECT_LT(gatedPoints, allPoints * 3 / 4) << "off screen, or over land";
    }
}
