// The continents' maxima (src/terrain/continent_bound.h): the pyramid's value for a cap bounds the
// map everywhere in it, seams and corners of the cube included, and it is tight enough to drop the
// open sea's floor from orbit (tests/test_ocean_culling.cpp has the frames).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "app/session.h"
#include "gl/program.h"
#include "render/bindings.h"
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
        const glm::dvec3 centre = test::randomCubeDirection(i, rng);
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

namespace {

class ContinentBoundGpu : public test::GLTest {};

}  // namespace

TEST_F(ContinentBoundGpu, TheControlStagesLookupIsTheCpuTwins) {
    // shaders/terrain/continent_max_probe.comp: continentMaxWithin (terrain/patch_continents.glsl),
    // as terrain/terrain.tesc calls it, against terrain::continentMaxWithin over 4000 caps (a third
    // near the faces' edges and corners), the pyramid's texture as the terrain pass uploads it. The
    // GPU picks the level in float, rounded up by 1e-4 (a coarser level still bounds: its 3x3 holds
    // the finer one's), and the texel by GL's face selection in float: where either falls on a
    // boundary the GPU's value may be a neighbour's or a coarser level's. Measured on llvmpipe: of
    // the 3555 caps whose centre is on one face, 3554 the same (342 past the pyramid: 1e30 on both),
    // 1 looser (a coarser level), none tighter. A GLSL lookup with another stretch or level rounding
    // than the twin's would pick other levels for many of them.
    const Session s = loadSession(test::repoPaths(), "earth", "orbit");
    const noise::CubeMap& map = s.ground.continents();
    const terrain::ContinentMaxPyramid pyramid = terrain::buildContinentMaxPyramid(map);
    const gl::Texture texture = terrain::makeContinentMaxTexture(pyramid);
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    std::vector<glm::vec4> caps;
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec3 centre = test::randomCubeDirection(i, rng);
        caps.emplace_back(glm::vec3(centre), static_cast<float>(std::pow(10.0, -4.0 + 3.4 * fraction(rng))));
    }
    const gl::Program program =
        gl::buildProgram({test::repoPaths().shaders(), gl::shaderPreamble()},
                         {"continent_max_probe", {"terrain/continent_max_probe.comp"}});
    gl::Buffer input, output;
    glNamedBufferStorage(input.id(), static_cast<GLsizeiptr>(caps.size() * sizeof(glm::vec4)), caps.data(), 0);
    glNamedBufferStorage(output.id(), static_cast<GLsizeiptr>(caps.size() * sizeof(float)), nullptr, 0);
    glBindTextureUnit(binding::UNIT_CONTINENT_MAX, texture.id());
    glUseProgram(program.id());
    glUniform1i(0, static_cast<GLint>(caps.size()));
    glUniform1f(1, static_cast<float>(terrain::kContinentMaxRadiusRad));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
    glDispatchCompute(static_cast<GLuint>((caps.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> gpu(caps.size());
    glGetNamedBufferSubData(output.id(), 0, static_cast<GLsizeiptr>(gpu.size() * sizeof(float)), gpu.data());
    glUseProgram(0);
    glBindTextureUnit(binding::UNIT_CONTINENT_MAX, 0);
    int same = 0, looser = 0, tighter = 0, unbounded = 0, ties = 0;
    for (std::size_t i = 0; i < caps.size(); ++i) {
        // A centre on a cube edge (two largest components equal in float) is on two faces, and GL
        // leaves the choice to the implementation: either face's texel bounds the cap.
        const glm::vec3 a = glm::abs(glm::vec3(caps[i]));
        const float largest = std::max(a.x, std::max(a.y, a.z));
        if ((a.x == largest) + (a.y == largest) + (a.z == largest) > 1) {
            ++ties;
            continue;
        }
        // The CPU twin for the cap the GPU was given (float centre and radius).
        float cpu = terrain::continentMaxWithin(pyramid, glm::dvec3(glm::vec3(caps[i])), double(caps[i].w));
        if (!std::isfinite(cpu)) cpu = 1.0e30f;
        unbounded += cpu >= 1.0e30f;
        same += gpu[i] == cpu;
        looser += gpu[i] > cpu;
        tighter += gpu[i] < cpu;
    }
    std::printf("%zu caps (%d on an edge, not compared): %d the same (%d past the pyramid on the CPU), %d looser on "
                "the GPU, %d tighter\n",
                caps.size(), ties, same, unbounded, looser, tighter);
    EXPECT_GE(same, 3960 - ties);
    EXPECT_LE(tighter, 20);  // a neighbour's texel at a boundary, at most
    EXPECT_GE(unbounded, 200);  // the caps reach past the pyramid, where both say nothing
    EXPECT_LE(unbounded, 3000);
}
