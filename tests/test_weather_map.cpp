// The clouds' weather map (noise/weather_map.h), CPU only: the mean coverage follows its
// parameter over the sphere, 0 and 1 are exact, the latitude bands, the three cloud types,
// continuity across the cube's edges, seeds, and the cache (tier (a) and (d) of STYLE habit 9).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "clouds/cloud_resources.h"
#include "noise/cloud_volume.h"
#include "noise/weather_map.h"
#include "util/file_util.h"

using namespace planet;
namespace fs = std::filesystem;

namespace {

constexpr int kSize = 48;

const noise::WeatherMap& bakedDefault() {
    static const noise::WeatherMap map = noise::bakeWeatherMap({}, kSize);
    return map;
}

}  // namespace

// The change of coverage between two neighbouring texels of a face that all but a thousandth of
// the pairs stay under.
float coverageStepAtP999(const noise::WeatherMap& map) {
    std::vector<float> steps;
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y + 1 < map.size; ++y)
            for (int x = 0; x + 1 < map.size; ++x) {
                const float c = map.at(f, x, y).x;
                steps.push_back(std::abs(map.at(f, x + 1, y).x - c));
                steps.push_back(std::abs(map.at(f, x, y + 1).x - c));
            }
    std::nth_element(steps.begin(), steps.begin() + steps.size() * 999 / 1000, steps.end());
    return steps[steps.size() * 999 / 1000];
}

TEST(WeatherMap, TheDefaultMapResolvesTheEdgesOfItsFields) {
    // The edges of the cloud fields seen from orbit follow the map's bilinear filtering: where the
    // coverage changes by much across one texel they are stair-steps of its texels (39 km on the
    // earth at 256 per face, the default until 2026-12-04: 16 px steps in the 640x360 orbit view).
    // The steps shrink with the texel (the fields are smooth at these sizes), and at the default
    // size all but a thousandth of the neighbours differ by under a quarter of the range
    // (measured: 0.167 at 1024 per face; 0.298 at 512, 0.501 at 256). From the cache the GL
    // tests share.
    const CloudParams defaults;
    const noise::WeatherMap map = noise::loadOrBakeWeatherMap(clouds::weatherParamsOf(defaults),
                                                           defaults.weather_map_size, noise::defaultCloudCacheRoot());
    const float step = coverageStepAtP999(map);
    std::printf("weather map %d per face: coverage step between neighbours, 99.9th percentile %.3f\n", map.size,
                step);
    EXPECT_LT(step, 0.25f);
}

TEST(WeatherMap, MeanCoverageOverTheSphereFollowsTheParameter) {
    for (const double coverage : {0.1, 0.3, 0.5, 0.7, 0.9}) {
        noise::WeatherParams p;
        p.coverage = coverage;
        const noise::WeatherMap map = noise::bakeWeatherMap(p, kSize);
        // Solid-angle weighted, and by an independent Monte Carlo over directions.
        EXPECT_NEAR(noise::meanCoverageOf(map), coverage, 2.0e-3) << coverage;
        std::mt19937 rng(3);
        std::normal_distribution<double> g(0.0, 1.0);
        double sum = 0.0;
        const int samples = 20000;
        for (int i = 0; i < samples; ++i) sum += noise::sampleWeather(map, {g(rng), g(rng), g(rng)}).x;
        EXPECT_NEAR(sum / samples, coverage, 0.02) << coverage;
        // Somewhere clear and somewhere overcast: fields, not a uniform haze.
        int clear = 0, overcast = 0;
        for (const glm::vec2& t : map.texels) {
            ASSERT_TRUE(t.x >= 0.0f && t.x <= 1.0f && t.y >= 0.0f && t.y <= 1.0f);
            clear += t.x == 0.0f;
            overcast += t.x == 1.0f;
        }
        EXPECT_GT(clear, 0) << coverage;
        EXPECT_GT(overcast, 0) << coverage;
    }
}

TEST(WeatherMap, CoverageZeroIsClearEverywhereAndOneOvercast) {
    for (const double coverage : {0.0, 1.0}) {
        noise::WeatherParams p;
        p.coverage = coverage;
        const noise::WeatherMap map = noise::bakeWeatherMap(p, 16);
        for (const glm::vec2& t : map.texels) ASSERT_EQ(t.x, static_cast<float>(coverage));
    }
}

TEST(WeatherMap, SubtropicsAreClearerThanTheStormTracks) {
    // The zonal pattern (weather_map.h): averaged over three seeds, the coverage between 15
    // and 35 degrees of latitude is below that between 45 and 65.
    double subtropics = 0.0, stormTracks = 0.0, subtropicsWeight = 0.0, stormWeight = 0.0;
    for (int seed = 1; seed <= 3; ++seed) {
        noise::WeatherParams p;
        p.seed = seed;
        p.latitudeBands = 1.0;
        const noise::WeatherMap map = noise::bakeWeatherMap(p, kSize);
        for (int f = 0; f < 6; ++f)
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    const glm::dvec3 d = noise::cubeTexelDirection(f, x, y, kSize);
                    const double lat = std::abs(glm::degrees(std::asin(d.z)));
                    const double w = noise::cubeTexelSolidAngle(x, y, kSize);
                    if (lat > 15.0 && lat < 35.0) {
                        subtropics += w * map.at(f, x, y).x;
                        subtropicsWeight += w;
                    } else if (lat > 45.0 && lat < 65.0) {
                        stormTracks += w * map.at(f, x, y).x;
                        stormWeight += w;
                    }
                }
    }
    subtropics /= subtropicsWeight;
    stormTracks /= stormWeight;
    std::printf("mean coverage: subtropics %.3f, storm tracks %.3f\n", subtropics, stormTracks);
    EXPECT_LT(subtropics + 0.1, stormTracks);
}

TEST(WeatherMap, AllThreeCloudTypesOccur) {
    double stratus = 0.0, cumulus = 0.0, high = 0.0;
    for (const glm::vec2& t : bakedDefault().texels) {
        stratus += t.y < 0.25f;
        cumulus += t.y >= 0.25f && t.y <= 0.75f;
        high += t.y > 0.75f;
    }
    const double n = static_cast<double>(bakedDefault().texels.size());
    std::printf("cloud types: stratus %.3f, cumulus %.3f, high %.3f of the texels\n", stratus / n, cumulus / n, high / n);
    EXPECT_GT(stratus / n, 0.03);
    EXPECT_GT(cumulus / n, 0.3);
    EXPECT_GT(high / n, 0.03);
}

TEST(WeatherMap, IsContinuousAcrossCubeEdges) {
    // (a) The baked field: texels that share a cube edge differ no more than neighbours inside
    // a face (a face baked with a wrong orientation would make the edge a seam).
    const noise::WeatherMap& map = bakedDefault();
    double across = 0.0, inside = 0.0;
    int acrossCount = 0, insideCount = 0;
    for (int f = 0; f < 6; ++f)
        for (int i = 0; i < kSize; ++i) {
            // The texel beyond the face's x = size - 1 edge: the face of a point just past it.
            const glm::dvec3 edge = noise::cubeTexelDirection(f, kSize - 1, i, kSize);
            const glm::dvec3 next = noise::cubeTexelDirection(f, kSize - 2, i, kSize);
            const glm::dvec3 beyond = glm::normalize(edge + (edge - next));  // one texel further along the great circle
            double s = 0.0, t = 0.0;
            const int g = noise::cubeFaceOf(beyond, s, t);
            ASSERT_NE(g, f);
            const glm::vec2 other = map.at(g, std::clamp(int(s * kSize), 0, kSize - 1), std::clamp(int(t * kSize), 0, kSize - 1));
            across += std::abs(other.x - map.at(f, kSize - 1, i).x);
            ++acrossCount;
            inside += std::abs(map.at(f, kSize - 2, i).x - map.at(f, kSize - 1, i).x);
            ++insideCount;
        }
    across /= acrossCount;
    inside /= insideCount;
    std::printf("mean |coverage step|: across cube edges %.4f, inside faces %.4f\n", across, inside);
    EXPECT_LT(across, 1.5 * inside + 0.01);
    // (b) The sampler: small steps across edges give small changes.
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    float worst = 0.0f;
    for (int i = 0; i < 3000; ++i) {
        // A point on an edge of the cube (two coordinates +-1), stepped across it.
        glm::dvec3 c(u(rng), u(rng), u(rng));
        const int a = i % 3, b = (i + 1) % 3;
        c[a] = c[a] < 0.0 ? -1.0 : 1.0;
        c[b] = c[b] < 0.0 ? -1.0 : 1.0;
        glm::dvec3 step(0.0);
        step[a] = -c[a] * 1.0e-4;
        step[b] = c[b] * 1.0e-4;
        const glm::vec2 w0 = noise::sampleWeather(map, c - step), w1 = noise::sampleWeather(map, c + step);
        worst = std::max({worst, std::abs(w0.x - w1.x), std::abs(w0.y - w1.y)});
    }
    EXPECT_LT(worst, 0.02f);  // 2e-4 of a face is 1 % of a texel at 48
}

TEST(WeatherMap, SamplerReturnsTexelsAtTheirCentres) {
    const noise::WeatherMap& map = bakedDefault();
    for (int f = 0; f < 6; ++f) {
        const glm::vec2 w = noise::sampleWeather(map, noise::cubeTexelDirection(f, 7, 30, kSize));
        EXPECT_NEAR(w.x, map.at(f, 7, 30).x, 1e-5);
        EXPECT_NEAR(w.y, map.at(f, 7, 30).y, 1e-5);
    }
}

TEST(WeatherMap, SameSeedSameMapAnotherSeedAnotherMap) {
    const noise::WeatherMap again = noise::bakeWeatherMap({}, kSize);
    EXPECT_EQ(again.texels, bakedDefault().texels);
    noise::WeatherParams other;
    other.seed = 7;
    const noise::WeatherMap different = noise::bakeWeatherMap(other, kSize);
    double difference = 0.0;
    for (std::size_t i = 0; i < different.texels.size(); ++i)
        difference += std::abs(different.texels[i].x - bakedDefault().texels[i].x);
    EXPECT_GT(difference / static_cast<double>(different.texels.size()), 0.15);
    EXPECT_NE(noise::weatherMapCacheKey(other, kSize), noise::weatherMapCacheKey({}, kSize));
}

TEST(WeatherMap, RejectsParametersOutOfRange) {
    noise::WeatherParams p;
    EXPECT_THROW(noise::bakeWeatherMap(p, 2), std::invalid_argument);
    p.coverage = 1.2;
    EXPECT_THROW(noise::bakeWeatherMap(p, 16), std::invalid_argument);
    p = {};
    p.octaves = 0;
    EXPECT_THROW(noise::bakeWeatherMap(p, 16), std::invalid_argument);
    p = {};
    p.frequency = 0.0;
    EXPECT_THROW(noise::bakeWeatherMap(p, 16), std::invalid_argument);
}

TEST(WeatherMap, CacheRoundTripsAndRejectsDamageWithAReasonThenRebakes) {
    const fs::path root = fs::path(PLANET_TEST_OUT) / "weather_map_cache";
    fs::remove_all(root);
    const noise::WeatherParams p;
    const std::string key = noise::weatherMapCacheKey(p, kSize);
    const fs::path dir = root / ("weather-" + key);
    const noise::WeatherMap baked = noise::loadOrBakeWeatherMap(p, kSize, root);
    EXPECT_EQ(baked.texels, bakedDefault().texels);
    std::string reason;
    const std::optional<noise::WeatherMap> loaded = noise::loadWeatherMap(dir, key, kSize, &reason);
    ASSERT_TRUE(loaded) << reason;
    EXPECT_EQ(loaded->texels, baked.texels);
    EXPECT_FALSE(noise::loadWeatherMap(dir, key, 32, &reason));
    EXPECT_NE(reason.find("size"), std::string::npos) << reason;
    {
        std::string bytes = readFile(dir / "weather_map.exr");
        bytes[bytes.size() - 100] = static_cast<char>(bytes[bytes.size() - 100] ^ 0x01);
        writeFileAtomic(dir / "weather_map.exr", bytes);
    }
    EXPECT_FALSE(noise::loadWeatherMap(dir, key, kSize, &reason));
    EXPECT_NE(reason.find("damaged"), std::string::npos) << reason;
    EXPECT_EQ(noise::loadOrBakeWeatherMap(p, kSize, root).texels, baked.texels);
    EXPECT_TRUE(noise::loadWeatherMap(dir, key, kSize, &reason)) << reason;
}
