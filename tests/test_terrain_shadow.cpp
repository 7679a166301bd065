// Terrain shadows (shaders/terrain/terrain_shadow.glsl, compiled as C++ by
// terrain/terrain_shadow.cpp, and the frame's surface light through SunVisibility):
//   - the CPU twin against cases known without a march: the disc's circular segment, flat
//     ground (lit above the horizon, the disc's share at it, dark below), the far side of a
//     summit whose elevation is computed directly;
//   - the CPU twin against a fine reference march (every 20 m near, 0.2 % of the distance
//     far, all octaves, in double but for the heights) over the mountains around the
//     'mountains' view at a 5 deg sun;
//   - the GPU's shadows in the 'mountains' view at a 5 deg sun against the reference march
//     at the pixels' points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "app/session.h"
#include "atmosphere/parameters.h"
#include "gl_test_support.h"
#include "noise/continents.h"
#include "ocean/land_cull.h"
#include "render/readback.h"
#include "render/renderer.h"
#include "terrain/height.h"
#include "terrain/terrain_shadow.h"

using namespace planet;

namespace {

constexpr double kRadiusKm = 6360.0;
constexpr double kSunRadius = 0.00465;  // rad, the default sun's angular radius (about 0.27 deg)
constexpr double kDeg = 3.14159265358979 / 180.0;

// The world direction at a local elevation and azimuth (clockwise from north) above `up`.
glm::dvec3 sunAt(glm::dvec3 up, double elevationDeg, double azimuthDeg) {
    const glm::dvec3 pole = std::abs(up.z) > 0.99 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
    const glm::dvec3 east = glm::normalize(glm::cross(pole, up));
    const glm::dvec3 north = glm::cross(up, east);
    const double e = elevationDeg * kDeg, a = azimuthDeg * kDeg;
    return std::cos(e) * (std::cos(a) * north + std::sin(a) * east) + std::sin(e) * up;
}

// A continents map with the same value everywhere (no gradient): with mountainOctaves 0 the
// ground is a sphere (e = 1: at TERRAIN_LOWLAND_SHARE x maxHeight).
noise::CubeMap uniformContinents(float value) {
    noise::CubeMap map;
    map.size = 4;
    map.texels.assign(6 * 4 * 4, glm::vec4(value, 0.0f, 0.0f, 0.0f));
    return map;
}

// The default Earth's height field (continents from the cache, as the session's).
const terrain::HeightField& earthField() {
    static terrain::HeightField field = [] {
        terrain::HeightField f;
        f.update(TerrainParams{});
        return f;
    }();
    return field;
}

// The smallest clearance angle (rad: height of the ray above the terrain over the distance)
// along the ray from the ground under `up` towards `sun`, from the first sample distance
// of the shader's march to its longest, by a fine march: every 20 m, or 0.2 % of the
// distance where that is longer, all octaves; positions in double. No bias: rounding shows.
// With `startM`, from that height above sea level where the ground is lower (the sea's surface).
double referenceClearance(const terrain::HeightField& field, glm::dvec3 up, glm::dvec3 sun, double startM = -1e9) {
    const terrain::TerrainShadowConstants c = terrain::terrainShadowConstants();
    const double ground = std::max(double(field.height(glm::vec3(up))), startM);
    const double startKm = kRadiusKm + ground / 1000.0;
    double clearance = 1.0;
    for (double t = c.firstKm; t <= c.maxKm; t += std::max(0.02, 0.002 * t)) {
        const glm::dvec3 p = up * startKm + sun * t;
        const double r = glm::length(p);
        const double rayM = (r - kRadiusKm) * 1000.0;
        if (rayM > field.shape().maxHeight) break;
        const double terrainM = field.height(glm::vec3(p / r));
        clearance = std::min(clearance, (rayM - terrainM) / 1000.0 / t);
    }
    return clearance;
}

float twinVisibility(const terrain::HeightField& field, glm::dvec3 up, glm::dvec3 sun, float footprintKm = 0.0f) {
    return terrain::terrainSunVisibility(glm::vec3(up * kRadiusKm), glm::vec3(sun), float(kRadiusKm), float(kSunRadius),
                                         footprintKm, field.shape(), field.continents());
}

// Lit (1), shadowed (0) or too near the shadow's edge to say (-1) by the reference march:
// within the sun's radius plus `marginRad` of the horizon line it says nothing.
int referenceClass(double clearance, double marginRad) {
    if (clearance > kSunRadius + marginRad) return 1;
    if (clearance < -kSunRadius - marginRad) return 0;
    return -1;
}

}  // namespace

TEST(TerrainShadow, DiscShareIsTheCircularSegment) {
    const float a = float(kSunRadius);
    EXPECT_NEAR(terrain::terrainShadowDiscShare(0.0f, a), 0.5f, 1e-6f);
    EXPECT_EQ(terrain::terrainShadowDiscShare(a, a), 1.0f);
    EXPECT_EQ(terrain::terrainShadowDiscShare(2.0f * a, a), 1.0f);
    EXPECT_NEAR(terrain::terrainShadowDiscShare(-a, a), 0.0f, 1e-6f);
    EXPECT_NEAR(terrain::terrainShadowDiscShare(-2.0f * a, a), 0.0f, 1e-6f);
    // Half the radius above the line: the segment below it is (2 pi / 3 - sqrt(3) / 2) / (2 pi) = 19.55 %.
    EXPECT_NEAR(terrain::terrainShadowDiscShare(0.5f * a, a), 1.0f - 0.19550f, 1e-4f);
    float last = 0.0f;
    for (int i = -20; i <= 20; ++i) {
        const float x = 0.05f * float(i) * a;
        const float share = terrain::terrainShadowDiscShare(x, a);
        EXPECT_GE(share, last);
        EXPECT_NEAR(share + terrain::terrainShadowDiscShare(-x, a), 1.0f, 1e-5f);
        last = share;
    }
}

TEST(TerrainShadow, FlatGroundIsLitAboveTheHorizonAndDarkBelow) {
    // A sphere 800 m above sea level (uniform continents, no mountains) under a field whose
    // bound is 8000 m, so the march runs: at every azimuth the sun is wholly visible a
    // degree or more above the horizon, hidden a degree below, and at the horizon the
    // disc's share above it (the march's 1 m bias lifts the line by under 0.2 radii).
    TerrainParams params;
    params.noise_octaves = 0;
    const terrain::TerrainShape shape = terrain::makeTerrainShape(params);
    const noise::CubeMap flat = uniformContinents(1.0f);
    for (glm::dvec3 up : {glm::dvec3(0, 0, 1), glm::normalize(glm::dvec3(1, -2, 0.5)), glm::dvec3(-1, 0, 0)}) {
        for (double azimuth = 0.0; azimuth < 360.0; azimuth += 45.0) {
            auto visibility = [&](double elevationDeg) {
                return terrain::terrainSunVisibility(glm::vec3(up * kRadiusKm), glm::vec3(sunAt(up, elevationDeg, azimuth)),
                                                     float(kRadiusKm), float(kSunRadius), 0.0f, shape, flat);
            };
            for (double e : {1.0, 5.0, 30.0, 89.0}) EXPECT_EQ(visibility(e), 1.0f) << e << " deg, azimuth " << azimuth;
            for (double e : {-1.0, -5.0}) EXPECT_EQ(visibility(e), 0.0f) << e << " deg, azimuth " << azimuth;
            for (double x = -1.5; x <= 1.5; x += 0.25) {
                const double e = x * kSunRadius / kDeg;
                EXPECT_NEAR(visibility(e), terrain::terrainShadowDiscShare(float(x * kSunRadius), float(kSunRadius)), 0.12)
                    << x << " sun radii, azimuth " << azimuth;
            }
        }
    }
}

TEST(TerrainShadow, TwinAgreesWithAFineMarchInTheMountains) {
    // 400 random points of the ground around the 'mountains' view (41 N, 105.5-105 W: a
    // range with 5 km summits), the sun 5 deg up at a random azimuth: lit or shadowed as the
    // reference march says (unless the horizon line is within the sun's radius of its centre:
    // then either), and the twin's visibility on the same side of 1/2. Measured: 368 of 384
    // agree (95.8 %); every disagreement is a ridge the 26 samples stepped over (the twin
    // lit, the reference shadowed; 98 % at 40 samples). Both kinds must be there.
    const terrain::HeightField& field = earthField();
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> lat(40.8, 41.2), lon(-105.5, -105.0), az(0.0, 360.0);
    int agree = 0, disagree = 0, litCount = 0, shadowCount = 0;
    for (int i = 0; i < 400; ++i) {
        const glm::dvec3 up = directionFromLatLon(lat(rng), lon(rng));
        if (field.height(glm::vec3(up)) < 0.0f) continue;
        const glm::dvec3 sun = sunAt(up, 5.0, az(rng));
        const int reference = referenceClass(referenceClearance(field, up, sun), 0.0);
        if (reference < 0) continue;
        const int twin = twinVisibility(field, up, sun) >= 0.5f ? 1 : 0;
        (twin == reference ? agree : disagree) += 1;
        (reference == 1 ? litCount : shadowCount) += 1;
    }
    std::printf("reference lit %d, shadowed %d; the twin agrees at %d, disagrees at %d\n", litCount, shadowCount, agree,
                disagree);
    EXPECT_GE(litCount, 40);
    EXPECT_GE(shadowCount, 40);
    EXPECT_GE(agree, 0.93 * (agree + disagree));
}

TEST(TerrainShadow, TheOctavesBoundIsTheHeightOrAboveItUnderTheCeiling) {
    // terrainShadowHeightBelow over 3000 random points around the 'mountains' view and on the
    // plains east of it, ceilings from 500 m under the ground to 8 km above sea level, 1 to all
    // octaves: with every octave it is the field's height (terrainHeight); with the bound, where
    // it did not stop early the very same value, and where it did, at least the height (else a
    // march would see the terrain lower than it is) and no more than the ceiling (else the stop
    // came too early to prove anything: a metre's rounding allowed). Measured: 2187 of 3000
    // bounded (73 %). Able to fail: a bound that took the remaining octaves' most as half
    // (their mean) instead of TERRAIN_SHADOW_OCTAVE_MAX lies below the height at many points (1884
    // of 3000), and the march then clears ridges it should not (310 of 1500 in the next test).
    const terrain::HeightField& field = earthField();
    const terrain::TerrainShape& shape = field.shape();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> lat(38.0, 42.0), lon(-106.0, -98.0), unit(0.0, 1.0);
    std::uniform_int_distribution<int> octaves(1, shape.mountainOctaves);
    int bounded = 0, tried = 0;
    for (int i = 0; i < 3000; ++i) {
        const glm::vec3 up(directionFromLatLon(lat(rng), lon(rng)));
        const float groundM = field.height(up);
        const float ceilingM = float(groundM - 500.0 + unit(rng) * (shape.maxHeight + 500.0 - groundM));
        const int count = octaves(rng);
        if (count == shape.mountainOctaves) {
            EXPECT_EQ(terrain::terrainShadowHeightBelow(up, shape, field.continents(), count, ceilingM, false), groundM);
        }
        const float exact = terrain::terrainShadowHeightBelow(up, shape, field.continents(), count, ceilingM, false);
        const float bound = terrain::terrainShadowHeightBelow(up, shape, field.continents(), count, ceilingM, true);
        ++tried;
        if (bound == exact) continue;
        ++bounded;
        EXPECT_GT(bound, exact) << "at point " << i;
        EXPECT_LE(bound, ceilingM + 1.0f) << "at point " << i;
    }
    std::printf("%d of %d heights bounded under their ceiling\n", bounded, tried);
    EXPECT_GE(bounded, tried / 4);
}

TEST(TerrainShadow, TheOctavesBoundLeavesTheClearanceAsMarched) {
    // The march with the octaves' bounds against the same march with every octave, from 1500
    // random points around the 'mountains' view and on the plains east of it, the sun 1-60 deg up
    // at a random azimuth: where the clearance is below the sun's radius plus the exact margin
    // (what the visibility and the shadow samples read), the very same clearance; above it, both
    // above it; and so the visibility the same to the bit everywhere. Both kinds must be there.
    const terrain::HeightField& field = earthField();
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> lat(38.0, 42.0), lon(-106.0, -98.0), az(0.0, 360.0), elevation(1.0, 60.0);
    const float exactBelow = float(kSunRadius) + terrain::terrainShadowExactMargin();
    int exact = 0, beyond = 0;
    for (int i = 0; i < 1500; ++i) {
        const glm::dvec3 up = directionFromLatLon(lat(rng), lon(rng));
        const glm::dvec3 sun = sunAt(up, elevation(rng), az(rng));
        auto clearance = [&](bool boundOctaves) {
            return terrain::terrainShadowClearanceMarch(glm::vec3(up * kRadiusKm), -1e9f, glm::vec3(sun),
                                                        float(kRadiusKm), float(kSunRadius), 0.0f, field.shape(),
                                                        field.continents(), exactBelow, boundOctaves);
        };
        const float every = clearance(false), boundedMarch = clearance(true);
        if (every < exactBelow) {
            ++exact;
            EXPECT_EQ(boundedMarch, every) << "at point " << i;
        } else {
            ++beyond;
            EXPECT_GE(boundedMarch, exactBelow) << "at point " << i;
        }
        EXPECT_EQ(terrain::terrainShadowDiscShare(boundedMarch, float(kSunRadius)),
                  terrain::terrainShadowDiscShare(every, float(kSunRadius)))
            << "at point " << i;
    }
    std::printf("clearance below the exact margin at %d points, beyond it at %d\n", exact, beyond);
    EXPECT_GE(exact, 50);
    EXPECT_GE(beyond, 50);
}

TEST(TerrainShadow, BeyondTheLongestShadowNothingIsMarched) {
    // A pixel whose footprint is longer than any shadow the terrain can throw at this sun
    // (the relief above the point over sin(elevation)) is lit without a march; the same point
    // at a fine footprint is shadowed from some azimuth at a low sun.
    const terrain::HeightField& field = earthField();
    const glm::dvec3 up = directionFromLatLon(41.0, -105.3);
    const double reliefKm = (field.shape().maxHeight - field.height(glm::vec3(up))) / 1000.0;
    const glm::dvec3 sun = sunAt(up, 30.0, 200.0);
    EXPECT_EQ(twinVisibility(field, up, sun, float(reliefKm / 0.5 * 1.01)), 1.0f);
    int shadowed = 0;
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 10.0)
        if (twinVisibility(field, up, sunAt(up, 3.0, azimuth)) < 0.5f) ++shadowed;
    EXPECT_GT(shadowed, 0) << "a valley point under a 3 deg sun is shadowed from some azimuth";
}

namespace {

// The ocean pass skips the terrain's march where terrainShadowMayReachSea says nothing can
// shadow the sea: where, by the map's slope bound, the sun's ray stands above all that the land
// near it may rise to (terrainHeightBound) as far as the march reaches. On 3000 random points of
// the sea (continent value -0.2 to 0) under a sun 2-90 deg up: along the ray of every skipped
// point, sampled every 200 m to where it clears the highest terrain (at most the march's 100 km),
// the ray stands above the height field and the reference march from sea level finds it lit;
// and it skips most of the points (measured 2084 of 3000; 531 when the reach was the highest
// mountain's and any land within it marched; the open sea away from coasts, which this sample
// leaves out, is skipped wherever the sun is not low). Able to fail: many of the points marched
// have land within reach (a bound with too short a reach or too small a slope would skip some
// of those).
TEST(TerrainShadow, TheOpenSeaIsSkippedOnlyWhereNothingCanShadowIt) {
    const terrain::HeightField& field = earthField();
    const noise::CubeMap& map = field.continents();
    const float lipschitz = float(ocean::continentLipschitz(map));
    const float slack = float(ocean::continentSampleSlackRad(map));
    const terrain::TerrainShadowConstants c = terrain::terrainShadowConstants();
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), share(0.0, 1.0);
    int sea = 0, skipped = 0, skippedBelowTerrain = 0, skippedButShadowed = 0, marchedWithLand = 0;
    while (sea < 3000) {
        const glm::dvec3 up = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        if (const float e = terrain::continentValue(glm::vec3(up), map); e >= 0.0f || e < -0.2f) continue;
        ++sea;
        const glm::dvec3 sun = sunAt(up, 2.0 + 88.0 * share(rng), 360.0 * share(rng));
        const bool march = terrain::terrainShadowMayReachSea(glm::vec3(up), glm::vec3(sun), 0.0f, float(kRadiusKm),
                                                             lipschitz, slack, field.shape(), map);
        bool land = false;   // a continent value >= 0 under the ray within the march's reach
        bool below = false;  // the ray below the height field there
        for (double t = 0.0; t <= c.maxKm; t += 0.2) {
            const glm::dvec3 p = up * kRadiusKm + sun * t;
            const double rayM = (glm::length(p) - kRadiusKm) * 1000.0;
            if (rayM > field.shape().maxHeight) break;
            const glm::vec3 d(glm::normalize(p));
            land = land || terrain::continentValue(d, map) >= 0.0f;
            below = below || (t > 0.0 && rayM < terrain::terrainHeight(d, field.shape(), map));
        }
        if (march) {
            marchedWithLand += land;
            continue;
        }
        ++skipped;
        skippedBelowTerrain += below;
        skippedButShadowed += referenceClearance(field, up, sun, 0.0) < -1e-6;
    }
    std::printf("slope bound %.1f per radian; %d sea points: %d skipped (%d with the ray below the ground, %d shadowed); "
                "%d of those marched have land within reach\n",
                lipschitz, sea, skipped, skippedBelowTerrain, skippedButShadowed, marchedWithLand);
    EXPECT_EQ(skippedBelowTerrain, 0);
    EXPECT_EQ(skippedButShadowed, 0);
    EXPECT_GT(skipped, sea / 2);
    EXPECT_GT(marchedWithLand, 30);
}

constexpr glm::ivec2 kSize{160, 90};
constexpr double kSunElevationDeg = 5.0;
// The view's own azimuth (assets/views/mountains.toml: 220, afternoon light from the
// south-west), chosen before looking at the result; see the test for the other azimuths.
constexpr double kSunAzimuthDeg = 220.0;
// The sea's test: the sun in the north-west, where both lit and shadowed water are in view.
// Measured (every second pixel of 160x90; sea pixels the reference march classes, lit /
// shadowed, agreement): 100 deg 0 / 2023 (94 %), 120: 1764 / 107 (97.9 %), 140: 1880 / 44
// (98.8 %), 180: 2056 / 14, 220: 76 / 1808 (96.7 %), 260: 29 / 1899 (95.3 %), 300: 222 /
// 1131 (96.8 %), 320: 955 / 46 (99.8 %), 340: 1957 / 71 (99.8 %).
constexpr double kLakeSunAzimuthDeg = 300.0;

class TerrainShadowRender : public test::GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    }
    // The 'mountains' view, clouds off (their shadows would mix in), the sun as given.
    Session mountains(double elevationDeg, double azimuthDeg, bool shadows) {
        Session s = loadSession(test::repoPaths(), "earth", "mountains");
        View v = s.view;
        v.sun_elevation_deg = elevationDeg;
        v.sun_azimuth_deg = azimuthDeg;
        applyView(v, s);
        s.scene.clouds.enabled = false;
        s.scene.terrain.shadows = shadows;
        return s;
    }
    std::unique_ptr<Renderer> renderer;
};

// The world direction of the ray through the centre of pixel (x, imageRow) of a kSize frame
// (image rows from the top).
glm::dvec3 pixelRay(const Camera& camera, int x, int imageRow) { return test::pixelRay(camera, kSize, x, imageRow); }

// The render tests' tally: the GPU's class (1 lit, 0 shadowed) against the reference's at each
// judged pixel; `check` asks for both kinds (10 each) and agreement at `share` of them.
struct Tally {
    int agree = 0, disagree = 0, lit = 0, shadowed = 0;
    void add(int gpu, int reference) {
        (gpu == reference ? agree : disagree) += 1;
        (reference == 1 ? lit : shadowed) += 1;
    }
    void check(const char* what, double share) const {
        std::printf("%s: %d judged, reference lit %d, shadowed %d; the GPU agrees at %d, disagrees at %d\n", what,
                    agree + disagree, lit, shadowed, agree, disagree);
        EXPECT_GE(lit, 10);
        EXPECT_GE(shadowed, 10);
        EXPECT_GE(agree, share * (agree + disagree));
    }
};

// One pixel's surface point and what the two renders made of it.
struct SurfaceSample {
    glm::dvec3 point;   // km from the planet centre
    glm::dvec3 normal;  // the G-buffer's
    double withShadows, without;  // luminance of the surface radiance
};

double luminanceOf(const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

// Every `stride`-th pixel's surface point (distance > 0) with the surface radiance of the
// frame with terrain shadows and without.
std::vector<SurfaceSample> surfaceSamples(Renderer& renderer, const Session& lit, const Session& shadowed, int stride) {
    renderer.render(lit.scene, lit.camera, kSize);
    const ImageRGBAF without = readTextureRGBAF(renderer.targets().surfaceRadiance(), kSize.x, kSize.y);
    renderer.render(shadowed.scene, shadowed.camera, kSize);
    const ImageRGBAF with = readTextureRGBAF(renderer.targets().surfaceRadiance(), kSize.x, kSize.y);
    const ImageRGBAF distance = readTextureRGBAF(renderer.targets().surfaceDistance(), kSize.x, kSize.y);
    const ImageRGBAF normal = readTextureRGBAF(renderer.targets().gbuffer().normal, kSize.x, kSize.y);
    const Camera& camera = shadowed.camera;
    std::vector<SurfaceSample> samples;
    for (int imageRow = stride / 2; imageRow < kSize.y; imageRow += stride) {
        for (int x = stride / 2; x < kSize.x; x += stride) {
            const double d = test::pixelAt(distance, x, imageRow)[0];
            if (!(d > 0.0)) continue;
            const glm::dvec3 dir = pixelRay(camera, x, imageRow);
            const float* n = test::pixelAt(normal, x, imageRow);
            samples.push_back({(camera.position + dir * d) / 1000.0, glm::normalize(glm::dvec3(n[0], n[1], n[2])),
                               luminanceOf(test::pixelAt(with, x, imageRow)),
                               luminanceOf(test::pixelAt(without, x, imageRow))});
        }
    }
    return samples;
}

}  // namespace

// Measured (160x90, every third pixel, about 3 s): at the view's azimuth 220 deg, 182
// pixels judged, reference lit 75, shadowed 107, the GPU agrees at 180 (98.9 %) at 3bf31c3
// (209: 75 and 134, 207 agree, with terrain edits then under way in the tree). A sweep of
// the azimuth in 15 deg steps agrees at 96-100 % wherever both kinds are sampled (180: 153
// of 158, 270: 177 of 191), but at 90 deg (the sun behind the range, seen from the valley
// it shadows) only 19 of 40: the main 5.1 km summit 20 km east is narrower than the
// march's 35 % gap there (samples at 16 and 22 km) and is stepped over, the limitation
// terrain_shadow.glsl states; its twin does the same (TwinAgreesWithAFineMarchInTheMountains).
// Able to fail: with the march returning 1 (no shadows) 75 of 182 agree (41 %); marching
// away from the sun instead of towards it, 74 of 182.
TEST_F(TerrainShadowRender, MountainShadowsAtALowSunMatchACpuMarch) {
    // The 'mountains' view with the sun 5 deg up in the south-west: rendered with and without
    // terrain shadows; a pixel is in the GPU's shadow where the shadows took more than a
    // quarter of its light. The reference march (no bias, all octaves, fine steps) at each
    // sampled land pixel's point, facing the sun (n.l > 0.3, where the sun is most of the
    // light), says lit or shadowed unless the horizon line is within the sun's radius plus
    // 0.01 rad (a penumbra, or the float heights' rounding: both marches may say either).
    // At least 90 % must agree, and both kinds must be among them so that the test can fail.
    const Session lit = mountains(kSunElevationDeg, kSunAzimuthDeg, false);
    const Session shadowed = mountains(kSunElevationDeg, kSunAzimuthDeg, true);
    const glm::dvec3 sun = shadowed.scene.sunDirection();
    Tally tally;
    for (const SurfaceSample& s : surfaceSamples(*renderer, lit, shadowed, 3)) {
        if (glm::dot(s.normal, sun) < 0.3 || s.without <= 0.0) continue;
        const glm::dvec3 up = glm::normalize(s.point);
        if (shadowed.ground.height(glm::vec3(up)) < 0.0f) continue;  // the sea floor
        const int reference = referenceClass(referenceClearance(shadowed.ground, up, sun), 0.01);
        if (reference < 0) continue;
        tally.add(s.withShadows > 0.75 * s.without ? 1 : 0, reference);
    }
    tally.check("land pixels", 0.9);
}

namespace {

// The sea in the mountains' shadow: the 'mountains' view's high valley flooded to 2600 m
// (a lake reaching 6.5 km east, the range rising 2.5 km above it beyond the far shore: the
// scene of tests/test_ocean_reflections.cpp), flat water, no clouds, the camera 400 m above
// the lake looking east, the sun 5 deg up behind the range.
constexpr double kLakeLevelM = 2600.0;

Session lakeAtALowSun(double sunAzimuthDeg) {
    Session s = loadSession(test::repoPaths(), "earth", "mountains");
    s.scene.clouds.enabled = false;
    s.scene.terrain.shadows = true;
    s.scene.ocean.sea_level_m = kLakeLevelM;
    s.scene.waves.clear();
    View v = s.view;
    v.latitude_deg = 41.0;
    v.longitude_deg = -105.452;
    v.heading_deg = 90.0;
    v.pitch_deg = -8.0;
    v.fov_deg = 50.0;
    v.sun_elevation_deg = kSunElevationDeg;
    v.sun_azimuth_deg = sunAzimuthDeg;
    applyView(v, s);
    const glm::dvec3 up = glm::normalize(s.camera.position);
    s.camera.position = up * (s.scene.planetRadiusM() + kLakeLevelM + 400.0);
    return s;
}

// The shader tree with the sea's terrain shadows compiled out (ocean/sea_light.frag's
// SUN_VISIBILITY_TERRAIN 0; the sea floor under it keeps its own), in a temporary folder.
std::filesystem::path shadersWithoutSeaShadows() {
    return test::shadersWith("planet_test_sea_shadows_off", "ocean/sea_light.frag", "#define SUN_VISIBILITY_TERRAIN 1",
                             "#define SUN_VISIBILITY_TERRAIN 0");
}

}  // namespace

// The sea's own light (the sun into the water and its glitter) in the terrain's shadow, against
// the reference march from the water's surface: rendered with the sea's shadows and with them
// compiled out (the sea floor below shadowed alike in both), a sea pixel over at least 5 m of
// water is in the GPU's shadow where its surface radiance dropped by more than 0.2 % (a lit one
// is the same to the bit: the march returns exactly 1). At least 90 % must agree, with both kinds
// among them. Able to fail: before the sea had terrain shadows no pixel dropped.
TEST_F(TerrainShadowRender, TheSeaInAMountainsShadowMatchesACpuMarch) {
    const Session s = lakeAtALowSun(kLakeSunAzimuthDeg);
    const glm::dvec3 sun = s.scene.sunDirection();
    renderer->render(s.scene, s.camera, kSize);
    const ImageRGBAF with = readTextureRGBAF(renderer->targets().surfaceRadiance(), kSize.x, kSize.y);
    const ImageRGBAF distance = readTextureRGBAF(renderer->targets().surfaceDistance(), kSize.x, kSize.y);
    ImageRGBAF without;
    {
        Renderer off(shadersWithoutSeaShadows(), atmosphere::TableSizes::reduced(), s.continents);
        off.render(s.scene, s.camera, kSize);
        without = readTextureRGBAF(off.targets().surfaceRadiance(), kSize.x, kSize.y);
    }
    Tally tally;
    for (int imageRow = 1; imageRow < kSize.y; imageRow += 2) {
        for (int x = 1; x < kSize.x; x += 2) {
            const double d = test::pixelAt(distance, x, imageRow)[0];
            if (!(d > 0.0)) continue;
            const glm::dvec3 dir = pixelRay(s.camera, x, imageRow);
            const glm::dvec3 up = glm::normalize(s.camera.position + dir * d);
            if (s.ground.height(glm::vec3(up)) > kLakeLevelM - 5.0) continue;  // land, or the shore's blend
            const int reference = referenceClass(referenceClearance(s.ground, up, sun, kLakeLevelM), 0.01);
            if (reference < 0) continue;
            const double a = luminanceOf(test::pixelAt(with, x, imageRow));
            const double b = luminanceOf(test::pixelAt(without, x, imageRow));
            if (!(b > 0.0)) continue;
            tally.add(a < 0.998 * b ? 0 : 1, reference);
        }
    }
    tally.check("sea pixels", 0.9);
}

// Light shafts (terrain.light_shafts): the 'mountains' view with the sun 7 deg up in the east,
// behind the range, clouds off, every pixel marched, rendered with the light shafts off and on.
// (Measured, judged pixels lit / shadowed air, agreement: sun 7 deg at 90: 435 / 173, 100 %;
// 5 deg at 90: 4 / 688; 10 deg at 90: 581 / 6; 5-15 deg at 220 and 10 at 270: all shadowed,
// 10 at 180: all lit; every one 100 %.) For every third pixel with a surface, a fine CPU estimate of the share of
// its view segment (the first 60 km below the highest terrain) in the terrain's shadow: 64
// points, each the twin of the GPU's march from that point's height. Where it is 0 the air
// must be unchanged (the GPU's 8 samples found no shadow either: the same pixel to the bit);
// where it is over 30 % the air must be darker (the in-scattering of the shadowed length taken
// off). At least 85 % of the judged pixels must agree, with both kinds among them. Able to
// fail: without the shafts nothing changes (every shadowed pixel disagrees); shafts taken from
// the wrong side (marching away from the sun) darken the lit air instead.
TEST_F(TerrainShadowRender, LightShaftsDarkenTheAirWhereACpuMarchFindsItShadowed) {
    Session off = mountains(7.0, 90.0, true);
    off.scene.render.temporal = false;
    Session on = off;
    on.scene.terrain.light_shafts = true;
    renderer->render(off.scene, off.camera, kSize);
    const ImageRGBAF without = readTextureRGBAF(renderer->targets().hdr(), kSize.x, kSize.y);
    renderer->render(on.scene, on.camera, kSize);
    const ImageRGBAF with = readTextureRGBAF(renderer->targets().hdr(), kSize.x, kSize.y);
    const ImageRGBAF distance = readTextureRGBAF(renderer->targets().surfaceDistance(), kSize.x, kSize.y);
    const glm::dvec3 sun = on.scene.sunDirection();
    const double reachKm = kRadiusKm + on.ground.shape().maxHeight / 1000.0;
    Tally tally;
    for (int imageRow = 1; imageRow < kSize.y; imageRow += 3) {
        for (int x = 1; x < kSize.x; x += 3) {
            const double d = test::pixelAt(distance, x, imageRow)[0] / 1000.0;  // km
            if (!(d > 0.0)) continue;
            const glm::dvec3 dir = pixelRay(on.camera, x, imageRow);
            const glm::dvec3 camera = on.camera.position / 1000.0;
            // The segment below the highest terrain, as the shader takes it (the camera is inside).
            const double rmu = glm::dot(camera, dir), r = glm::length(camera);
            const double leave = std::min({-rmu + std::sqrt(rmu * rmu - (r - reachKm) * (r + reachKm)), d, 60.0});
            double shadowed = 0.0;
            for (int i = 0; i < 64; ++i) {
                const glm::dvec3 p = camera + dir * (leave * (i + 0.5) / 64.0);
                const double heightM = (glm::length(p) - kRadiusKm) * 1000.0;
                shadowed += 1.0 - terrain::terrainSunVisibilityAbove(glm::vec3(p), float(heightM), glm::vec3(sun),
                                                                     float(kRadiusKm), float(kSunRadius),
                                                                     float(leave / 8.0), on.ground.shape(),
                                                                     on.ground.continents());
            }
            const double share = shadowed / 64.0;
            const int reference = share <= 0.0 ? 1 : share > 0.3 ? 0 : -1;
            if (reference < 0) continue;
            const double a = luminanceOf(test::pixelAt(with, x, imageRow));
            const double b = luminanceOf(test::pixelAt(without, x, imageRow));
            tally.add(a < b * (1.0 - 1e-4) ? 0 : 1, reference);
        }
    }
    tally.check("pixels' air (shadowed: over 30 %)", 0.85);
}

namespace {

// How a frame's surface radiance with the terrain's shadow from the sparse samples differs from
// one marched at every pixel: the share of surface pixels whose luminance differs by more than
// 0.1 %, and the mean absolute difference of luminance over the surface pixels relative to
// their mean luminance.
struct SampledAgainstMarched {
    double differing = 0.0, meanRelative = 0.0;
};

SampledAgainstMarched compareSurfaceRadiance(const ImageRGBAF& sampled, const ImageRGBAF& marched, glm::ivec2 size) {
    int surface = 0, differing = 0;
    double sum = 0.0, total = 0.0;
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            const double b = luminanceOf(test::pixelAt(marched, x, y));
            if (!(b > 0.0)) continue;
            const double difference = std::abs(luminanceOf(test::pixelAt(sampled, x, y)) - b);
            ++surface;
            differing += difference > 1.0e-3 * b ? 1 : 0;
            sum += difference;
            total += b;
        }
    }
    return {surface ? double(differing) / surface : 1.0, total > 0.0 ? sum / total : 1.0};
}

ImageRGBAF surfaceRadianceWith(const std::filesystem::path& shaders, const Session& s, glm::ivec2 size) {
    Renderer r(shaders, atmosphere::TableSizes::reduced(), s.continents);
    r.render(s.scene, s.camera, size);
    return readTextureRGBAF(r.targets().surfaceRadiance(), size.x, size.y);
}

}  // namespace

// The surface light takes the terrain's shadow from the samples (one pixel of each block,
// render/terrain_shadow.frag) where those around a pixel agree on fully lit or fully
// shadowed, and marches elsewhere: after the surface light, at the pixels it listed (render/
// terrain_shadow_list.glsl; on a dry planet the list is the surface light's alone at the frame's
// end, and holds the shadows' edges). Against the march at every pixel (the surface light built
// with TERRAIN_SHADOW_FROM_SAMPLES 0), in the 'mountains' view at a 5 deg sun (long shadows,
// many edges) and in 'ground' (the meadow under a 40 deg sun): the two frames are the same
// but for shadows narrower than the samples' spacing that fall between them (a spacing of 4 pixels
// from 720 rows up: render/sample_spacing.glsl; mountains at 1280x720 measured 0.26 % of surface
// pixels differing, mean change 0.23 %). Measured
// (320x180, spacing 2): mountains 0.68 % of surface pixels differ, mean change 0.64 % of the
// mean luminance (margin 0.01 rad: 0.72 / 0.74 %; 0.1: 0.33 / 0.43 % at half again the cost);
// ground 0 and 0 (no terrain shadow in view). Able to fail: samples that all say "lit" (the
// marches after the sampling pass writing 1) leave the shadowed valleys lit (71 %, 110 %); a pixel taking its
// nearest sample alone, not the corners around it, 4.9 % and 5.5 %.
TEST_F(TerrainShadowRender, TheSampledShadowIsTheMarchedOneButForSlivers) {
    const std::filesystem::path marched = test::shadersWith(
        "planet_test_shadow_marched", "render/surface_light.frag", "#define TERRAIN_SHADOW_FROM_SAMPLES 1",
        "#define TERRAIN_SHADOW_FROM_SAMPLES 0");
    const std::filesystem::path allLit = test::shadersWith(
        "planet_test_shadow_samples_lit", "render/terrain_shadow_sample_marches.comp",
        "if (onGround) clearance.r = c;", "if (onGround) clearance.r = 1.0;");
    Session ground = loadSession(test::repoPaths(), "earth", "ground");
    ground.scene.clouds.enabled = false;
    const Session mountainsAtALowSun = mountains(kSunElevationDeg, kSunAzimuthDeg, true);
    struct Case {
        const Session* session;
        glm::ivec2 size;
    };
    for (const Case& c : {Case{&mountainsAtALowSun, {320, 180}}, Case{&ground, {320, 180}},
                          Case{&mountainsAtALowSun, {1280, 720}}}) {
        const Session* s = c.session;
        const glm::ivec2 size = c.size;
        const ImageRGBAF reference = surfaceRadianceWith(marched, *s, size);
        const SampledAgainstMarched sampled =
            compareSurfaceRadiance(surfaceRadianceWith(test::repoPaths().shaders(), *s, size), reference, size);
        const SampledAgainstMarched lit =
            compareSurfaceRadiance(surfaceRadianceWith(allLit, *s, size), reference, size);
        std::printf("%s %dx%d (spacing %d): sampled: %.3f %% of surface pixels differ, mean %.4f %%; samples all "
                    "lit: %.3f %%, %.4f %%\n",
                    s == &ground ? "ground" : "mountains at 5 deg", size.x, size.y, terrainShadowSampleSpacing(size.y),
                    100.0 * sampled.differing,
                    100.0 * sampled.meanRelative, 100.0 * lit.differing, 100.0 * lit.meanRelative);
        EXPECT_LT(sampled.differing, 0.01);
        EXPECT_LT(sampled.meanRelative, 0.01);
        if (s == &mountainsAtALowSun) {
            EXPECT_GT(lit.meanRelative, 0.05);
        }
    }
    Session dry = mountainsAtALowSun;
    dry.scene.terrain.ocean = false;
    Renderer r(test::repoPaths().shaders(), atmosphere::TableSizes::reduced(), dry.continents);
    r.render(dry.scene, dry.camera, {320, 180});
    const glm::uvec2 listed = r.targets().terrainShadowListCount();
    std::printf("mountains at 5 deg, dry: %u pixels marched after the surface light (capacity %u)\n", listed.x,
                listed.y);
    EXPECT_GT(listed.x, 200u) << "the shadows' edges";
    EXPECT_LT(listed.x, 320u * 180u / 4u) << "only where the samples disagree";
}

// The sea's surface takes the terrain's shadow from the samples' g channel (the march from sea
// level where each sample's ray meets the sea, render/terrain_shadow.frag) where those around a
// pixel agree, and marches elsewhere (ocean/sea_light.frag's OCEAN_TERRAIN_SHADOW_FROM_SAMPLES). Against
// the march at every pixel that land may shadow (built with it 0), on the flooded valley at a
// 5 deg sun with the range's shadow across the water (lakeAtALowSun, 320x180), and in `beach`
// and `sunset` (the shore beside the camera: every sea pixel within land's reach, where the march
// cost the ocean pass a quarter of its time): the same frames but for shadows narrower than the
// samples' spacing. The samples hold both lit and shadowed water on the lake (2366 / 3825).
// Measured: lake 0.007 % of surface pixels differ, mean under 0.0001 %; beach and sunset 0
// and 0 (lit water only). Since the march runs after the ocean pass at the listed pixels
// (render/terrain_shadow_list.glsl), on the radiance the ocean kept as half floats, a marched pixel
// is rounded twice: lake 0.19 % differ (by over 1e-3), mean 0.008 %; beach and sunset 0 and 0.
// Able to fail: samples of the sea that all say "lit" leave the
// range's shadow on the lake lit (55 % of pixels differ, mean 0.90 %: the sea's own light is
// a small part of its radiance beside the sky it reflects).
TEST_F(TerrainShadowRender, TheSeaTakesItsShadowFromTheSamplesButForSlivers) {
    const std::filesystem::path marched =
        test::shadersWith("planet_test_sea_shadow_marched", "ocean/sea_light.frag",
                          "#define OCEAN_TERRAIN_SHADOW_FROM_SAMPLES 1", "#define OCEAN_TERRAIN_SHADOW_FROM_SAMPLES 0");
    const std::filesystem::path allLit = test::shadersWith(
        "planet_test_sea_samples_lit", "render/terrain_shadow_sample_marches.comp",
        "else clearance.g = c;", "else clearance.g = 1.0;");
    const Session lake = lakeAtALowSun(kLakeSunAzimuthDeg);
    const Session beach = loadSession(test::repoPaths(), "earth", "beach");
    const Session sunset = loadSession(test::repoPaths(), "earth", "sunset");
    const glm::ivec2 size{320, 180};
    for (const Session* s : std::vector<const Session*>{&lake, &beach, &sunset}) {
        const char* name = s == &lake ? "lake" : s == &beach ? "beach" : "sunset";
        SCOPED_TRACE(name);
        const ImageRGBAF reference = surfaceRadianceWith(marched, *s, size);
        Renderer sampling(test::repoPaths().shaders(), atmosphere::TableSizes::reduced(), s->continents);
        sampling.render(s->scene, s->camera, size);
        const SampledAgainstMarched sampled = compareSurfaceRadiance(
            readTextureRGBAF(sampling.targets().surfaceRadiance(), size.x, size.y), reference, size);
        // The pixels whose march ran after the ocean pass (render/terrain_shadow_list.glsl), within the list.
        const glm::uvec2 listed = sampling.targets().terrainShadowListCount();
        std::printf("%s: sampled: %.3f %% of surface pixels differ, mean %.4f %%; %u pixels marched after the ocean "
                    "(capacity %u)\n",
                    name, 100.0 * sampled.differing, 100.0 * sampled.meanRelative, listed.x, listed.y);
        EXPECT_LE(listed.x, listed.y);
        if (s == &lake) {
            EXPECT_GT(listed.x, 1000u) << "the range's shadow's edges across the lake";
        }
        EXPECT_LT(sampled.differing, 0.01);
        EXPECT_LT(sampled.meanRelative, 0.005);
        if (s != &lake) continue;
        // The samples of the lake's surface: lit water and water in the range's shadow.
        const TerrainShadowSamples& samples = sampling.targets().terrainShadowSamples();
        const ImageRGBAF clearance = readTextureRGBAF(samples.visibility, samples.size.x, samples.size.y);
        const double radius = kSunRadius;
        int lit = 0, shadowed = 0;
        for (std::size_t i = 0; i < clearance.pixels.size(); i += 4) {
            lit += clearance.pixels[i + 1] >= radius;
            shadowed += clearance.pixels[i + 1] <= -radius && clearance.pixels[i + 1] > -1.0e29f;
        }
        // Marched after the sampling pass at the samples it listed (render/terrain_shadow_sample_marches.comp).
        const std::size_t marchedSamples = sampling.targets().readTerrainShadowSampleMarches().size();
        std::printf("lake: samples of the sea's surface lit %d, shadowed %d; %zu marched after the sampling pass\n", lit,
                    shadowed, marchedSamples);
        EXPECT_GT(lit, 100);
        EXPECT_GT(shadowed, 100);
        EXPECT_GE(marchedSamples, std::size_t(shadowed));
        const SampledAgainstMarched lit_ = compareSurfaceRadiance(surfaceRadianceWith(allLit, *s, size), reference, size);
        std::printf("lake: samples all lit: %.3f %% differ, mean %.4f %%\n", 100.0 * lit_.differing,
                    100.0 * lit_.meanRelative);
        EXPECT_GT(lit_.differing, 0.2);
        EXPECT_GT(lit_.meanRelative, 0.005);
    }
}
