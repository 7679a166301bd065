#include "terrain/detail_texture.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <epoxy/gl.h>

namespace planet::terrain {
namespace glsl {
using glm::max;
using std::abs;
using std::exp;
#include "shaders/terrain/rough_cosine.glsl"
using vec3 = glm::vec3;
#include "shaders/terrain/detail_planes.glsl"
}  // namespace glsl

float expectedClampedCosine(float mu, float sigma) { return glsl::expectedClampedCosine(mu, sigma); }

DetailPlanes detailPlanes(glm::vec3 up) {
    const glsl::DetailPlanes p = glsl::detailPlanes(up);
    return {p.a0, p.b0, p.a1, p.b1, p.w0, p.w1};
}

namespace {

struct Wave {
    glm::vec2 k;  // integer wave vector, cycles per texture period
    float amplitude;
    float phase;
};

constexpr float kTwoPi = 6.28318530717958647692f;

// `count` waves with |k| in [minK, maxK], uniformly spread over log |k| and angle, amplitude
// |k|^-exponent, normalised so the field's standard deviation is 1 (sum of a^2 / 2 = 1).
std::vector<Wave> makeWaves(std::mt19937& random, int count, float minK, float maxK, float exponent) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Wave> waves;
    float power = 0.0f;
    while (static_cast<int>(waves.size()) < count) {
        const float magnitude = std::exp(std::log(minK) + unit(random) * std::log(maxK / minK));
        const float angle = kTwoPi * unit(random);
        const glm::vec2 k(std::round(magnitude * std::cos(angle)), std::round(magnitude * std::sin(angle)));
        if (k == glm::vec2(0.0f)) continue;
        const float amplitude = std::pow(glm::length(k), -exponent);
        waves.push_back({k, amplitude, kTwoPi * unit(random)});
        power += 0.5f * amplitude * amplitude;
    }
    for (Wave& w : waves) w.amplitude /= std::sqrt(power);
    return waves;
}

float heightOf(const std::vector<Wave>& waves, glm::vec2 uv, glm::vec2* gradient) {
    float h = 0.0f;
    glm::vec2 g(0.0f);
    for (const Wave& w : waves) {
        const float angle = kTwoPi * glm::dot(w.k, uv) + w.phase;
        h += w.amplitude * std::cos(angle);
        g -= (w.amplitude * kTwoPi * std::sin(angle)) * w.k;
    }
    if (gradient) *gradient = g;
    return h;
}

// The bake's waves, from the seed: the fine field (h) and the patches (w).
struct DetailWaves {
    std::vector<Wave> fine, patches;
};

DetailWaves detailWaves(int size, std::uint32_t seed) {
    std::mt19937 random(seed);
    DetailWaves w;
    // Up to a quarter of the texels' Nyquist frequency: the finest wave still spans 8 texels,
    // so bilinear filtering reproduces it.
    // No wave longer than a quarter of the period (|k| >= 4): integer wave vectors that short
    // have few directions, (1, 0), (1, 1) and their turns, and the strongest amplitudes, and
    // together they drew the tile's own lattice, a regular diamond pattern of the period's
    // size over the rock (4 m at 100 m) and a checker on the meadow. The next coarser scale,
    // 8 times the period, covers those wavelengths (its |k| up to 32, a quarter of this
    // period): the bands of the three scales meet without a gap. Likewise the patches from |k| 2.
    const float maxK = static_cast<float>(size) / 8.0f;
    w.fine = makeWaves(random, 96, std::min(4.0f, 0.5f * maxK), maxK, 1.0f);
    w.patches = makeWaves(random, 32, 2.0f, 8.0f, 1.5f);
    return w;
}

}  // namespace

DetailTexture bakeDetailTexture(int size, std::uint32_t seed) {
    if (size < 16 || (size & (size - 1)) != 0)
        throw std::invalid_argument("terrain detail texture: size must be a power of two >= 16");
    const DetailWaves waves = detailWaves(size, seed);
    DetailTexture t;
    t.size = size;
    t.texels.resize(static_cast<std::size_t>(size) * size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const glm::vec2 uv(static_cast<float>(x) / size, static_cast<float>(y) / size);
            glm::vec2 gradient;
            const float h = heightOf(waves.fine, uv, &gradient);
            const float patches = heightOf(waves.patches, uv, nullptr);
            t.texels[static_cast<std::size_t>(y) * size + x] = glm::vec4(gradient, h, patches);
        }
    // Waves that rounding gave the same wave vector interfere, so the sum of a^2 / 2 is only
    // nearly the variance: normalise by the texels' own spread.
    double fine = 0.0, patchPower = 0.0;
    for (const glm::vec4& texel : t.texels) fine += texel.z * texel.z, patchPower += texel.w * texel.w;
    t.fineScale = static_cast<float>(1.0 / std::sqrt(fine / t.texels.size()));
    const float patchScale = static_cast<float>(1.0 / std::sqrt(patchPower / t.texels.size()));
    for (glm::vec4& texel : t.texels) texel = glm::vec4(t.fineScale * glm::vec3(texel), patchScale * texel.w);
    // The mip levels' slopes, box-averaged 2x2 per level as glGenerateMipmap makes them.
    std::vector<glm::vec2> level(t.texels.size());
    for (std::size_t i = 0; i < t.texels.size(); ++i) level[i] = glm::vec2(t.texels[i]);
    double fullSquare = 0.0;
    for (const glm::vec2& s : level) fullSquare += glm::dot(s, s);
    fullSquare /= static_cast<double>(level.size());
    for (int n = size;; n /= 2) {
        double square = 0.0;
        for (const glm::vec2& s : level) square += glm::dot(s, s);
        t.lostSlopeVariance.push_back(static_cast<float>(fullSquare - square / static_cast<double>(level.size())));
        if (n == 1) break;
        std::vector<glm::vec2> next(static_cast<std::size_t>(n / 2) * (n / 2));
        for (int y = 0; y < n / 2; ++y)
            for (int x = 0; x < n / 2; ++x) {
                const auto at = [&](int dx, int dy) { return level[static_cast<std::size_t>(2 * y + dy) * n + 2 * x + dx]; };
                next[static_cast<std::size_t>(y) * (n / 2) + x] = 0.25f * (at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1));
            }
        level = std::move(next);
    }
    return t;
}

float detailHeightAt(const DetailTexture& texture, glm::vec2 uv) {
    // The seed is not stored: the default bake's (the only one the renderer makes).
    return texture.fineScale * heightOf(detailWaves(texture.size, 7).fine, uv, nullptr);
}

gl::Texture makeDetailGlTexture(const DetailTexture& texture) {
    gl::Texture t(GL_TEXTURE_2D);
    const int levels = static_cast<int>(std::log2(texture.size)) + 1;
    glTextureStorage2D(t.id(), levels, GL_RGBA16F, texture.size, texture.size);
    glTextureSubImage2D(t.id(), 0, 0, 0, texture.size, texture.size, GL_RGBA, GL_FLOAT, texture.texels.data());
    glGenerateTextureMipmap(t.id());
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    // Isotropic on purpose: terrain/ground_material.frag skips a scale once the footprint's larger side spans
    // its period, which is where isotropic filtering reaches the (zero-mean) coarsest mip, so
    // the skip is seamless; anisotropic filtering would still show detail there (and costs
    // llvmpipe minutes per frame at grazing angles).
    t.label("terrain detail");
    return t;
}

}  // namespace planet::terrain
