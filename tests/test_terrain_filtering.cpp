// Filtering the terrain by a pixel's footprint (shaders/terrain/height.glsl's
// terrainNormalFiltered and terrainMaterialWeightSpread, compiled as C++; issue 13): a far
// pixel must show the mean of what the ground under it holds, not one sample of it. Checked
// against brute force: the unfiltered functions averaged over many points of the footprint.
// And the detail texture (terrain/detail_texture.h): tiling, zero mean, exact slopes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "noise/continents.h"
#include "noise/noise.h"
#include "terrain/detail_texture.h"
#include "terrain/height.h"

using namespace planet;
using terrain::Material;

namespace {

constexpr float kRadiusM = 6360.0e3f;

struct Ground {
    Ground() : shape(terrain::makeTerrainShape(params())), map(noise::bakeContinents(terrain::continentParams(params()), 64)) {}
    static TerrainParams params() {
        TerrainParams p;  // the shipped defaults' mountains (8 octaves from 120 per radius)
        p.continent_map_size = 64;
        return p;
    }
    terrain::TerrainShape shape;
    noise::CubeMap map;
};

const Ground& ground() {
    static const Ground g;
    return g;
}

// Land directions well inland (where the mountains are), from a fixed seed.
std::vector<glm::vec3> inlandDirections(int count) {
    std::mt19937 random(5);
    std::normal_distribution<float> normal;
    std::vector<glm::vec3> out;
    while (static_cast<int>(out.size()) < count) {
        const glm::vec3 d = glm::normalize(glm::vec3(normal(random), normal(random), normal(random)));
        if (terrain::continentValue(d, ground().map) > 0.4f) out.push_back(d);
    }
    return out;
}

// n points spread evenly over a square of side `sideM` centred on d, in its tangent plane
// (a pixel's footprint on flat ground).
std::vector<glm::vec3> footprintPoints(glm::vec3 d, float sideM, int n) {
    const glm::vec3 east = glm::normalize(glm::cross(glm::vec3(0, 0, 1), d));
    const glm::vec3 north = glm::cross(d, east);
    std::vector<glm::vec3> out;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const float u = ((i + 0.5f) / n - 0.5f) * sideM / kRadiusM;
            const float v = ((j + 0.5f) / n - 0.5f) * sideM / kRadiusM;
            out.push_back(glm::normalize(d + u * east + v * north));
        }
    return out;
}

}  // namespace

TEST(TerrainFiltering, NoFootprintIsTheUnfilteredFieldExactly) {
    const Ground& g = ground();
    for (const glm::vec3& d : inlandDirections(200)) {
        terrain::FootprintSpread spread;
        const glm::vec3 filtered = terrain::terrainNormalFiltered(d, g.shape, g.map, kRadiusM, 0.0f, spread);
        EXPECT_EQ(filtered, terrain::terrainNormal(d, g.shape, g.map, kRadiusM));
        EXPECT_EQ(spread.meanHeightM, terrain::terrainHeight(d, g.shape, g.map));
        EXPECT_EQ(spread.heightSpreadM, 0.0f);
        EXPECT_EQ(spread.slopeSpread, 0.0f);
        for (int m = 0; m < terrain::kMaterialCount; ++m)
            EXPECT_EQ(terrain::terrainMaterialWeightSpread(Material(m), 1000.0f, 0.19f, 0.7f, 0.0f, 0.0f),
                      terrain::terrainMaterialWeight(Material(m), 1000.0f, 0.19f, 0.7f));
    }
}

// terrainFootprintShowsEveryOctave says where the filter leaves the field exactly as it is (the
// ground's material then takes its normal from the near field's evaluation instead,
// terrain/ground_material.frag): at footprints it accepts the filtered normal and height are the
// unfiltered ones to the bit, with no spread; just past its bound (2 % more) the finest octave
// has begun to fade and they differ at most points. Able to fail: a bound one octave too coarse
// (the second finest's cell) accepts footprints at which the finest fades.
TEST(TerrainFiltering, AFootprintThatShowsEveryOctaveIsTheFieldExactly) {
    const Ground& g = ground();
    float bound = 0.0f;  // the largest footprint accepted, m (searched: the test does not assume the formula)
    for (float f = 1.0f; f < 10000.0f; f *= 1.001f)
        if (terrain::terrainFootprintShowsEveryOctave(g.shape, f, kRadiusM)) bound = f;
    ASSERT_GT(bound, 1.0f);
    std::printf("every octave whole up to a footprint of %.1f m\n", bound);
    int differ = 0, points = 0;
    for (const glm::vec3& d : inlandDirections(200)) {
        terrain::FootprintSpread spread;
        const glm::vec3 exact = terrain::terrainNormal(d, g.shape, g.map, kRadiusM);
        EXPECT_EQ(terrain::terrainNormalFiltered(d, g.shape, g.map, kRadiusM, bound, spread), exact);
        EXPECT_EQ(spread.meanHeightM, terrain::terrainHeight(d, g.shape, g.map));
        EXPECT_EQ(spread.heightSpreadM, 0.0f);
        EXPECT_EQ(spread.slopeSpread, 0.0f);
        differ += terrain::terrainNormalFiltered(d, g.shape, g.map, kRadiusM, 1.02f * bound, spread) != exact;
        ++points;
    }
    EXPECT_GT(differ, points / 2) << "past the bound the finest octave fades";
}

// The moments the filter assumes for one octave, re-measured over 400k random points.
TEST(TerrainFiltering, OctaveMomentsAreTheNoisesOwn) {
    std::mt19937 random(9);
    std::uniform_real_distribution<float> u(-200.0f, 200.0f);
    double fbm = 0, fbm2 = 0, fbmGrad = 0, ridged = 0, ridged2 = 0, ridgedGrad = 0;
    const int n = 400000;
    for (int i = 0; i < n; ++i) {
        glm::vec3 g;
        const float v = noise::simplexGrad(glm::vec3(u(random), u(random), u(random)), g);
        const float f = 0.5f + 0.5f * v, ridge = 1.0f - std::abs(v), r = ridge * ridge;
        fbm += f, fbm2 += f * f, fbmGrad += 0.25 * glm::dot(g, g);
        ridged += r, ridged2 += r * r, ridgedGrad += 4.0 * ridge * ridge * glm::dot(g, g);
    }
    const terrain::OctaveMoments m = terrain::mountainOctaveMoments();
    EXPECT_NEAR(m.fbmMean, fbm / n, 0.005);
    EXPECT_NEAR(m.fbmVariance, fbm2 / n - (fbm / n) * (fbm / n), 0.03 * m.fbmVariance);
    EXPECT_NEAR(m.fbmGradientMs, fbmGrad / n, 0.03 * m.fbmGradientMs);
    EXPECT_NEAR(m.ridgedMean, ridged / n, 0.005);
    EXPECT_NEAR(m.ridgedVariance, ridged2 / n - (ridged / n) * (ridged / n), 0.03 * m.ridgedVariance);
    EXPECT_NEAR(m.ridgedGradientMs, ridgedGrad / n, 0.03 * m.ridgedGradientMs);
}

// A pixel 20 km across (the default planet from a few thousand km) over mountains whose
// finest octave is 2.6 km: the filtered height, normal and rock share at its centre against
// the mean of 24 x 24 unfiltered samples of the footprint. The point sample (what the shader
// did before) is the yardstick: the filter must be much closer to the mean than it is.
TEST(TerrainFiltering, AFarPixelShowsTheMeanOfItsFootprint) {
    const Ground& g = ground();
    const float footprintM = 20000.0f;
    double pointHeight = 0, filteredHeight = 0, pointNormal = 0, filteredNormal = 0, pointRock = 0,
           filteredRock = 0, meanRockAll = 0;
    const std::vector<glm::vec3> centres = inlandDirections(60);
    for (const glm::vec3& d : centres) {
        double height = 0, rock = 0;
        glm::dvec3 normal(0.0);
        const std::vector<glm::vec3> points = footprintPoints(d, footprintM, 24);
        for (const glm::vec3& p : points) {
            height += terrain::terrainHeight(p, g.shape, g.map);
            const glm::vec3 n = terrain::terrainNormal(p, g.shape, g.map, kRadiusM);
            normal += glm::dvec3(n);
            const float h = terrain::terrainHeight(p, g.shape, g.map);
            rock += terrain::terrainMaterialWeight(Material::Rock, h, terrain::terrainSlope(n, p),
                                                   terrain::terrainLatitude(p));
        }
        height /= points.size();
        rock /= points.size();
        normal /= double(points.size());  // the mean normal: what a Lambertian pixel reflects, to first order
        meanRockAll += rock;

        terrain::FootprintSpread spread;
        const glm::vec3 nf = terrain::terrainNormalFiltered(d, g.shape, g.map, kRadiusM, footprintM, spread);
        const float rockFiltered =
            terrain::terrainMaterialWeightSpread(Material::Rock, spread.meanHeightM, terrain::terrainSlope(nf, d),
                                                 terrain::terrainLatitude(d), spread.heightSpreadM, spread.slopeSpread);
        const glm::vec3 np = terrain::terrainNormal(d, g.shape, g.map, kRadiusM);
        const float hp = terrain::terrainHeight(d, g.shape, g.map);
        const float rockPoint =
            terrain::terrainMaterialWeight(Material::Rock, hp, terrain::terrainSlope(np, d), terrain::terrainLatitude(d));
        pointHeight += std::abs(hp - height), filteredHeight += std::abs(spread.meanHeightM - height);
        pointNormal += glm::length(glm::dvec3(np) - normal), filteredNormal += glm::length(glm::dvec3(nf) - normal);
        pointRock += std::abs(rockPoint - rock), filteredRock += std::abs(rockFiltered - rock);
    }
    const double n = double(centres.size());
    std::printf("mean |error| against the footprint's mean, point sample -> filtered: height %.1f -> %.1f m, "
                "normal %.4f -> %.4f, rock share %.3f -> %.3f (mean rock share %.3f)\n",
                pointHeight / n, filteredHeight / n, pointNormal / n, filteredNormal / n, pointRock / n,
                filteredRock / n, meanRockAll / n);
    EXPECT_GT(meanRockAll / n, 0.05) << "the footprints must hold rock for the rock check to mean anything";
    // Measured: height 393 -> 199 m, normal 0.325 -> 0.107, rock share 0.314 -> 0.057. The
    // height keeps the octaves between one and four footprints (a pixel can show them), which
    // a box mean over the footprint still damps: hence the height's looser bound.
    EXPECT_LT(filteredHeight, 0.6 * pointHeight);
    EXPECT_LT(filteredNormal, 0.4 * pointNormal);
    EXPECT_LT(filteredRock, 0.3 * pointRock);
}

TEST(TerrainDetailTexture, TilesHasZeroMeanUnitSpreadAndExactSlopes) {
    const terrain::DetailTexture t = terrain::bakeDetailTexture(64);
    ASSERT_EQ(t.texels.size(), 64u * 64u);
    double mean = 0, square = 0, patches = 0;
    for (const glm::vec4& texel : t.texels) mean += texel.z, square += texel.z * texel.z, patches += texel.w;
    mean /= t.texels.size(), square /= t.texels.size(), patches /= t.texels.size();
    // A sum of whole waves over whole periods: the mean (the coarsest mip) is 0, so far
    // ground shows no detail, and the spread is the normalised 1.
    EXPECT_NEAR(mean, 0.0, 1e-4);
    EXPECT_NEAR(patches, 0.0, 1e-4);
    EXPECT_NEAR(std::sqrt(square), 1.0, 0.02);
    // Tiling: the field at uv and uv + (1, 0), (0, 1) agree; texel (0, 0) is h(0, 0).
    for (float u : {0.1f, 0.37f, 0.8f}) {
        EXPECT_NEAR(terrain::detailHeightAt(t, {u, 0.3f}), terrain::detailHeightAt(t, {u + 1.0f, 0.3f}), 1e-3f);
        EXPECT_NEAR(terrain::detailHeightAt(t, {u, 0.3f}), terrain::detailHeightAt(t, {u, 1.3f}), 1e-3f);
    }
    EXPECT_NEAR(t.texels[0].z, terrain::detailHeightAt(t, {0.0f, 0.0f}), 1e-5f);
    // The slopes are the height's derivatives: central differences at a few texels.
    const float e = 1e-3f;
    for (int i : {0, 100, 2000, 4095}) {
        const glm::vec2 uv(float(i % 64) / 64, float(i / 64) / 64);
        const float du = (terrain::detailHeightAt(t, uv + glm::vec2(e, 0)) - terrain::detailHeightAt(t, uv - glm::vec2(e, 0))) / (2 * e);
        const float dv = (terrain::detailHeightAt(t, uv + glm::vec2(0, e)) - terrain::detailHeightAt(t, uv - glm::vec2(0, e))) / (2 * e);
        EXPECT_NEAR(t.texels[i].x, du, 0.01f * std::max(1.0f, std::abs(du)));
        EXPECT_NEAR(t.texels[i].y, dv, 0.01f * std::max(1.0f, std::abs(dv)));
    }
}

// The lattice (issue 13): the fine field has no wave longer than a quarter of the tile, whose
// few integer directions ((1, 0), (1, 1) and turns) drew a regular diamond pattern of the
// tile's size over the rock. Measured by the field's discrete Fourier transform at every wave
// vector with |k| < 3.5: before, with waves from |k| = 1 (1/|k| amplitudes), they held about a
// fifth of the power.
TEST(TerrainDetailTexture, HasNoWaveLongerThanAQuarterOfTheTile) {
    const int n = 256;
    const terrain::DetailTexture t = terrain::bakeDetailTexture(n);
    double total = 0.0;
    for (const glm::vec4& texel : t.texels) total += texel.z * texel.z;
    total /= t.texels.size();  // the mean power, sum over k of |c_k|^2 (Parseval)
    double low = 0.0;
    for (int ky = -3; ky <= 3; ++ky)
        for (int kx = -3; kx <= 3; ++kx) {
            if ((kx == 0 && ky == 0) || kx * kx + ky * ky >= 3.5 * 3.5) continue;
            double re = 0.0, im = 0.0;
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const double a = -6.283185307179586 * (double(kx * x) + double(ky * y)) / n;
                    const double h = t.texels[static_cast<std::size_t>(y) * n + x].z;
                    re += h * std::cos(a), im += h * std::sin(a);
                }
            re /= double(n) * n, im /= double(n) * n;
            low += re * re + im * im;
        }
    EXPECT_LT(low / total, 1e-3) << "share of the fine field's power at |k| < 3.5";
}

// What the mip levels take from the slopes (DetailTexture::lostSlopeVariance, the detail
// filter's table for the lighting): nothing at level 0, more at every level, everything at
// the 1x1 level (mean slope 0), and level 1's share as its 2x2 means say.
TEST(TerrainDetailTexture, LostSlopeVarianceIsWhatEachMipLevelAveragesAway) {
    const int n = 64;
    const terrain::DetailTexture t = terrain::bakeDetailTexture(n);
    ASSERT_EQ(t.lostSlopeVariance.size(), 7u);  // 64 .. 1
    double full = 0.0;
    for (const glm::vec4& texel : t.texels) full += texel.x * texel.x + texel.y * texel.y;
    full /= t.texels.size();
    EXPECT_NEAR(t.lostSlopeVariance.front(), 0.0, 1e-6 * full);
    EXPECT_NEAR(t.lostSlopeVariance.back(), full, 1e-3 * full);
    for (std::size_t i = 1; i < t.lostSlopeVariance.size(); ++i)
        EXPECT_GT(t.lostSlopeVariance[i], t.lostSlopeVariance[i - 1]);
    double level1 = 0.0;
    for (int y = 0; y < n; y += 2)
        for (int x = 0; x < n; x += 2) {
            glm::vec2 s(0.0f);
            for (int d = 0; d < 4; ++d) s += 0.25f * glm::vec2(t.texels[static_cast<std::size_t>(y + d / 2) * n + x + d % 2]);
            level1 += glm::dot(s, s);
        }
    level1 /= (n / 2) * (n / 2);
    EXPECT_NEAR(t.lostSlopeVariance[1], full - level1, 1e-3 * full);
    EXPECT_GT(t.lostSlopeVariance[1], 0.0);
}

// The shader sizes its table by TERRAIN_DETAIL_LEVELS and reads the last entry as the tile's
// whole slope variance (the relief's scale, the coarsest mip's loss): it must have one entry
// per level of the bake the pass makes (bakeDetailTexture's default size), or the GL would
// drop the table's tail without a word.
TEST(TerrainDetailTexture, TheShadersTableHasALevelPerMipOfTheBake) {
    std::ifstream in(std::string(PLANET_SOURCE_DIR) + "/shaders/terrain/detail.glsl");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::smatch m;
    ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(const int TERRAIN_DETAIL_LEVELS = (\d+);)")));
    EXPECT_EQ(static_cast<std::size_t>(std::stoi(m[1])), terrain::bakeDetailTexture().lostSlopeVariance.size());
}

// The surface light's clamped cosine over a spread of detail slopes
// (shaders/terrain/rough_cosine.glsl as C++): E[max(0, mu + sigma X)], X ~ N(0, 1), against a
// Monte Carlo mean over 400 000 normal draws (its standard error is under sigma / 600).
TEST(TerrainDetailLighting, ExpectedClampedCosineIsTheMeanOverNormallySpreadFacets) {
    std::mt19937 random(3);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<double> draws(400000);
    for (double& x : draws) x = normal(random);
    for (float sigma : {0.02f, 0.1f, 0.3f, 0.6f})
        for (float mu : {-0.8f, -0.3f, -0.05f, 0.0f, 0.1f, 0.4f, 0.9f}) {
            double sum = 0.0;
            for (double x : draws) sum += std::max(0.0, double(mu) + double(sigma) * x);
            const double monteCarlo = sum / draws.size();
            EXPECT_NEAR(terrain::expectedClampedCosine(mu, sigma), monteCarlo, 4.0 * sigma / 600.0 + 1e-6)
                << "mu " << mu << ", sigma " << sigma;
        }
    // No spread: the plain clamped cosine; at mu = 0: sigma / sqrt(2 pi), not 0.
    EXPECT_EQ(terrain::expectedClampedCosine(0.5f, 0.0f), 0.5f);
    EXPECT_EQ(terrain::expectedClampedCosine(-0.5f, 0.0f), 0.0f);
    EXPECT_NEAR(terrain::expectedClampedCosine(0.0f, 0.2f), 0.2f / std::sqrt(2.0f * 3.14159265f), 1e-6f);
}

// The detail's two tri-planar projections (shaders/terrain/detail_planes.glsl, compiled as C++):
// world-axis pairs, the least-weighted plane dropped, weights that sum to 1, and no jump on the
// ground where the dropped plane changes; near the 8 directions where all three weights are equal
// (the cube's corners) the pair turns with the direction, gradually a kilometre off. Where the
// third weight is small (every shipped view), the three planes' old rule: |up|^4, those under 2 %
// dropped, renormalised. Weights per axis: each projection's weight on the axis it projects along.
TEST(TerrainDetailTexture, TheTwoProjectionsChangeWithoutAJumpOnTheGround) {
    const auto along = [](glm::vec3 a, glm::vec3 b) { return glm::abs(glm::cross(a, b)); };
    const auto perAxis = [&](const terrain::DetailPlanes& p) {
        return p.w0 * along(p.a0, p.b0) + p.w1 * along(p.a1, p.b1);
    };
    const auto unit = [](double latDeg, double lonDeg) {
        const double lat = glm::radians(latDeg), lon = glm::radians(lonDeg);
        return glm::vec3(glm::dvec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)));
    };
    const double corner = glm::degrees(std::asin(1.0 / std::sqrt(3.0)));  // latitude of (1, 1, 1) / sqrt 3
    constexpr double kKmPerDegree = 6371.0 * 3.14159265358979 / 180.0;
    // Paths across each kind of switch (x = y under a z-heavy vertical; y = z; x = z: the two
    // least components equal), and
    // paths passing a corner at 1, 0.1 and 0.01 degrees: the largest change of the weights per
    // kilometre of ground on an Earth-sized planet, and its bound.
    struct Path {
        double lat0, lon0, lat1, lon1, boundPerKm;
    };
    int switches = 0;
    for (const Path path : {Path{60.0, 44.0, 60.0, 46.0, 0.01}, Path{5.0, 10.0, 15.0, 10.0, 0.01},
                            Path{-5.0, 80.0, -15.0, 80.0, 0.01}, Path{corner + 1.0, 40.0, corner + 1.0, 50.0, 0.03},
                            Path{corner + 0.1, 40.0, corner + 0.1, 50.0, 0.3},
                            Path{corner + 0.01, 40.0, corner + 0.01, 50.0, 3.0}}) {
        constexpr int kSteps = 20000;
        const double stepKm = kKmPerDegree * std::hypot(path.lat1 - path.lat0, (path.lon1 - path.lon0) *
                                                                                    std::cos(glm::radians(path.lat0))) /
                              kSteps;
        glm::vec3 previous(0.0f);
        int droppedBefore = -1;
        double steepest = 0.0;
        for (int i = 0; i <= kSteps; ++i) {
            const double t = static_cast<double>(i) / kSteps;
            const glm::vec3 up = unit(glm::mix(path.lat0, path.lat1, t), glm::mix(path.lon0, path.lon1, t));
            const terrain::DetailPlanes p = terrain::detailPlanes(up);
            for (const glm::vec3 axis : {p.a0, p.b0, p.a1, p.b1}) ASSERT_NEAR(glm::length(axis), 1.0f, 1e-6f);
            ASSERT_NEAR(glm::dot(p.a0, p.b0), 0.0f, 1e-6f);
            ASSERT_NEAR(glm::dot(p.a1, p.b1), 0.0f, 1e-6f);
            ASSERT_NEAR(p.w0 + p.w1, 1.0f, 1e-6f);
            ASSERT_GE(std::min(p.w0, p.w1), 0.0f);
            // The dropped axis (no projection along it) is the vertical's least component.
            const glm::vec3 used = along(p.a0, p.b0) + along(p.a1, p.b1);
            ASSERT_EQ(used.x + used.y + used.z, 2.0f);
            const int dropped = used.x == 0.0f ? 0 : (used.y == 0.0f ? 1 : 2);
            const glm::vec3 c = glm::abs(up);
            EXPECT_LE(c[dropped], std::min({c.x, c.y, c.z}) + 1e-6f) << path.lat0 << " " << t;
            const glm::vec3 weights = perAxis(p);
            if (i > 0) {
                steepest = std::max(steepest, static_cast<double>(glm::length(weights - previous)) / stepKm);
                switches += dropped != droppedBefore;
            }
            previous = weights;
            droppedBefore = dropped;
        }
        std::printf("path from (%.2f, %.1f) to (%.2f, %.1f): weights change by at most %.4f a km\n", path.lat0,
                    path.lon0, path.lat1, path.lon1, steepest);
        // A plane entering with the third's weight (no subtraction) jumps by 0.03-0.3 in one step.
        EXPECT_LT(steepest, path.boundPerKm) << path.lat0 << " " << path.lon0;
    }
    EXPECT_GE(switches, 6);  // each path crosses a switch
    for (const glm::vec3 up : {unit(30.0, -84.0), unit(43.0, -6.5025), unit(41.0, -105.5)}) {  // ground, beach, mountains
        glm::vec3 w = up * up * up * up;
        w /= w.x + w.y + w.z;
        w = glm::mix(glm::vec3(0.0f), w, glm::greaterThan(w, glm::vec3(0.02f)));
        w /= w.x + w.y + w.z;
        EXPECT_LT(glm::length(perAxis(terrain::detailPlanes(up)) - w), 0.01f) << up.x << " " << up.y << " " << up.z;
    }
}
