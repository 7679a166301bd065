// Terrain height field (shaders/terrain/height.glsl, compiled as C++ by terrain/height.cpp):
// CPU properties of heights, normals and materials (tier (a) of STYLE habit 9), and the
// GPU's values from shaders/terrain/height_probe.comp against the same code on the CPU
// (tier (c)). Earth-sized planet, default TerrainParams unless a test says otherwise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "gl/program.h"
#include "gl_test_support.h"
#include "terrain/height.h"
#include "terrain/terrain_params_table.h"

using namespace planet;
using terrain::Material;

namespace {

constexpr float kRadiusM = 6360.0e3f;

std::vector<glm::vec3> randomDirections(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> n(0.0f, 1.0f);
    std::vector<glm::vec3> directions(static_cast<std::size_t>(count));
    for (glm::vec3& d : directions) d = glm::normalize(glm::vec3(n(rng), n(rng), n(rng)));
    return directions;
}

// Direction for a latitude / longitude in radians, in double (world frame of scene.h).
glm::dvec3 directionAt(double latitude, double longitude) {
    return {std::cos(latitude) * std::cos(longitude), std::cos(latitude) * std::sin(longitude), std::sin(latitude)};
}

double angleBetween(glm::dvec3 a, glm::dvec3 b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// Heights, normals and slopes at a set of directions, computed once for several tests.
struct Samples {
    std::vector<glm::vec3> directions;
    std::vector<float> heights, slopes;
};

const Samples& defaultSamples() {
    static const Samples samples = [] {
        Samples s;
        const terrain::TerrainShape shape = terrain::makeTerrainShape(TerrainParams{});
        s.directions = randomDirections(100000, 1);
        for (const glm::vec3& d : s.directions) {
            s.heights.push_back(terrain::terrainHeight(d, shape));
            s.slopes.push_back(terrain::terrainSlope(terrain::terrainNormal(d, shape, kRadiusM), d));
        }
        return s;
    }();
    return samples;
}

// Angles (rad, sorted) between terrainNormal and the normal from central differences of the
// surface P(d) = (R + h(d)) d along two tangents, positions in double, steps of 1e-5 rad.
std::vector<double> normalErrors(const TerrainParams& params) {
    const double step = 1.0e-5;
    const terrain::TerrainShape shape = terrain::makeTerrainShape(params);
    std::vector<double> errors;
    for (const glm::vec3& df : randomDirections(5000, 4)) {
        const glm::dvec3 d(df);
        const glm::dvec3 t1 = glm::normalize(glm::cross(std::abs(d.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0), d));
        const glm::dvec3 t2 = glm::cross(d, t1);
        auto surface = [&](glm::dvec3 offset) {
            const glm::dvec3 e = glm::normalize(d + offset);
            return (double(kRadiusM) + double(terrain::terrainHeight(glm::vec3(e), shape))) * e;
        };
        const glm::dvec3 du = surface(step * t1) - surface(-step * t1);
        const glm::dvec3 dv = surface(step * t2) - surface(-step * t2);
        const glm::dvec3 fd = glm::normalize(glm::cross(du, dv));
        errors.push_back(angleBetween(fd, glm::dvec3(terrain::terrainNormal(df, shape, kRadiusM))));
    }
    std::sort(errors.begin(), errors.end());
    return errors;
}

}  // namespace

// ---------------------------------------------------------------- heights

TEST(TerrainHeight, StaysInRangeUsesMostOfItAndHasLandAndSea) {
    const TerrainParams p;
    const Samples& s = defaultSamples();
    float lo = 0.0f, hi = 0.0f;
    int land = 0;
    for (float h : s.heights) {
        ASSERT_TRUE(std::isfinite(h));
        lo = std::min(lo, h);
        hi = std::max(hi, h);
        if (h > 0.0f) ++land;
    }
    const double landFraction = double(land) / double(s.heights.size());
    std::printf("terrain heights at %zu directions: [%.1f, %.1f] m, land fraction %.3f\n", s.heights.size(), lo, hi,
                landFraction);
    EXPECT_GE(lo, -float(p.ocean_depth_m));
    EXPECT_LE(hi, float(p.max_height_m));
    // Measured [-4000, 4981] m (peaks need every octave's crest at once), 40.6 % land.
    EXPECT_LE(lo, -0.99f * float(p.ocean_depth_m));  // the abyssal plain is reached
    EXPECT_GE(hi, 0.55f * float(p.max_height_m));
    EXPECT_GT(landFraction, 0.2);
    EXPECT_LT(landFraction, 0.6);
}

TEST(TerrainHeight, StaysInRangeForExtremeParameters) {
    TerrainParams rough;
    rough.noise_octaves = 10;
    rough.ridged_weight = 1.0;
    rough.max_height_m = 50000.0;
    rough.ocean_depth_m = 20000.0;
    rough.mountain_frequency = 10000.0;
    rough.continent_frequency = 100.0;
    rough.seed = 1000000;
    TerrainParams smooth;
    smooth.noise_octaves = 1;
    smooth.ridged_weight = 0.0;
    smooth.mountain_frequency = 0.1;
    smooth.continent_frequency = 0.01;
    smooth.seed = 0;
    for (const TerrainParams& p : {rough, smooth}) {
        const terrain::TerrainShape shape = terrain::makeTerrainShape(p);
        for (const glm::vec3& d : randomDirections(20000, 2)) {
            const float h = terrain::terrainHeight(d, shape);
            ASSERT_GE(h, -float(p.ocean_depth_m));
            ASSERT_LE(h, float(p.max_height_m));
            const glm::vec3 n = terrain::terrainNormal(d, shape, kRadiusM);
            ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
        }
    }
}

TEST(TerrainHeight, CoastsAreGentlerThanInlandMountains) {
    const Samples& s = defaultSamples();
    double coast = 0.0, mountains = 0.0;
    int coastCount = 0, mountainCount = 0;
    float steepest = 0.0f;
    for (std::size_t i = 0; i < s.heights.size(); ++i) {
        steepest = std::max(steepest, s.slopes[i]);
        if (std::abs(s.heights[i]) < 50.0f) {
            coast += s.slopes[i];
            ++coastCount;
        } else if (s.heights[i] > 2000.0f) {
            mountains += s.slopes[i];
            ++mountainCount;
        }
    }
    coast /= std::max(coastCount, 1);
    mountains /= std::max(mountainCount, 1);
    std::printf("mean slope within 50 m of sea level %.2e (%d samples), above 2000 m %.2e (%d samples); max %.3f\n",
                coast, coastCount, mountains, mountainCount, steepest);
    ASSERT_GT(coastCount, 100);
    ASSERT_GT(mountainCount, 100);
    EXPECT_LT(coast, 0.1 * mountains);  // measured 2.2e-3 against 0.11
}

TEST(TerrainHeight, SeedPicksAnotherPlanetDeterministically) {
    TerrainParams a, b;
    b.seed = 2;
    const auto shapeA = terrain::makeTerrainShape(a), shapeA2 = terrain::makeTerrainShape(a);
    const auto shapeB = terrain::makeTerrainShape(b);
    int differ = 0;
    for (const glm::vec3& d : randomDirections(1000, 3)) {
        EXPECT_EQ(terrain::terrainHeight(d, shapeA), terrain::terrainHeight(d, shapeA2));
        if (std::abs(terrain::terrainHeight(d, shapeA) - terrain::terrainHeight(d, shapeB)) > 100.0f) ++differ;
    }
    EXPECT_GT(differ, 500);
}

// ---------------------------------------------------------------- normals

TEST(TerrainNormal, MatchesFiniteDifferencesOfTheHeightField) {
    // Steps of 1e-5 rad (64 m; the finest default octave is ~30 km across). Errors: float
    // rounding of h and of the direction (~0.4 m along the ground) over the 128 m baseline,
    // truncation, and ridged crests, where the surface has a crease and a difference across it
    // averages the two sides.
    // Smooth mountains (no ridges, so no creases): every normal agrees to the differences' own error.
    TerrainParams smooth;
    smooth.ridged_weight = 0.0;
    const std::vector<double> s = normalErrors(smooth);
    // The default ridged mountains: the same almost everywhere, but up to ~0.2 rad where the
    // 128 m baseline straddles a crest (about 1 % of the points).
    const std::vector<double> r = normalErrors(TerrainParams{});
    auto percentile = [](const std::vector<double>& e, int p) { return e[e.size() * std::size_t(p) / 100]; };
    std::printf("terrain normal vs finite differences, angle in rad: no ridges median %.2e, max %.2e; "
                "default median %.2e, 95th percentile %.2e, 99th %.2e, max %.2e\n",
                percentile(s, 50), s.back(), percentile(r, 50), percentile(r, 95), percentile(r, 99), r.back());
    EXPECT_LT(percentile(s, 50), 5.0e-4);  // measured 9.9e-5
    EXPECT_LT(s.back(), 1.0e-2);           // measured 3.4e-3
    EXPECT_LT(percentile(r, 50), 5.0e-4);  // measured 1.2e-4
    EXPECT_LT(percentile(r, 95), 1.0e-2);  // measured 1.5e-3
    EXPECT_LT(percentile(r, 99), 0.1);     // measured 3.1e-2 (max 0.13)
}

TEST(TerrainNormal, IsUnitLengthAndTiltsAwayFromHigherGround) {
    TerrainParams smooth;  // no ridge creases, where a step across the crest goes downhill both ways
    smooth.ridged_weight = 0.0;
    const terrain::TerrainShape shape = terrain::makeTerrainShape(smooth);
    int checked = 0;
    for (const glm::vec3& d : randomDirections(2000, 5)) {
        const glm::vec3 n = terrain::terrainNormal(d, shape, kRadiusM);
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(n, d), 0.5f);
        // Moving a little against the normal's tangential part goes uphill.
        const glm::vec3 downhill = n - glm::dot(n, d) * d;
        if (glm::length(downhill) < 1e-4f) continue;
        const glm::vec3 uphill = glm::normalize(d - 1.0e-5f * glm::normalize(downhill));
        const glm::vec3 downhillPoint = glm::normalize(d + 1.0e-5f * glm::normalize(downhill));
        EXPECT_GT(terrain::terrainHeight(uphill, shape), terrain::terrainHeight(downhillPoint, shape) - 0.01f);
        ++checked;
    }
    EXPECT_GT(checked, 500);
}

// ---------------------------------------------------------------- seams

TEST(TerrainHeight, IsContinuousAcrossTheDateLineAndThePoles) {
    // 3D noise of the direction has no seams by construction; this guards against a later
    // change (a cube map, a lat/lon parametrisation) that would bring one. Points 1e-6 rad
    // apart (6.4 m on the ground) differ by at most slope * 6.4 m plus float rounding.
    const terrain::TerrainShape shape = terrain::makeTerrainShape(TerrainParams{});
    const double gap = 1.0e-6, pi = 3.14159265358979323846;
    float worstHeight = 0.0f;
    double worstNormal = 0.0;
    auto compare = [&](glm::dvec3 a, glm::dvec3 b) {
        const glm::vec3 fa(a), fb(b);
        worstHeight = std::max(worstHeight, std::abs(terrain::terrainHeight(fa, shape) - terrain::terrainHeight(fb, shape)));
        worstNormal = std::max(worstNormal, angleBetween(glm::dvec3(terrain::terrainNormal(fa, shape, kRadiusM)),
                                                         glm::dvec3(terrain::terrainNormal(fb, shape, kRadiusM))));
    };
    for (int i = 0; i <= 1000; ++i) {
        const double latitude = -0.5 * pi + 0.01 + (pi - 0.02) * i / 1000.0;
        compare(directionAt(latitude, pi - 0.5 * gap), directionAt(latitude, -pi + 0.5 * gap));
    }
    for (double pole : {-0.5 * pi, 0.5 * pi})
        for (int i = 0; i < 360; ++i) {
            const double toward = pole > 0 ? pole - gap : pole + gap;
            compare(directionAt(pole, 0.0), directionAt(toward, 2.0 * pi * i / 360.0));
        }
    std::printf("across the date line and the poles, 1e-6 rad apart: max |dh| %.3f m, normals %.2e rad\n",
                worstHeight, worstNormal);
    EXPECT_LT(worstHeight, 1.0f);       // measured 0.68 m
    EXPECT_LT(worstNormal, 2.0e-3);     // measured 7.4e-4 rad: the normal's own change over 6 m (a crest crossed)
}

// ---------------------------------------------------------------- materials

TEST(TerrainMaterial, FollowsTheDocumentedRule) {
    const terrain::MaterialThresholds t = terrain::materialThresholds();
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> height(-200.0f, 9000.0f), slope(0.0f, 0.4f), latitude(-1.5707963f, 1.5707963f);
    int counts[terrain::kMaterialCount] = {};
    for (int i = 0; i < 200000; ++i) {
        const float h = i % 4 == 0 ? height(rng) * 0.02f : height(rng);  // a quarter near sea level
        const float s = slope(rng), lat = latitude(rng);
        const Material m = terrain::terrainMaterial(h, s, lat);
        ++counts[int(m)];
        EXPECT_EQ(m == Material::SeaFloor, h < -t.beachDepthM);
        if (m == Material::Snow) { EXPECT_GT(h, terrain::terrainSnowLine(lat)); }  // high, or poleward and above the sea
        if (m == Material::Sand) { EXPECT_TRUE(h >= -t.beachDepthM && h < t.beachHeightM); }  // near sea level only
        if (m == Material::Rock) { EXPECT_GT(s, t.rockSlope); }                                 // steep only
        if (h >= -t.beachDepthM && s > t.rockSlope) { EXPECT_EQ(m, Material::Rock); }         // and every steep slope
        if (m == Material::Grass) { EXPECT_TRUE(h >= t.beachHeightM && h <= terrain::terrainSnowLine(lat) && s <= t.rockSlope); }

        // Blend weights: sum to 1, and the hard rule away from every threshold.
        float sum = 0.0f, own = 0.0f;
        for (int k = 0; k < terrain::kMaterialCount; ++k) {
            const float w = terrain::terrainMaterialWeight(Material(k), h, s, lat);
            EXPECT_GE(w, 0.0f);
            sum += w;
            if (k == int(m)) own = w;
        }
        EXPECT_NEAR(sum, 1.0f, 1e-5f);
        const bool nearThreshold = std::abs(h + t.beachDepthM) < t.blendHeightM ||
                                   std::abs(h - t.beachHeightM) < t.blendHeightM ||
                                   std::abs(h - terrain::terrainSnowLine(lat)) < t.blendSnowM ||
                                   std::abs(s - t.rockSlope) < t.blendSlope;
        if (!nearThreshold) { EXPECT_EQ(own, 1.0f); }
        if (::testing::Test::HasFailure()) return;  // one report, not 200 000
    }
    for (int k = 0; k < terrain::kMaterialCount; ++k) EXPECT_GT(counts[k], 1000) << "material " << k;
    // Snow: at the equator only above the equatorial snow line, near the poles down to the sea.
    EXPECT_EQ(terrain::terrainMaterial(4000.0f, 0.0f, 0.0f), Material::Grass);
    EXPECT_EQ(terrain::terrainMaterial(5500.0f, 0.0f, 0.0f), Material::Snow);
    EXPECT_EQ(terrain::terrainMaterial(30.0f, 0.0f, 1.4f), Material::Snow);
    // The snow line: 5200 m at the equator, 0 at 75 deg, quadratic in latitude between.
    EXPECT_NEAR(terrain::terrainSnowLine(0.0f), 5200.0f, 1e-3f);
    EXPECT_NEAR(terrain::terrainSnowLine(glm::radians(45.0f)), 5200.0f * (1.0f - 0.36f), 0.5f);
    EXPECT_EQ(terrain::terrainSnowLine(glm::radians(80.0f)), 0.0f);
}

TEST(TerrainMaterial, TheDefaultPlanetHasEveryMaterial) {
    const Samples& s = defaultSamples();
    int counts[terrain::kMaterialCount] = {};
    for (std::size_t i = 0; i < s.heights.size(); ++i)
        ++counts[int(terrain::terrainMaterial(s.heights[i], s.slopes[i], terrain::terrainLatitude(s.directions[i])))];
    std::printf("materials at %zu directions: sea floor %d, rock %d, snow %d, sand %d, grass %d\n", s.heights.size(),
                counts[0], counts[1], counts[2], counts[3], counts[4]);
    EXPECT_GT(counts[int(Material::SeaFloor)], 20000);
    EXPECT_GT(counts[int(Material::Sand)], 100);
    EXPECT_GT(counts[int(Material::Grass)], 10000);
    EXPECT_GT(counts[int(Material::Snow)], 1000);
    EXPECT_GT(counts[int(Material::Rock)], 100);
}

// ---------------------------------------------------------------- parameters

TEST(TerrainParams, TableHasARowPerFieldWithTheDefaultsInRange) {
    std::vector<ParamSpec> table;
    addTerrainParams(table);
    ASSERT_EQ(table.size(), 12u);
    Scene scene;
    for (const ParamSpec& row : table) {
        EXPECT_EQ(row.section, "terrain");
        const ParamRef ref = row.field(scene);
        double value = 0.0;
        if (const auto* d = std::get_if<double*>(&ref)) value = **d;
        else if (const auto* i = std::get_if<int*>(&ref)) value = **i;
        else if (const auto* b = std::get_if<bool*>(&ref)) value = **b ? 1.0 : 0.0;
        else ADD_FAILURE() << row.key << " is neither double, int nor bool";
        EXPECT_GE(value, row.min) << row.key;
        EXPECT_LE(value, row.max) << row.key;
    }
    EXPECT_EQ(table.front().key, "max_height_m");
    EXPECT_EQ(std::get<bool*>(table.back().field(scene)), &scene.terrain.ocean);
}

// ---------------------------------------------------------------- GPU vs CPU

namespace {

class TerrainGpu : public test::GLTest {};

}  // namespace

TEST_F(TerrainGpu, ProbeMatchesTheCpuAtRandomDirections) {
    const TerrainParams params;
    const terrain::TerrainShape shape = terrain::makeTerrainShape(params);
    const std::vector<glm::vec3> directions = randomDirections(4096, 7);

    const gl::Program program = gl::buildProgram({std::filesystem::path(PLANET_SOURCE_DIR) / "shaders", gl::shaderPreamble()},
                                                 {"terrain_height_probe", {"terrain/height_probe.comp"}});
    std::vector<glm::vec4> input;
    for (const glm::vec3& d : directions) input.emplace_back(d, 0.0f);
    const GLsizeiptr outputBytes = static_cast<GLsizeiptr>(directions.size() * 2 * sizeof(glm::vec4));
    gl::Buffer shapeBuffer, inputBuffer, outputBuffer;
    glNamedBufferStorage(shapeBuffer.id(), sizeof(shape), &shape, 0);  // std140 mirror, copied as is
    glNamedBufferStorage(inputBuffer.id(), static_cast<GLsizeiptr>(input.size() * sizeof(glm::vec4)), input.data(), 0);
    glNamedBufferStorage(outputBuffer.id(), outputBytes, nullptr, 0);
    glUseProgram(program.id());
    glUniform1i(0, static_cast<GLint>(directions.size()));
    glUniform1f(1, kRadiusM);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, shapeBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, inputBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, outputBuffer.id());
    glDispatchCompute(static_cast<GLuint>((directions.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> gpu(directions.size() * 2);
    glGetNamedBufferSubData(outputBuffer.id(), 0, outputBytes, gpu.data());
    glUseProgram(0);

    float worstHeight = 0.0f;
    double worstNormal = 0.0;
    int materialMismatches = 0;
    for (std::size_t i = 0; i < directions.size(); ++i) {
        const glm::vec3 d = directions[i];
        const glm::vec4 a = gpu[2 * i], b = gpu[2 * i + 1];
        worstHeight = std::max(worstHeight, std::abs(a.x - terrain::terrainHeight(d, shape)));
        worstNormal = std::max(worstNormal, angleBetween(glm::dvec3(a.y, a.z, a.w),
                                                         glm::dvec3(terrain::terrainNormal(d, shape, kRadiusM))));
        // The material and its weight from the GPU's own height, slope and latitude: the
        // rule's code must agree exactly; it can only differ on a threshold.
        const Material m = terrain::terrainMaterial(a.x, b.x, b.y);
        if (int(m) != int(b.z)) ++materialMismatches;
        EXPECT_NEAR(b.w, terrain::terrainMaterialWeight(m, a.x, b.x, b.y), 1e-5f);
    }
    std::printf("terrain GPU - CPU at %zu directions: max |dh| %.3e m (%.1e of max height), normals %.2e rad, "
                "material mismatches %d\n",
                directions.size(), worstHeight, worstHeight / params.max_height_m, worstNormal, materialMismatches);
    // Measured on Mesa llvmpipe: 5.9e-3 m (7e-7 of max_height_m), normals 1.4e-7 rad.
    EXPECT_LT(worstHeight, 1.0e-4f * float(params.max_height_m));
    EXPECT_LT(worstNormal, 1.0e-4);
    EXPECT_EQ(materialMismatches, 0);
}
