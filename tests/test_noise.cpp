// Noise (shaders/noise/*.glsl, compiled as C++ by noise/noise.cpp): CPU properties of
// simplex, fBm, ridged fBm, Worley F1 and tiled Perlin noise and fBm (tier (a) of STYLE
// habit 9), and the GPU's values from shaders/noise/noise_probe.comp against the same code
// on the CPU (tier (c)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "gl/program.h"
#include "gl_test_support.h"
#include "noise/noise.h"

using namespace planet;

namespace {

// Uniform random points in [-extent, extent]^3, the same on every run.
std::vector<glm::vec3> randomPoints(int count, float extent, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-extent, extent);
    std::vector<glm::vec3> points(static_cast<std::size_t>(count));
    for (glm::vec3& p : points) p = glm::vec3(u(rng), u(rng), u(rng));
    return points;
}

glm::vec3 randomDirection(std::mt19937& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    return glm::normalize(glm::vec3(n(rng), n(rng), n(rng)));
}

// Central finite differences of f in float, step about h; divided by the step the
// rounded coordinates really took (p +- h rounds to the float grid, off by up to
// 1e-3 relative at |p| ~ 10 and h = 1e-3).
template <class F>
glm::vec3 centralDifference(F f, glm::vec3 p, float h) {
    glm::vec3 g;
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 plus = p, minus = p;
        plus[axis] += h;
        minus[axis] -= h;
        g[axis] = (f(plus) - f(minus)) / (plus[axis] - minus[axis]);
    }
    return g;
}

}  // namespace

// ---------------------------------------------------------------- seed offsets

TEST(NoiseSeedOffset, IsDeterministicInRangeOnTheFloatGridAndUnrelatedAcrossSeedsAndStreams) {
    // Each component in [-32, 32) in steps of 1/256 (exact in float); the same seed and
    // stream give the same offset, nearby seeds and the two streams give far-apart ones.
    std::vector<glm::vec3> offsets;
    for (int seed : {0, 1, 2, 3, 1000000})
        for (unsigned stream : {0u, 1u}) {
            const glm::vec3 o = noise::seedOffset(seed, stream);
            EXPECT_EQ(o, noise::seedOffset(seed, stream));
            for (int c = 0; c < 3; ++c) {
                EXPECT_GE(o[c], -32.0f);
                EXPECT_LT(o[c], 32.0f);
                EXPECT_EQ(o[c] * 256.0f, std::floor(o[c] * 256.0f));
            }
            offsets.push_back(o);
        }
    for (std::size_t i = 0; i < offsets.size(); ++i)
        for (std::size_t j = i + 1; j < offsets.size(); ++j)
            EXPECT_GT(glm::length(offsets[i] - offsets[j]), 1.0f) << i << " " << j;  // a simplex cell apart at least
}

// ---------------------------------------------------------------- simplex

TEST(NoiseSimplex, StaysInRangeReachesBeyondPointEightAndAveragesZero) {
    float lo = 0.0f, hi = 0.0f;
    double sum = 0.0, sum2 = 0.0;
    const auto points = randomPoints(100000, 100.0f, 1);
    for (const glm::vec3& p : points) {
        const float v = noise::simplex(p);
        ASSERT_TRUE(std::isfinite(v)) << p.x << " " << p.y << " " << p.z;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        sum += v;
        sum2 += double(v) * v;
    }
    const double mean = sum / double(points.size());
    const double sd = std::sqrt(sum2 / double(points.size()) - mean * mean);
    // Measured: [-0.967, 0.965], standard deviation 0.38; the numerically maximised extreme is 0.974.
    EXPECT_LE(hi, 1.0f);
    EXPECT_GE(lo, -1.0f);
    EXPECT_GT(hi, 0.8f);
    EXPECT_LT(lo, -0.8f);
    EXPECT_NEAR(mean, 0.0, 0.01);  // standard error about 0.001
    EXPECT_GT(sd, 0.15);           // a collapsed or over-scaled noise lands outside
    EXPECT_LT(sd, 0.5);
}

TEST(NoiseSimplex, SmallStepsGiveSmallChanges) {
    // Lipschitz: |n(p + d) - n(p)| <= max |gradient| |d|. A kernel wider than the simplex
    // (radius^2 0.6) or a corner hashed inconsistently between neighbouring simplices
    // makes jumps of several 0.01 at simplex faces, which 100 000 steps cross hundreds of times.
    std::mt19937 rng(2);
    const float step = 1.0e-3f;
    float worst = 0.0f, maxGradient = 0.0f;
    for (const glm::vec3& p : randomPoints(100000, 20.0f, 3)) {
        glm::vec3 g;
        const float v = noise::simplexGrad(p, g);
        maxGradient = std::max(maxGradient, glm::length(g));
        worst = std::max(worst, std::abs(noise::simplex(p + step * randomDirection(rng)) - v));
    }
    EXPECT_LT(maxGradient, 10.0f);  // measured 7.3
    EXPECT_LT(worst, 10.0f * step);
}

TEST(NoiseSimplex, AnalyticGradientMatchesCentralDifferences) {
    // Float central differences: truncation ~h^2 |n'''| / 6, plus the noise's own rounding
    // (x0 = p - i is off by ~ulp(|p|), times |gradient| ~5) divided by h; near the origin
    // with h = 2e-3 both stay small. A wrong derivative (missing -8 m^3 term, wrong
    // scale) is off by O(1). Measured max 5e-4.
    const float h = 2.0e-3f;
    float worst = 0.0f;
    for (const glm::vec3& p : randomPoints(20000, 2.0f, 4)) {
        glm::vec3 g;
        noise::simplexGrad(p, g);
        const glm::vec3 fd = centralDifference([](glm::vec3 q) { return noise::simplex(q); }, p, h);
        worst = std::max(worst, glm::length(g - fd));
    }
    std::printf("simplex gradient - central differences: max %.2e\n", worst);
    EXPECT_LT(worst, 2.0e-3f);
}

TEST(NoiseSimplex, IsDeterministicAndKeepsItsValues) {
    // Baked textures (continents, cloud volume) are cached; if these values change,
    // the noise changed, and so must those caches' version keys.
    const glm::vec3 p(1.25f, -3.5f, 7.75f);
    EXPECT_EQ(noise::simplex(p), noise::simplex(p));
    EXPECT_EQ(noise::worley(p, 8.0f), noise::worley(p, 8.0f));
    EXPECT_NEAR(noise::simplex(p), 0.0977540f, 1e-6f);
    EXPECT_NEAR(noise::fbm(p, 5), 0.0271786f, 1e-6f);
    EXPECT_NEAR(noise::worley(p), 0.3767854f, 1e-6f);
}

// ---------------------------------------------------------------- fBm

TEST(NoiseFbm, OneOctaveIsSimplexAndOctavesAreClamped) {
    for (const glm::vec3& p : randomPoints(1000, 50.0f, 5)) {
        EXPECT_EQ(noise::fbm(p, 1, 2.0f, 0.5f), noise::simplex(p));
        EXPECT_EQ(noise::fbm(p, 0), noise::fbm(p, 1));
        EXPECT_EQ(noise::fbm(p, 25), noise::fbm(p, 10));
        const float r = 1.0f - std::abs(noise::simplex(p));
        EXPECT_FLOAT_EQ(noise::ridgedFbm(p, 1), r * r);
    }
}

TEST(NoiseFbm, StaysInRangeAndAddsDetail) {
    float fbmLo = 0.0f, fbmHi = 0.0f, ridgedLo = 1.0f, ridgedHi = 0.0f;
    double detail = 0.0;
    const auto points = randomPoints(20000, 50.0f, 6);
    for (const glm::vec3& p : points) {
        const float f = noise::fbm(p, 8);
        const float r = noise::ridgedFbm(p, 8);
        fbmLo = std::min(fbmLo, f);
        fbmHi = std::max(fbmHi, f);
        ridgedLo = std::min(ridgedLo, r);
        ridgedHi = std::max(ridgedHi, r);
        detail += std::abs(f - noise::simplex(p) / 1.99609375f);  // 8 octaves: sum of 0.5^k
    }
    EXPECT_GE(fbmLo, -1.0f);
    EXPECT_LE(fbmHi, 1.0f);
    EXPECT_LT(fbmLo, -0.4f);
    EXPECT_GT(fbmHi, 0.4f);
    EXPECT_GE(ridgedLo, 0.0f);
    EXPECT_LE(ridgedHi, 1.0f);
    EXPECT_GT(ridgedHi, 0.8f);
    EXPECT_GT(detail / double(points.size()), 0.05);  // the higher octaves contribute
}

TEST(NoiseFbm, AnalyticGradientMatchesCentralDifferences) {
    // Octave k is noise(2^k p): its third derivative grows as 8^k, so the steps are smaller
    // than for simplex alone and the tolerance wider. Measured max 3e-3.
    const float h = 5.0e-4f;
    float worst = 0.0f;
    for (const glm::vec3& p : randomPoints(5000, 1.0f, 7)) {
        glm::vec3 g;
        noise::fbmGrad(p, 5, 2.0f, 0.5f, g);
        const glm::vec3 fd = centralDifference([](glm::vec3 q) { return noise::fbm(q, 5, 2.0f, 0.5f); }, p, h);
        worst = std::max(worst, glm::length(g - fd));
    }
    std::printf("fbm gradient - central differences: max %.2e\n", worst);
    EXPECT_LT(worst, 6.0e-3f);
}

// ---------------------------------------------------------------- Worley

TEST(NoiseWorley, IsZeroAtFeaturePointsWhichLieInTheirCells) {
    for (int z = -3; z <= 3; ++z)
        for (int y = -3; y <= 3; ++y)
            for (int x = -3; x <= 3; ++x) {
                const glm::ivec3 cell(x, y, z);
                const glm::vec3 f = noise::worleyFeaturePoint(cell);
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(f, glm::vec3(cell))));
                EXPECT_TRUE(glm::all(glm::lessThan(f, glm::vec3(cell) + 1.0f)));
                EXPECT_LT(noise::worley(f), 1.0e-5f);
            }
}

TEST(NoiseWorley, MatchesABruteForceNearestFeatureSearch) {
    // The 5 x 5 x 5 cells around p hold the true nearest feature point (cells further
    // away are over 2 from p, the own cell's point within sqrt(3)). The 3 x 3 x 3 search
    // may miss it where a point two cells away is nearer; measured: never in 200 000 points.
    int missed = 0;
    float lo = 10.0f, hi = 0.0f;
    double sum = 0.0;
    const auto points = randomPoints(20000, 50.0f, 8);
    for (const glm::vec3& p : points) {
        const glm::ivec3 cell(glm::floor(p));
        float nearest = 1.0e9f;
        for (int z = -2; z <= 2; ++z)
            for (int y = -2; y <= 2; ++y)
                for (int x = -2; x <= 2; ++x)
                    nearest = std::min(nearest, glm::distance(noise::worleyFeaturePoint(cell + glm::ivec3(x, y, z)), p));
        const float f1 = noise::worley(p);
        EXPECT_GE(f1, nearest - 1.0e-4f) << "nearer than any feature point";
        if (f1 > nearest + 1.0e-4f) ++missed;
        lo = std::min(lo, f1);
        hi = std::max(hi, f1);
        sum += f1;
    }
    EXPECT_LE(missed, 2);
    EXPECT_GE(lo, 0.0f);
    EXPECT_LT(hi, std::sqrt(3.0f));
    const double mean = sum / double(points.size());  // one uniform point per cell: measured 0.52
    EXPECT_GT(mean, 0.4);
    EXPECT_LT(mean, 0.7);
}

TEST(NoiseWorley, IsOneLipschitz) {
    // F1 is a distance, so it changes by at most the step length.
    std::mt19937 rng(9);
    const float step = 1.0e-2f;
    float worst = 0.0f;
    for (const glm::vec3& p : randomPoints(50000, 20.0f, 10))
        worst = std::max(worst, std::abs(noise::worley(p + step * randomDirection(rng)) - noise::worley(p)));
    EXPECT_LE(worst, step * 1.001f + 1.0e-5f);
}

TEST(NoiseWorley, TiledVariantRepeatsWithItsPeriod) {
    for (float period : {1.0f, 4.0f, 7.0f, 32.0f}) {
        int differsFromUntiled = 0;
        for (const glm::vec3& p : randomPoints(2000, 3.0f * period, 11)) {
            const float w = noise::worley(p, period);
            for (int axis = 0; axis < 3; ++axis) {
                glm::vec3 e(0.0f);
                e[axis] = period;
                EXPECT_NEAR(noise::worley(p + e, period), w, 2.0e-5f) << "period " << period << " axis " << axis;
                EXPECT_NEAR(noise::worley(p - 2.0f * e, period), w, 2.0e-5f) << "period " << period << " axis " << axis;
            }
            if (std::abs(noise::worley(p) - w) > 1.0e-3f) ++differsFromUntiled;
        }
        EXPECT_GT(differsFromUntiled, 100) << "period " << period;
        const glm::ivec3 cell(-5, 2, 9);
        const glm::ivec3 shift(0, int(period), -2 * int(period));
        const glm::vec3 shifted = noise::worleyFeaturePoint(cell + shift, period) - glm::vec3(shift);
        EXPECT_LT(glm::distance(shifted, noise::worleyFeaturePoint(cell, period)), 1.0e-5f) << "period " << period;
    }
}

TEST(NoiseWorley, StreamsPlaceUnrelatedFeaturePointsAndStreamZeroIsThePlainHash) {
    int moved = 0;
    for (int i = 0; i < 200; ++i) {
        const glm::ivec3 cell(i % 7 - 3, i / 7 % 5, i / 35 - 2);
        EXPECT_EQ(noise::worleyFeaturePoint(cell, 8.0f, 0u), noise::worleyFeaturePoint(cell, 8.0f));
        const glm::vec3 a = noise::worleyFeaturePoint(cell, 8.0f, 1u), b = noise::worleyFeaturePoint(cell, 8.0f, 2u);
        EXPECT_EQ(glm::floor(a), glm::vec3(cell));
        if (glm::distance(a, noise::worleyFeaturePoint(cell, 8.0f)) > 0.05f && glm::distance(a, b) > 0.05f) ++moved;
    }
    EXPECT_GT(moved, 180);
}

// ---------------------------------------------------------------- tiled Perlin

namespace {

// Random points on the 1/64 grid in [-extent, extent]^3: p + period e is then exact in float.
std::vector<glm::vec3> gridPoints(int count, float extent, unsigned seed) {
    std::vector<glm::vec3> points = randomPoints(count, extent, seed);
    for (glm::vec3& p : points) p = glm::floor(p * 64.0f) / 64.0f;
    return points;
}

}  // namespace

TEST(NoisePerlin, TilesExactlyWithItsPeriod) {
    for (float period : {1.0f, 3.0f, 4.0f, 16.0f}) {
        int differsFromUntiled = 0;
        for (const glm::vec3& p : gridPoints(2000, 3.0f * period, 21)) {
            const float v = noise::perlinTiled(p, period);
            const float f = noise::perlinFbmTiled(p, period, 4, 0.5f, 3u);
            for (int axis = 0; axis < 3; ++axis) {
                glm::vec3 e(0.0f);
                e[axis] = period;
                ASSERT_EQ(noise::perlinTiled(p + e, period), v) << "period " << period << " axis " << axis;
                ASSERT_EQ(noise::perlinTiled(p - 2.0f * e, period), v) << "period " << period << " axis " << axis;
                ASSERT_EQ(noise::perlinFbmTiled(p + e, period, 4, 0.5f, 3u), f) << "period " << period;
            }
            if (std::abs(noise::perlinTiled(p, 0.0f) - v) > 1.0e-3f) ++differsFromUntiled;
        }
        EXPECT_GT(differsFromUntiled, 100) << "period " << period;
    }
}

TEST(NoisePerlin, IsZeroAtLatticePointsAndOneOctaveFbmIsTheNoise) {
    for (int i = -20; i <= 20; ++i)
        for (float period : {0.0f, 5.0f}) {
            const glm::vec3 p(float(i), float(i * 7 % 11), float(-3 * i));
            EXPECT_EQ(noise::perlinTiled(p, period), 0.0f);
            EXPECT_EQ(noise::perlinTiled(p, period, 9u), 0.0f);
        }
    for (const glm::vec3& p : randomPoints(1000, 10.0f, 22)) {
        EXPECT_EQ(noise::perlinFbmTiled(p, 6.0f, 1, 0.5f, 4u), noise::perlinTiled(p, 6.0f, 4u));
        EXPECT_EQ(noise::perlinFbmTiled(p, 6.0f, 0, 0.5f), noise::perlinFbmTiled(p, 6.0f, 1, 0.5f));
    }
}

TEST(NoisePerlin, StaysInRangeReachesFarAndAveragesZero) {
    float lo = 0.0f, hi = 0.0f, fbmLo = 0.0f, fbmHi = 0.0f;
    double sum = 0.0, sum2 = 0.0;
    int streamDiffers = 0;
    const auto points = randomPoints(200000, 50.0f, 23);
    for (const glm::vec3& p : points) {
        const float v = noise::perlinTiled(p, 0.0f);
        const float f = noise::perlinFbmTiled(p, 32.0f, 5, 0.5f);
        ASSERT_TRUE(std::isfinite(v) && std::isfinite(f));
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        fbmLo = std::min(fbmLo, f);
        fbmHi = std::max(fbmHi, f);
        sum += v;
        sum2 += double(v) * v;
        if (std::abs(noise::perlinTiled(p, 0.0f, 1u) - v) > 0.05f) ++streamDiffers;
    }
    const double mean = sum / double(points.size());
    const double sd = std::sqrt(sum2 / double(points.size()) - mean * mean);
    std::printf("perlin: [%.3f, %.3f], sd %.3f; fbm 5 octaves [%.3f, %.3f]\n", lo, hi, sd, fbmLo, fbmHi);
    EXPECT_LE(hi, 1.0f);
    EXPECT_GE(lo, -1.0f);
    EXPECT_GT(hi, 0.7f);
    EXPECT_LT(lo, -0.7f);
    EXPECT_LE(fbmHi, 1.0f);
    EXPECT_GE(fbmLo, -1.0f);
    EXPECT_NEAR(mean, 0.0, 0.01);
    EXPECT_GT(sd, 0.1);
    EXPECT_LT(sd, 0.5);
    EXPECT_GT(streamDiffers, int(points.size()) / 2);
}

TEST(NoisePerlin, SmallStepsGiveSmallChangesAcrossCellFaces) {
    // Lipschitz in the cell and across its faces: a corner hashed differently by the two
    // cells that share it, or a wrap that picks another corner, jumps by O(0.1). Steps of
    // 1e-3 from random points, and pairs straddling a cell face (and the period's) by 1e-4.
    std::mt19937 rng(24);
    const float step = 1.0e-3f;
    float worst = 0.0f;
    for (const glm::vec3& p : randomPoints(100000, 20.0f, 25))
        worst = std::max(worst, std::abs(noise::perlinTiled(p + step * randomDirection(rng), 8.0f) -
                                         noise::perlinTiled(p, 8.0f)));
    EXPECT_LT(worst, 4.0f * step);  // the gradient is below 4 (measured max change / step: printed)
    float worstFace = 0.0f;
    for (const glm::vec3& q : randomPoints(20000, 20.0f, 26)) {
        for (int axis = 0; axis < 3; ++axis) {
            glm::vec3 a = q, b = q;
            a[axis] = std::round(q[axis]) - 1.0e-4f;  // integer faces include multiples of the period 8
            b[axis] = std::round(q[axis]) + 1.0e-4f;
            worstFace = std::max(worstFace, std::abs(noise::perlinTiled(a, 8.0f) - noise::perlinTiled(b, 8.0f)));
            worstFace = std::max(worstFace, std::abs(noise::perlinFbmTiled(a, 8.0f, 4, 0.5f) -
                                                     noise::perlinFbmTiled(b, 8.0f, 4, 0.5f)));
        }
    }
    std::printf("perlin: max change %.2e over steps of %.0e, %.2e across cell faces\n", worst, step, worstFace);
    EXPECT_LT(worstFace, 4.0e-3f);
}

// ---------------------------------------------------------------- GPU vs CPU

namespace {

struct ProbeSettings {
    int octaves = 5;
    float lacunarity = 2.0f;
    float gain = 0.5f;
    float period = 8.0f;
};

// Runs shaders/noise/noise_probe.comp at the points; 4 vec4 per point (layout in the shader).
std::vector<glm::vec4> runProbe(const std::vector<glm::vec3>& points, const ProbeSettings& s) {
    const gl::Program program = gl::buildProgram(
        {std::filesystem::path(PLANET_SOURCE_DIR) / "shaders", gl::shaderPreamble()}, {"noise_probe", {"noise/noise_probe.comp"}});
    std::vector<glm::vec4> input;
    for (const glm::vec3& p : points) input.emplace_back(p, 0.0f);
    const GLsizeiptr outputBytes = static_cast<GLsizeiptr>(points.size() * 4 * sizeof(glm::vec4));
    gl::Buffer inputBuffer, outputBuffer;
    glNamedBufferStorage(inputBuffer.id(), static_cast<GLsizeiptr>(input.size() * sizeof(glm::vec4)), input.data(), 0);
    glNamedBufferStorage(outputBuffer.id(), outputBytes, nullptr, 0);
    glUseProgram(program.id());
    glUniform1i(0, static_cast<GLint>(points.size()));
    glUniform1i(1, s.octaves);
    glUniform1f(2, s.lacunarity);
    glUniform1f(3, s.gain);
    glUniform1f(4, s.period);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, inputBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, outputBuffer.id());
    glDispatchCompute(static_cast<GLuint>((points.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> output(points.size() * 4);
    glGetNamedBufferSubData(outputBuffer.id(), 0, outputBytes, output.data());
    glUseProgram(0);
    return output;
}

struct Differences {
    float simplex = 0, gradient = 0, fbm = 0, fbmGradient = 0, ridged = 0, worley = 0, worleyTiled = 0;
    float perlinTiled = 0, perlinFbmTiled = 0, worleyStream = 0;
};

Differences compareWithCpu(const std::vector<glm::vec3>& points, const ProbeSettings& s) {
    const std::vector<glm::vec4> gpu = runProbe(points, s);
    Differences d;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::vec3 p = points[i];
        glm::vec3 g, fg;
        const float v = noise::simplexGrad(p, g);
        const float f = noise::fbmGrad(p, s.octaves, s.lacunarity, s.gain, fg);
        const glm::vec4 a = gpu[4 * i], b = gpu[4 * i + 1], c = gpu[4 * i + 2], e = gpu[4 * i + 3];
        d.simplex = std::max(d.simplex, std::abs(a.x - v));
        d.gradient = std::max(d.gradient, glm::length(glm::vec3(a.y, a.z, a.w) - g));
        d.fbm = std::max(d.fbm, std::abs(b.x - f));
        d.fbmGradient = std::max(d.fbmGradient, glm::length(glm::vec3(b.y, b.z, b.w) - fg));
        d.ridged = std::max(d.ridged, std::abs(c.x - noise::ridgedFbm(p, s.octaves, s.lacunarity, s.gain)));
        d.worley = std::max(d.worley, std::abs(c.y - noise::worley(p)));
        d.worleyTiled = std::max(d.worleyTiled, std::abs(c.z - noise::worley(p, s.period)));
        d.perlinTiled = std::max(d.perlinTiled, std::abs(c.w - noise::perlinTiled(p, s.period)));
        d.perlinFbmTiled =
            std::max(d.perlinFbmTiled, std::abs(e.x - noise::perlinFbmTiled(p, s.period, s.octaves, s.gain, 7u)));
        d.worleyStream = std::max(d.worleyStream, std::abs(e.y - noise::worley(p, s.period, 7u)));
    }
    std::printf("noise GPU - CPU max |difference| at %zu points: simplex %.2e, gradient %.2e, fbm %.2e, "
                "fbm gradient %.2e, ridged %.2e, worley %.2e, worley tiled %.2e, perlin tiled %.2e, perlin fbm tiled "
                "%.2e, worley stream 7 %.2e\n",
                points.size(), d.simplex, d.gradient, d.fbm, d.fbmGradient, d.ridged, d.worley, d.worleyTiled, d.perlinTiled,
                d.perlinFbmTiled, d.worleyStream);
    return d;
}

class NoiseGpu : public test::GLTest {};

}  // namespace

TEST_F(NoiseGpu, ProbeMatchesTheCpuAtRandomPoints) {
    // Points in [-100, 100]^3 (5 octaves reach |p| ~ 2800 in the last octave).
    const Differences d = compareWithCpu(randomPoints(4096, 100.0f, 12), ProbeSettings{});
    EXPECT_LT(d.simplex, 1.0e-4f);
    EXPECT_LT(d.gradient, 1.0e-3f);
    EXPECT_LT(d.fbm, 5.0e-4f);
    EXPECT_LT(d.fbmGradient, 1.0e-2f);
    EXPECT_LT(d.ridged, 5.0e-4f);
    EXPECT_LT(d.worley, 1.0e-4f);
    EXPECT_LT(d.worleyTiled, 1.0e-4f);
    EXPECT_LT(d.perlinTiled, 1.0e-4f);
    EXPECT_LT(d.perlinFbmTiled, 5.0e-4f);
    EXPECT_LT(d.worleyStream, 1.0e-4f);
}
