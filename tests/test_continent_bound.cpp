// The continents' maxima (src/terrain/continent_bound.h): the pyramid's value for a cap bounds the
// map everywhere in it, seams and corners of the cube included, and it is tight enough to drop the
// open sea's floor from orbit (tests/test_ocean_culling.cpp has the frames).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "app/session.h"
#include "gl_test_support.h"
#include "noise/continents.h"
#include "test_util.h"
#include "terrain/continent_bound.h"

using namespace planet;

TEST(ContinentBound, LevelsCoverTheCapsTheyAreAskedFor) {
    // The stretch: 3 at a face's corner for a point cap, 1 / cos^2(54.7 deg + 0.2) at 0.2 rad.
    EXPECT_NEAR(terrain::continentCapStretch(0.0), 3.0, 1e-12);
    EXPECT_NEAR(terrain::continentCapStretch(0.2), 1.0 / std::pow(std::cos(std::acos(1.0 / std::sqrt(3.0)) + 0.2), 2), 1e-12);
    // (size / 2) s r <= 2^k: at 512 a face, r = 1 / 768 is level 0 (s = 3 + a little: just over).
    EXPECT_EQ(terrain::continentMaxLevel(512, 8, 0.0), 0);
    EXPECT_EQ(terrain::continentMaxLevel(512, 8, 0.99 / 768.0), 0);
    EXPECT_EQ(terrain::continentMaxLevel(512, 8, 1.01 / 768.0), 1);
    EXPECT_EQ(terrain::continentMaxLevel(512, 8, 0.06), 6);   // 256 x 3.59 x 0.06 = 55 texels
    EXPECT_EQ(terrain::continentMaxLevel(512, 8, 0.08), 7);   // 79
    EXPECT_EQ(terrain::continentMaxLevel(512, 8, 0.13), -1);  // 152: past the coarsest level
    EXPECT_EQ(terrain::continentMaxLevel(16, 5, 0.21), -1);  // past the stretch bound
    EXPECT_EQ(terrain::continentMaxLevel(512, 8, -1.0), -1);
}

TEST(ContinentBound, TheMaximaBoundTheMapOverEveryCap) {
    const Session s = loadSession(test::repoPaths(), "earth", "orbit");
    const noise::CubeMap& map = s.ground.continents();
    const auto start = std::chrono::steady_clock::now();
    const terrain::ContinentMaxPyramid pyramid = terrain::buildContinentMaxPyramid(map);
    std::printf("the pyramid of a %d map built in %.0f ms\n", map.size,
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    ASSERT_EQ(pyramid.size, map.size);
    ASSERT_EQ(pyramid.levels.size(), std::size_t(terrain::kContinentMaxLevels));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    int caps = 0, violations = 0;
    double worstExcess = -1e30, meanSlack = 0.0;
    for (int i = 0; i < 3000; ++i) {
        glm::dvec3 centre = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        if (i % 3 == 0) {  // near a face's edge or corner, where the faces meet
            glm::dvec3 a = glm::abs(centre);
            const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
            const int other = (axis + 1 + (i / 3) % 2) % 3;
            centre[other] = std::copysign(std::abs(centre[axis]) * (1.0 - 0.002 * fraction(rng)), centre[other]);
            if (i % 9 == 0) centre[3 - axis - other] = std::copysign(std::abs(centre[axis]), centre[3 - axis - other]);
            centre = glm::normalize(centre);
        }
        const double radius = std::pow(10.0, -4.0 + 3.3 * fraction(rng));  // 1e-4 .. 0.2 rad
        const float bound = terrain::continentMaxWithin(pyramid, centre, radius);
        if (!std::isfinite(bound)) {
            EXPECT_GT(radius, 0.11) << "a cap the levels cover had no bound";
            continue;
        }
        ++caps;
        float highest = -1e30f;
        for (int k = 0; k < 200; ++k) {
            const double angle = radius * std::sqrt(fraction(rng));
            highest = std::max(highest, noise::sampleContinents(map, test::atAngle(centre, angle, rng)).x);
        }
        highest = std::max(highest, noise::sampleContinents(map, centre).x);
        if (highest > bound) ++violations;
        worstExcess = std::max(worstExcess, double(highest - bound));
        meanSlack += bound - highest;
    }
    meanSlack /= std::max(caps, 1);
    std::printf("%d caps bounded, %d exceeded (worst by %.2e); mean slack of the bound over the sampled maximum %.3f\n",
                caps, violations, worstExcess, meanSlack);
    EXPECT_GT(caps, 2000);
    EXPECT_EQ(violations, 0);
    // Tight enough to say something: the map's values span about [-1, 1], and the slope bound
    // alone over a cap of 0.01 rad allows 0.7 above its centre's value.
    EXPECT_LT(meanSlack, 0.2);
}

TEST(ContinentBound, SmallCapsAreBoundedNearTheirCentresValue) {
    const Session s = loadSession(test::repoPaths(), "earth", "orbit");
    const noise::CubeMap& map = s.ground.continents();
    const terrain::ContinentMaxPyramid pyramid = terrain::buildContinentMaxPyramid(map);
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 centre = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        const float bound = terrain::continentMaxWithin(pyramid, centre, 1e-5);
        const float value = noise::sampleContinents(map, centre).x;
        ASSERT_GE(bound, value);
        worst = std::max(worst, double(bound - value));
    }
    // Level 0: the largest texel of the 4 x 4 around each place of a 3 x 3 of texels, about five
    // texels across (a texel spans 1/256 of the face's plane; the slope bound, 70 per radian, over
    // 2.5 texels: 0.68 at the face's centre).
    std::printf("a cap of 1e-5 rad: bound at most %.3f above its centre's value\n", worst);
    EXPECT_LT(worst, 0.6);
}
