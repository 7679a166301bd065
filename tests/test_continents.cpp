// The continents cube map (noise/continents.h) and `planet bake`: OpenGL's cube face
// convention, the sea fraction, determinism, the baked gradient against the elevation,
// seamless sampling at edges and corners, the EXR cache's round trip and its refusal of
// damaged or foreign entries, loadOrBakeContinents, and the command end to end.
// All CPU; sizes are small so the whole file runs in a few seconds.
#include <gtest/gtest.h>

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>

#include <glm/glm.hpp>

#include "noise/cloud_volume.h"
#include "noise/continents.h"
#include "noise/weather_map.h"
#include "process.h"
#include "test_util.h"
#include "util/file_util.h"

namespace fs = std::filesystem;
using namespace planet;
using namespace planet::noise;
using planet::test::contains;

namespace {

double angleBetween(glm::dvec3 a, glm::dvec3 b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// Bakes are cached per (seed, sea fraction, size) within the test run.
const CubeMap& baked(int seed, double seaFraction, int size) {
    static std::map<std::tuple<int, double, int>, CubeMap> maps;
    auto [it, inserted] = maps.try_emplace({seed, seaFraction, size});
    if (inserted) {
        ContinentParams p;
        p.seed = seed;
        p.seaFraction = seaFraction;
        it->second = bakeContinents(p, size);
    }
    return it->second;
}

}  // namespace

// ---------------------------------------------------------------- geometry

TEST(CubeMapGeometry, TexelDirectionsAreUnitAndFaceCentresAreGlAxes) {
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < 7; ++y)
            for (int x = 0; x < 7; ++x) EXPECT_NEAR(glm::length(cubeTexelDirection(face, x, y, 7)), 1.0, 1e-14);
    // GL_TEXTURE_CUBE_MAP_POSITIVE_X .. NEGATIVE_Z.
    const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int face = 0; face < 6; ++face) {
        const glm::dvec3 d = cubeTexelDirection(face, 2, 2, 5);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(d[c], axes[face][c], 1e-15) << "face " << face;
    }
    // GL's s/t orientation (Table 8.19) at texel (0, 0), i.e. s, t -> 0: sc = tc = -1 * |ma|.
    const double r = 1.0 / std::sqrt(3.0);
    const glm::dvec3 corner[6] = {{1, 1, 1}, {-1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {-1, 1, 1}, {1, 1, -1}};
    for (int face = 0; face < 6; ++face) {
        const glm::dvec3 d = cubeTexelDirection(face, 0, 0, 4096);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(d[c], corner[face][c] * r, 1e-3) << "face " << face;
    }
}

TEST(CubeMapGeometry, FaceSelectionInvertsTexelDirections) {
    const int n = 8;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                double s = 0.0, t = 0.0;
                ASSERT_EQ(cubeFaceOf(cubeTexelDirection(face, x, y, n), s, t), face);
                EXPECT_NEAR(s, (x + 0.5) / n, 1e-14);
                EXPECT_NEAR(t, (y + 0.5) / n, 1e-14);
            }
}

TEST(CubeMapGeometry, BorderTexelsHaveCloseNeighboursOnOtherFaces) {
    // Every texel on a face's border has a texel on another face within about one texel.
    const int n = 16;
    const double texelAngle = 2.0 / n;  // the widest texel, at a face centre, spans 2/n rad
    auto onBorder = [](int x, int y) { return x == 0 || y == 0 || x == n - 1 || y == n - 1; };
    double worst = 0.0;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                if (!onBorder(x, y)) continue;
                const glm::dvec3 d = cubeTexelDirection(face, x, y, n);
                double nearest = 10.0;
                for (int other = 0; other < 6; ++other)
                    if (other != face)
                        for (int v = 0; v < n; ++v)
                            for (int u = 0; u < n; ++u)
                                if (onBorder(u, v))
                                    nearest = std::min(nearest, angleBetween(d, cubeTexelDirection(other, u, v, n)));
                worst = std::max(worst, nearest);
            }
    std::printf("largest angle from a border texel to the nearest texel on another face: %.4f rad (texel %.4f)\n",
                worst, texelAngle);
    EXPECT_LT(worst, texelAngle);
}

TEST(CubeMapGeometry, TexelSolidAnglesCoverTheSphere) {
    for (int n : {1, 5, 32}) {
        double total = 0.0;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) total += 6.0 * cubeTexelSolidAngle(x, y, n);
        EXPECT_NEAR(total, 4.0 * M_PI, 1e-12) << n;
    }
    // Centre over corner texel: 3 sqrt(3) in the limit.
    EXPECT_NEAR(cubeTexelSolidAngle(50, 50, 101) / cubeTexelSolidAngle(0, 0, 101), 3.0 * std::sqrt(3.0), 0.2);
}

// ---------------------------------------------------------------- bake

TEST(Continents, AchievesTheRequestedSeaFraction) {
    for (double requested : {0.0, 0.3, 0.6, 0.9, 1.0}) {
        const CubeMap& map = baked(1, requested, 32);
        const double achieved = seaFractionOf(map);
        std::printf("sea fraction requested %.2f, achieved %.6f (size 32)\n", requested, achieved);
        EXPECT_NEAR(achieved, requested, 0.01);
        // At most one texel off: the centre texel holds 1 / (pi n^2) of the sphere.
        EXPECT_LE(std::abs(achieved - requested), 1.0 / (M_PI * 32 * 32) + 1e-12);
    }
}

TEST(Continents, ValuesSpanMinusOneToOne) {
    const CubeMap& map = baked(1, 0.6, 32);
    ASSERT_EQ(map.texels.size(), 6u * 32 * 32);
    const auto byElevation = [](const glm::vec4& a, const glm::vec4& b) { return a.x < b.x; };
    const auto [lo, hi] = std::minmax_element(map.texels.begin(), map.texels.end(), byElevation);
    EXPECT_EQ(lo->x, -1.0f);
    EXPECT_EQ(hi->x, 1.0f);
}

TEST(Continents, GradientMatchesDifferencesOfTheElevation) {
    // The baked gradient (the fBm's analytic gradient, scaled like the elevation) against
    // central differences of the baked elevation between a texel's two neighbours along
    // each face axis, divided by the angle between them. They are the same derivative up
    // to the differences' truncation error, which is second order in the texel size: it
    // must fall about 4-fold from 128^2 to 256^2 and be small at 256^2 (4 octaves: finest
    // wavelength about 14 texels there). Texels whose neighbours straddle the coast are
    // skipped (each side has its own scale). Also: the gradient is tangential.
    ContinentParams p;
    p.octaves = 4;
    double median[2] = {}, worst[2] = {};
    for (int pass = 0; pass < 2; ++pass) {
        const int n = pass == 0 ? 128 : 256;
        const CubeMap map = bakeContinents(p, n);
        std::vector<double> errors;
        double sumSquares = 0.0, worstRadial = 0.0;
        for (int face = 0; face < 6; ++face)
            for (int y = 1; y + 1 < n; y += n / 64)
                for (int x = 1; x + 1 < n; x += n / 64) {
                    const glm::vec4 t = map.at(face, x, y);
                    const glm::dvec3 g(t.y, t.z, t.w), d = cubeTexelDirection(face, x, y, n);
                    worstRadial = std::max(worstRadial, std::abs(glm::dot(g, d)) / std::max(glm::length(g), 1e-12));
                    const glm::ivec2 steps[2] = {{1, 0}, {0, 1}};
                    for (const glm::ivec2 s : steps) {
                        const float a = map.elevation(face, x - s.x, y - s.y), b = map.elevation(face, x + s.x, y + s.y);
                        if ((a < 0.0f) != (b < 0.0f) || (a < 0.0f) != (t.x < 0.0f)) continue;
                        const glm::dvec3 da = cubeTexelDirection(face, x - s.x, y - s.y, n);
                        const glm::dvec3 db = cubeTexelDirection(face, x + s.x, y + s.y, n);
                        const double difference = (double(b) - a) / angleBetween(da, db);
                        const double analytic = glm::dot(g, glm::normalize(db - da));
                        errors.push_back(std::abs(difference - analytic));
                        sumSquares += analytic * analytic;
                    }
                }
        std::sort(errors.begin(), errors.end());
        const double rms = std::sqrt(sumSquares / double(errors.size()));
        median[pass] = errors[errors.size() / 2] / rms;
        worst[pass] = errors.back() / rms;
        std::printf("baked gradient vs differences of the elevation (%d^2, 4 octaves), %zu pairs: RMS derivative "
                    "%.2f per rad; error median %.4f, max %.4f of it; largest radial part %.1e\n",
                    n, errors.size(), rms, median[pass], worst[pass], worstRadial);
        EXPECT_LT(worstRadial, 1e-5);
    }
    EXPECT_LT(median[1], 0.35 * median[0]);  // second order: 0.25
    EXPECT_LT(worst[1], 0.35 * worst[0]);
    EXPECT_LT(median[1], 0.02);
}

TEST(Continents, SameSeedSameMapOtherSeedOtherMap) {
    ContinentParams p;
    const CubeMap a = bakeContinents(p, 24), b = bakeContinents(p, 24);
    EXPECT_TRUE(a.texels == b.texels);
    p.seed = 2;
    const CubeMap c = bakeContinents(p, 24);
    std::size_t differ = 0, coast = 0;
    for (std::size_t i = 0; i < a.texels.size(); ++i) {
        differ += a.texels[i] != c.texels[i];
        coast += (a.texels[i].x < 0.0f) != (c.texels[i].x < 0.0f);
    }
    EXPECT_EQ(differ, a.texels.size());
    EXPECT_GT(coast, a.texels.size() / 5);  // unrelated land masks disagree on ~48% at 60% sea
}

TEST(Continents, RejectsBadParameters) {
    ContinentParams p;
    EXPECT_THROW(bakeContinents(p, 0), std::invalid_argument);
    p.seaFraction = 1.5;
    EXPECT_THROW(bakeContinents(p, 16), std::invalid_argument);
    p = {};
    p.octaves = 0;
    EXPECT_THROW(bakeContinents(p, 16), std::invalid_argument);
}

// ---------------------------------------------------------------- sampling

TEST(Continents, SampleAtATexelCentreIsThatTexel) {
    const CubeMap& map = baked(1, 0.6, 32);
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                for (int c = 0; c < 4; ++c)
                    ASSERT_NEAR(sampleContinents(map, cubeTexelDirection(face, x, y, 32))[c], map.at(face, x, y)[c],
                                1e-6f * (1.0f + std::abs(map.at(face, x, y)[c])))
                        << face << " " << x << " " << y << " component " << c;
}

TEST(Continents, SampleHalfwayBetweenTexelsIsTheirMeanAcrossEdgesAndCorners) {
    // Inside a face, halfway between two texel centres: their mean. On a cube edge, halfway
    // along an edge texel: the mean of the texels on either side (seamless filtering). At a
    // cube corner: the mean of the three faces' corner texels (the missing fourth tap is
    // their mean, as GL recommends).
    const int n = 16;
    const CubeMap& map = baked(1, 0.6, n);
    // Inside face 4 (+Z: sc = x, tc = -y), halfway between texels (6, 3) and (7, 3).
    auto onFace4 = [](double x, double y) {  // texel coordinates, texel centres at integers
        return glm::dvec3(2.0 * (x + 0.5) / n - 1.0, -(2.0 * (y + 0.5) / n - 1.0), 1.0);
    };
    const glm::vec4 inside = sampleContinents(map, onFace4(6.5, 3.0));
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(inside[c], 0.5f * (map.at(4, 6, 3)[c] + map.at(4, 7, 3)[c]), 1e-5f) << c;
    // The edge between +Z (its column n-1, sc -> 1) and +X (its column 0: sc = -z -> -1), same row.
    for (int row = 0; row < n; ++row) {
        const double tc = 2.0 * (row + 0.5) / n - 1.0;
        const glm::vec4 edge = sampleContinents(map, glm::dvec3(1.0, -tc, 1.0));
        EXPECT_NEAR(edge.x, 0.5f * (map.elevation(4, n - 1, row) + map.elevation(0, 0, row)), 1e-6f) << row;
    }
    // The corner (+1, +1, +1): +X texel (0, 0), +Y texel (n-1, n-1), +Z texel (n-1, 0).
    const float corner = sampleContinents(map, glm::dvec3(1.0)).x;
    EXPECT_NEAR(corner, (map.elevation(0, 0, 0) + map.elevation(2, n - 1, n - 1) + map.elevation(4, n - 1, 0)) / 3.0f,
                1e-6f);
    for (const glm::dvec3 d : {glm::dvec3(1.0, 1.0, 1.0 - 1e-9), glm::dvec3(1.0, 1.0 - 1e-9, 1.0),
                               glm::dvec3(1.0 - 1e-9, 1.0, 1.0)})
        EXPECT_NEAR(sampleContinents(map, d).x, corner, 1e-6f);  // the same from each of the three faces
}

TEST(Continents, SamplesAreContinuousAcrossFaceSeams) {
    // All 12 edges: d[i] = +-1, d[j] = +-1, d[k] = a; one side of the edge moves d[i]
    // inwards by 1e-9, the other d[j]. With seamless filtering both sides blend the same
    // texels, so the jump (elevation and gradient) is float rounding, a millionth of the
    // step between neighbouring texels; without it, it would be up to a whole step.
    const int n = 64;
    const CubeMap& map = baked(1, 0.6, n);
    double interiorStep = 0.0, interiorSum = 0.0;
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x + 1 < n; ++x)
                for (double step : {glm::length(glm::dvec4(map.at(f, x + 1, y) - map.at(f, x, y))),
                                    glm::length(glm::dvec4(map.at(f, y, x + 1) - map.at(f, y, x)))}) {
                    interiorStep = std::max(interiorStep, step);
                    interiorSum += step;
                }
    const double interiorMean = interiorSum / (6.0 * n * (n - 1) * 2);
    double worst = 0.0, sum = 0.0;
    int count = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            for (double si : {-1.0, 1.0})
                for (double sj : {-1.0, 1.0})
                    for (int step = 0; step < 200; ++step) {
                        const int k = 3 - i - j;
                        glm::dvec3 a(0.0);
                        a[i] = si;
                        a[j] = sj;
                        a[k] = -0.995 + 1.99 * step / 199.0;
                        glm::dvec3 b = a;
                        a[i] *= 1.0 - 1e-9;  // on face j
                        b[j] *= 1.0 - 1e-9;  // on face i
                        const double d = glm::length(glm::dvec4(sampleContinents(map, a) - sampleContinents(map, b)));
                        worst = std::max(worst, d);
                        sum += d;
                        ++count;
                    }
    std::printf("seam jump: mean %.4f, max %.4f; neighbour step inside a face: mean %.4f, max %.4f (size %d)\n",
                sum / count, worst, interiorMean, interiorStep, n);
    EXPECT_LE(worst, 1e-6 * interiorMean);
}

// ---------------------------------------------------------------- cache

class ContinentsCache : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::path(PLANET_TEST_OUT) / "continents_cache" /
              ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir);
        key = continentsCacheKey(params, 16);
        entry = dir / key;
        map = bakeContinents(params, 16);
        saveContinents(map, params, entry, key);
    }
    ContinentParams params;
    fs::path dir, entry;
    std::string key;
    CubeMap map;
};

TEST_F(ContinentsCache, RoundTripsExactly) {
    std::string reason;
    const std::optional<CubeMap> loaded = loadContinents(entry, key, 16, &reason);
    ASSERT_TRUE(loaded) << reason;
    EXPECT_EQ(loaded->size, 16);
    EXPECT_EQ(loaded->texels, map.texels);
    // Saving over an existing entry replaces it and leaves no temporary folders.
    saveContinents(map, params, entry, key);
    EXPECT_TRUE(loadContinents(entry, key, 16));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST_F(ContinentsCache, KeyFollowsEveryInput) {
    ContinentParams p = params;
    std::set<std::string> keys{key, continentsCacheKey(p, 32)};
    p.seed = 7;
    keys.insert(continentsCacheKey(p, 16));
    p = params;
    p.seaFraction = 0.5;
    keys.insert(continentsCacheKey(p, 16));
    p = params;
    p.octaves = 5;
    keys.insert(continentsCacheKey(p, 16));
    p = params;
    p.frequency = 2.0;
    keys.insert(continentsCacheKey(p, 16));
    EXPECT_EQ(keys.size(), 6u);
    EXPECT_EQ(key.size(), 16u);
}

TEST_F(ContinentsCache, RejectsMissingDamagedAndForeignEntries) {
    std::string reason;
    EXPECT_FALSE(loadContinents(dir / "nothing", key, 16, &reason));
    EXPECT_TRUE(contains(reason, "no cache folder")) << reason;

    EXPECT_FALSE(loadContinents(entry, "0000000000000000", 16, &reason));
    EXPECT_TRUE(contains(reason, "holds key")) << reason;
    EXPECT_FALSE(loadContinents(entry, key, 32, &reason));
    EXPECT_TRUE(contains(reason, "size")) << reason;

    // One flipped byte in the image: the checksum catches it.
    const fs::path image = entry / "continents.exr";
    std::string bytes = readFile(image);
    bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5a);
    writeFileAtomic(image, bytes);
    EXPECT_FALSE(loadContinents(entry, key, 16, &reason));
    EXPECT_TRUE(contains(reason, "damaged")) << reason;

    // Garbage with a matching checksum: OpenEXR refuses it.
    writeFileAtomic(image, "not an exr");
    std::string keyText = readFile(entry / "key.txt");
    const std::size_t line = keyText.find("continents.exr ");
    ASSERT_NE(line, std::string::npos);
    const std::string garbageSum = [&] {
        // The checksum the loader computes, from its rejection message.
        std::string why;
        loadContinents(entry, key, 16, &why);
        const std::size_t at = why.find("checksum ");
        return at == std::string::npos ? std::string() : why.substr(at + 9, 16);
    }();
    ASSERT_EQ(garbageSum.size(), 16u);
    keyText.replace(line + 15, 16, garbageSum);
    writeFileAtomic(entry / "key.txt", keyText);
    EXPECT_FALSE(loadContinents(entry, key, 16, &reason));
    EXPECT_TRUE(contains(reason, "OpenEXR")) << reason;

    // Well-formed entries with texels out of range: an elevation beyond 1, a gradient NaN.
    for (int bad = 0; bad < 2; ++bad) {
        CubeMap broken = map;
        if (bad == 0) broken.at(3, 5, 7).x = 1.5f;
        else broken.at(3, 5, 7).z = std::nanf("");
        const fs::path other = dir / ("broken" + std::to_string(bad));
        saveContinents(broken, params, other, key);
        EXPECT_FALSE(loadContinents(other, key, 16, &reason));
        EXPECT_TRUE(contains(reason, bad == 0 ? "not in [-1, 1]" : "not finite")) << reason;
    }

    // No key.txt at all.
    fs::remove(entry / "key.txt");
    EXPECT_FALSE(loadContinents(entry, key, 16, &reason));
    EXPECT_FALSE(reason.empty());
}

TEST_F(ContinentsCache, LoadOrBakeBakesOnceThenReadsAndReplacesADamagedEntry) {
    const fs::path root = dir / "root";
    ContinentParams p = params;
    p.seed = 9;
    const CubeMap first = loadOrBakeContinents(p, 16, root);  // baked and saved
    const fs::path entry9 = root / continentsCacheKey(p, 16);
    ASSERT_TRUE(loadContinents(entry9, continentsCacheKey(p, 16), 16));
    EXPECT_TRUE(first.texels == bakeContinents(p, 16).texels);
    writeFileAtomic(entry9 / "continents.exr", "damaged");
    const CubeMap second = loadOrBakeContinents(p, 16, root);  // reported, rebaked, saved again
    EXPECT_TRUE(second.texels == first.texels);
    EXPECT_TRUE(loadContinents(entry9, continentsCacheKey(p, 16), 16));
    EXPECT_THROW(loadOrBakeContinents(p, 0, root), std::invalid_argument);
}

// ---------------------------------------------------------------- planet bake

using BakeCli = planet::test::CliFixture;

TEST_F(BakeCli, BakesCachesAndWritesAPreview) {
    const auto first = planet::test::runCommand(planet("bake --what continents --size 32 --seed 3 --preview p.png"));
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_TRUE(contains(first.output, "sea fraction: 0.6")) << first.output;
    ContinentParams p;
    p.seed = 3;
    const fs::path entry = dir / "cache" / "continents" / continentsCacheKey(p, 32);
    EXPECT_TRUE(fs::exists(entry / "continents.exr"));
    EXPECT_TRUE(contains(first.output, entry.filename().string())) << first.output;
    int w = 0, h = 0, n = 0;
    unsigned char* png = stbi_load((dir / "p.png").c_str(), &w, &h, &n, 4);
    ASSERT_NE(png, nullptr);
    EXPECT_EQ(w, 2 * h);
    bool sea = false, land = false;  // blue-dominated and green/brown-dominated pixels both present
    for (int i = 0; i < w * h; ++i) {
        const unsigned char* q = png + 4 * i;
        sea |= q[2] > q[1] && q[2] > q[0];
        land |= q[2] < q[1];
    }
    stbi_image_free(png);
    EXPECT_TRUE(sea && land);

    const auto second = planet::test::runCommand(planet("bake --what continents --size 32 --seed 3"));
    ASSERT_EQ(second.exitCode, 0) << second.output;
    EXPECT_TRUE(contains(second.output, "cache hit")) << second.output;
    const auto forced = planet::test::runCommand(planet("bake --what continents --size 32 --seed 3 --force"));
    ASSERT_EQ(forced.exitCode, 0) << forced.output;
    EXPECT_FALSE(contains(forced.output, "cache hit")) << forced.output;
}

TEST_F(BakeCli, BakesWhatAPresetsTerrainUses) {
    // The preset's [terrain] parameters: the cache entry the terrain pass will look for.
    std::ofstream(dir / "small.toml") << "[terrain]\nseed = 4\nsea_fraction = 0.3\ncontinent_octaves = 3\n"
                                         "continent_frequency = 2.5\ncontinent_map_size = 24\n[clouds]\nenabled = false\n";
    const auto r = planet::test::runCommand(planet("bake --preset small.toml"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "0.30000 requested")) << r.output;
    ContinentParams p;
    p.seed = 4;
    p.seaFraction = 0.3;
    p.octaves = 3;
    p.frequency = 2.5;
    EXPECT_TRUE(fs::exists(dir / "cache" / "continents" / continentsCacheKey(p, 24) / "continents.exr")) << r.output;
}

TEST_F(BakeCli, BakesThePresetsCloudVolumeAndWeatherMapThenHitsTheCache) {
    std::ofstream(dir / "cloudy.toml") << "[clouds]\nvolume_size = 32\ndetail_frequency = 8\nweather_map_size = 16\n";
    const auto first = planet::test::runCommand(planet("bake --what clouds --preset cloudy.toml --weather-preview w.png"));
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_TRUE(contains(first.output, "cloud volume baked in")) << first.output;
    EXPECT_TRUE(contains(first.output, "weather map baked in")) << first.output;
    EXPECT_TRUE(contains(first.output, "0.4000 cloud")) << first.output;  // the preset's cloud_fraction
    EXPECT_FALSE(fs::exists(dir / "cache" / "continents"));  // --what clouds
    noise::CloudVolumeParams v;
    v.size = 32;
    v.detailFrequency = 8;
    EXPECT_TRUE(fs::exists(dir / "cache" / "clouds" / ("volume-" + noise::cloudVolumeCacheKey(v)) / "cloud_volume.exr"));
    noise::WeatherParams w;
    EXPECT_TRUE(fs::exists(dir / "cache" / "clouds" / ("weather-" + noise::weatherMapCacheKey(w, 16)) / "weather_map.exr"));
    EXPECT_TRUE(fs::exists(dir / "w.png"));
    const auto second = planet::test::runCommand(planet("bake --what clouds --preset cloudy.toml"));
    ASSERT_EQ(second.exitCode, 0) << second.output;
    EXPECT_TRUE(contains(second.output, "cache hit: valid cloud volume")) << second.output;
    EXPECT_TRUE(contains(second.output, "cache hit: valid weather map")) << second.output;
    // No clouds in the preset: said, nothing baked.
    std::ofstream(dir / "clear.toml") << "[clouds]\nenabled = false\n";
    const auto clear = planet::test::runCommand(planet("bake --what clouds --preset clear.toml --cloud-cache cc"));
    ASSERT_EQ(clear.exitCode, 0) << clear.output;
    EXPECT_TRUE(contains(clear.output, "nothing to bake")) << clear.output;
    EXPECT_FALSE(fs::exists(dir / "cc"));
}

TEST_F(BakeCli, RejectsABadSize) {
    for (const char* size : {"7", "4096"}) {
        const auto result = planet::test::runCommand(planet(std::string("bake --size ") + size));
        EXPECT_NE(result.exitCode, 0);
        EXPECT_TRUE(contains(result.output, "--size")) << result.output;
        EXPECT_FALSE(fs::exists(dir / "cache"));
    }
}
