// The continents cube map (noise/continents.h) and `planet bake`: OpenGL's cube face
// convention, the sea fraction, determinism, sampling and its seams, the EXR cache's
// round trip and its refusal of damaged or foreign entries, and the command end to end.
// All CPU; sizes are small so the whole file runs in about a second.
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

#include "noise/continents.h"
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
    auto onBorder = [n](int x, int y) { return x == 0 || y == 0 || x == n - 1 || y == n - 1; };
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
    const auto [lo, hi] = std::minmax_element(map.texels.begin(), map.texels.end());
    EXPECT_EQ(*lo, -1.0f);
    EXPECT_EQ(*hi, 1.0f);
}

TEST(Continents, SameSeedSameMapOtherSeedOtherMap) {
    ContinentParams p;
    const CubeMap a = bakeContinents(p, 24), b = bakeContinents(p, 24);
    EXPECT_EQ(a.texels, b.texels);
    p.seed = 2;
    const CubeMap c = bakeContinents(p, 24);
    std::size_t differ = 0, coast = 0;
    for (std::size_t i = 0; i < a.texels.size(); ++i) {
        differ += a.texels[i] != c.texels[i];
        coast += (a.texels[i] < 0.0f) != (c.texels[i] < 0.0f);
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
                ASSERT_NEAR(sampleContinents(map, cubeTexelDirection(face, x, y, 32)), map.at(face, x, y), 1e-6f)
                    << face << " " << x << " " << y;
}

TEST(Continents, SamplesAreContinuousAcrossFaceSeams) {
    // All 12 edges: d[i] = +-1, d[j] = +-1, d[k] = a; one side of the edge moves d[i]
    // inwards by 1e-9, the other d[j]. The jump there must be no larger than the
    // largest step between neighbouring texels inside a face.
    const int n = 64;
    const CubeMap& map = baked(1, 0.6, n);
    double interiorStep = 0.0, interiorSum = 0.0;
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x + 1 < n; ++x)
                for (double step : {std::abs(double(map.at(f, x + 1, y)) - map.at(f, x, y)),
                                    std::abs(double(map.at(f, y, x + 1)) - map.at(f, y, x))}) {
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
                        const double d = std::abs(double(sampleContinents(map, a)) - sampleContinents(map, b));
                        worst = std::max(worst, d);
                        sum += d;
                        ++count;
                    }
    std::printf("seam jump: mean %.4f, max %.4f; neighbour step inside a face: mean %.4f, max %.4f (size %d)\n",
                sum / count, worst, interiorMean, interiorStep, n);
    EXPECT_LE(worst, interiorStep);
    EXPECT_LE(sum / count, 1.5 * interiorMean);
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

    // No key.txt at all.
    fs::remove(entry / "key.txt");
    EXPECT_FALSE(loadContinents(entry, key, 16, &reason));
    EXPECT_FALSE(reason.empty());
}

// ---------------------------------------------------------------- planet bake

using BakeCli = planet::test::CliFixture;

TEST_F(BakeCli, BakesCachesAndWritesAPreview) {
    const auto first = planet::test::runCommand(planet("bake --size 32 --seed 3 --preview p.png"));
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

    const auto second = planet::test::runCommand(planet("bake --size 32 --seed 3"));
    ASSERT_EQ(second.exitCode, 0) << second.output;
    EXPECT_TRUE(contains(second.output, "cache hit")) << second.output;
    const auto forced = planet::test::runCommand(planet("bake --size 32 --seed 3 --force"));
    ASSERT_EQ(forced.exitCode, 0) << forced.output;
    EXPECT_FALSE(contains(forced.output, "cache hit")) << forced.output;
}

TEST_F(BakeCli, RejectsABadSize) {
    const auto result = planet::test::runCommand(planet("bake --size 7"));
    EXPECT_NE(result.exitCode, 0);
    EXPECT_TRUE(contains(result.output, "--size")) << result.output;
    EXPECT_FALSE(fs::exists(dir / "cache"));
}
