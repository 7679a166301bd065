// The clear sky map (src/clouds/clear_sky.h): around every point, within the angle its texel holds,
// the weather map's coverage (bilinear, as the GPU filters it) is 0, at faces' edges and corners too;
// and the angle is large enough to matter (most of the clear sky, tens of kilometres and more).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "clouds/clear_sky.h"
#include "clouds/cloud_resources.h"
#include "noise/weather_map.h"
#include "scene/scene.h"
#include "test_util.h"

using namespace planet;

namespace {

// The earth preset's weather map (its bake parameters) at 128 a face: 78 km a texel.
const noise::WeatherMap& weather() {
    static const noise::WeatherMap map = [] {
        Scene scene;
        return noise::bakeWeatherMap(clouds::weatherParamsOf(scene.clouds), 128);
    }();
    return map;
}

}  // namespace

TEST(ClearSky, CapRadiusIsTheLargestWhoseStretchedSpanFitsTheLevelsTexels) {
    // (size / 2) r / cos^2(a + r) = 2^k at the root, and just past it more.
    for (const auto& [size, level, axis] : {std::tuple{1024, 0, 0.0}, {1024, 5, 0.5}, {16, 2, 0.95}, {128, 6, 0.2}}) {
        const double r = clouds::clearCapRadius(size, level, axis);
        const double span = 0.5 * size * r / std::pow(std::cos(axis + r), 2);
        EXPECT_NEAR(span, std::ldexp(1.0, level), 1e-9 * std::ldexp(1.0, level)) << size << " " << level << " " << axis;
        EXPECT_GT(0.5 * size * (r * 1.001) / std::pow(std::cos(axis + r * 1.001), 2), std::ldexp(1.0, level));
    }
    // A small cap at a face's centre: r = 2^k / (size / 2), the plane unstretched.
    EXPECT_NEAR(clouds::clearCapRadius(1024, 0, 0.0), 1.0 / 512.0, 1e-8);
}

namespace {

struct CapCheck {
    int points = 0, uncovered = 0, clearPoints = 0, violations = 0, widerViolations = 0;
    double meanKm = 0.0;
};

// 4000 points (a third near faces' edges and corners): where the map holds an angle, 40 places on
// the cap's rim and inside it (the weather's coverage there must be 0) and 40 at three times it.
CapCheck checkCaps(const noise::WeatherMap& map, const clouds::ClearSkyMap& clear) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    CapCheck c;
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec3 p = test::randomCubeDirection(i, rng);
        ++c.points;
        c.uncovered += noise::sampleWeather(map, p).x <= 0.0f;
        const double angle = clouds::clearSkyAngleAt(clear, p);
        if (angle <= 0.0) continue;
        ++c.clearPoints;
        c.meanKm += angle * 6360.0;
        bool wider = false;
        for (int j = 0; j < 40; ++j) {
            // On the cap's rim (where a wrong bound fails first) and inside it.
            const double a = j < 20 ? angle : angle * fraction(rng);
            c.violations += noise::sampleWeather(map, test::atAngle(p, a, rng)).x > 0.0f;
            wider = wider || noise::sampleWeather(map, test::atAngle(p, 3.0 * angle, rng)).x > 0.0f;
        }
        c.widerViolations += wider;
    }
    c.meanKm /= std::max(c.clearPoints, 1);
    std::printf("%d points: %d with no coverage, %d with a clear angle (mean %.0f km on the earth); at 3x the angle "
                "%d reach coverage\n",
                c.points, c.uncovered, c.clearPoints, c.meanKm, c.widerViolations);
    return c;
}

// No coverage within any angle; an angle at more than 1 / `shareDivisor` of the points with no
// coverage (the rest lie within a few texels of coverage, which a level's 3 x 3 must clear), tens of
// kilometres on average; and not loose by much: three times the angle reaches coverage from a tenth
// of the points that have one.
void expectSafeAndUseful(const CapCheck& c, int shareDivisor) {
    EXPECT_EQ(c.violations, 0);
    EXPECT_GT(c.clearPoints, c.uncovered / shareDivisor);
    EXPECT_GT(c.meanKm, 25.0);
    EXPECT_GT(c.widerViolations, c.clearPoints / 10);
}

}  // namespace

TEST(ClearSky, NoCoverageWithinTheAngleOfAnyPoint) {
    const noise::WeatherMap& map = weather();
    const auto start = std::chrono::steady_clock::now();
    const clouds::ClearSkyMap clear = clouds::buildClearSkyMap(map);
    std::printf("the clear sky map of a %d weather map built in %.0f ms\n", map.size,
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    ASSERT_EQ(clear.size, 128);
    // Measured: 741 points with no coverage, 204 with an angle, 53 km on average.
    expectSafeAndUseful(checkCaps(map, clear), 5);
}

TEST(ClearSky, OnACoarserGridTheMaximaOfTheWeathersTexelsStillBoundIt) {
    // The earth's weather at 256 a face on a grid twice coarser (as its 1024 map on 256, 4 times):
    // each coarse texel the largest of the 4 it covers, whose filter's taps reach the fine
    // filter's across the seams.
    Scene scene;
    const noise::WeatherMap map = noise::bakeWeatherMap(clouds::weatherParamsOf(scene.clouds), 256);
    const clouds::ClearSkyMap clear = clouds::buildClearSkyMap(map, 128);
    // Measured: no violation, 151 points with an angle (of 899 with no coverage), 50 km on average.
    ASSERT_EQ(clear.size, 128);
    expectSafeAndUseful(checkCaps(map, clear), 10);
}

TEST(ClearSky, TheLookupIsTheTexelThatHoldsTheDirection) {
    clouds::ClearSkyMap clear;
    clear.size = 4;
    clear.radians.resize(6 * 16);
    for (std::size_t i = 0; i < clear.radians.size(); ++i) clear.radians[i] = float(i);
    // GL's faces (noise/continents.h): +X is (1, -tc, -sc), -X (-1, -tc, sc), with s, t = (sc, tc + 1) / 2.
    double s, t;
    const glm::dvec3 d(1.0, -0.6, 0.1);  // +X, sc = -0.1, tc = 0.6: texel (1, 3) of face 0
    ASSERT_EQ(noise::cubeFaceOf(d, s, t), 0);
    EXPECT_EQ(clouds::clearSkyAngleAt(clear, d), double((0 * 4 + 3) * 4 + 1));
    EXPECT_EQ(clouds::clearSkyAngleAt(clear, -d), double((1 * 4 + 0) * 4 + 1));  // -X, sc = -0.1, tc = -0.6
    EXPECT_EQ(clouds::clearSkyAngleAt(clouds::ClearSkyMap{}, d), 0.0);  // an empty map: nothing is clear
}
