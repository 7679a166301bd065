#include "terrain/continent_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

namespace planet::terrain {

namespace {

// A point of face `face`'s plane (s, t in [0, 1] on the face, beyond it past its edges) as a
// direction: GL's face orientation (noise/continents.h), the plane extended.
glm::dvec3 facePlaneDirection(int face, double s, double t) {
    const double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
    switch (face) {
        case 0: return {1.0, -tc, -sc};
        case 1: return {-1.0, -tc, sc};
        case 2: return {sc, 1.0, tc};
        case 3: return {sc, -1.0, -tc};
        case 4: return {sc, -tc, 1.0};
        default: return {-sc, -tc, -1.0};
    }
}

// The largest texel among the 4 x 4 taps around the place `direction` selects on its face, as the
// seamless filter reads them (noise::seamlessTap: past the face's edge, the neighbour's texels):
// every value the bilinear filter takes within half a texel of it. (Taps beyond a corner, which the
// filter makes the mean of the other three, are bounded by those.)
template <class Texel>
float texelsAround(const noise::CubeMapOf<Texel>& map, glm::dvec3 direction) {
    double s, t;
    const int face = noise::cubeFaceOf(direction, s, t);
    const int n = map.size;
    const int x0 = static_cast<int>(std::floor(s * n - 0.5)), y0 = static_cast<int>(std::floor(t * n - 0.5));
    float highest = -std::numeric_limits<float>::infinity();
    for (int j = y0 - 1; j <= y0 + 2; ++j)
        for (int i = x0 - 1; i <= x0 + 2; ++i) {
            int tapFace = 0, x = 0, y = 0;
            if (noise::seamlessTap(n, face, std::clamp(i, -1, n), std::clamp(j, -1, n), tapFace, x, y))
                highest = std::max(highest, map.elevation(tapFace, x, y));
        }
    return highest;
}

int levelCount(int size, int maxLevels) {
    int levels = 1;
    while (levels < maxLevels && (1 << levels) <= size) ++levels;
    return levels;
}

// One face's levels: the places of level 0's grid on the face's plane, `border` texels past
// each edge, each the largest texel around it; their maxima over aligned blocks of 2^k; then each
// level-k texel the largest block of the 3 x 3 around it.
template <class Texel>
void buildFace(const noise::CubeMapOf<Texel>& map, int face, int levels, ContinentMaxPyramid& pyramid) {
    const int n = map.size;
    const int border = 1 << (levels - 1);
    int side = n + 2 * border;
    std::vector<float> blocks(static_cast<std::size_t>(side) * side);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            blocks[static_cast<std::size_t>(y) * side + x] =
                texelsAround(map, facePlaneDirection(face, (x - border + 0.5) / n, (y - border + 0.5) / n));
    for (int k = 0; k < levels; ++k) {
        if (k > 0) {  // blocks of 2^k from those of 2^(k-1) (the border is a whole number of them)
            const int half = side / 2;
            std::vector<float> coarser(static_cast<std::size_t>(half) * half);
            for (int y = 0; y < half; ++y)
                for (int x = 0; x < half; ++x) {
                    const float* row0 = &blocks[static_cast<std::size_t>(2 * y) * side + 2 * x];
                    const float* row1 = row0 + side;
                    coarser[static_cast<std::size_t>(y) * half + x] =
                        std::max(std::max(row0[0], row0[1]), std::max(row1[0], row1[1]));
                }
            blocks.swap(coarser);
            side = half;
        }
        const int m = n >> k;
        const int offset = border >> k;  // the face's first block
        std::vector<float>& level = pyramid.levels[static_cast<std::size_t>(k)];
        for (int y = 0; y < m; ++y)
            for (int x = 0; x < m; ++x) {
                float highest = -std::numeric_limits<float>::infinity();
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        highest = std::max(highest,
                                           blocks[static_cast<std::size_t>(y + offset + dy) * side + x + offset + dx]);
                level[(static_cast<std::size_t>(face) * m + y) * m + x] = highest;
            }
    }
}

}  // namespace

template <class Texel>
ContinentMaxPyramid buildContinentMaxPyramid(const noise::CubeMapOf<Texel>& map, int maxLevels) {
    ContinentMaxPyramid pyramid;
    pyramid.size = map.size;
    if (map.size < 1) return pyramid;
    const int levels = levelCount(map.size, std::max(maxLevels, 1));
    for (int k = 0; k < levels; ++k) {
        const std::size_t m = static_cast<std::size_t>(map.size >> k);
        pyramid.levels.emplace_back(6 * m * m);
    }
    std::vector<std::thread> pool;
    for (int face = 1; face < 6; ++face) pool.emplace_back([&, face] { buildFace(map, face, levels, pyramid); });
    buildFace(map, 0, levels, pyramid);
    for (std::thread& t : pool) t.join();
    return pyramid;
}

template ContinentMaxPyramid buildContinentMaxPyramid(const noise::CubeMapOf<glm::vec4>&, int);
template ContinentMaxPyramid buildContinentMaxPyramid(const noise::CubeMapOf<glm::vec2>&, int);

double continentCapStretch(double radiusRad) {
    constexpr double kCornerRad = 0.9553166181245093;  // acos(1 / sqrt(3)): a face's corner from its axis
    const double c = std::cos(kCornerRad + radiusRad);
    return 1.0 / (c * c);
}

int continentMaxLevel(int size, int levels, double radiusRad) {
    if (!(radiusRad >= 0.0) || radiusRad > kContinentMaxRadiusRad) return -1;
    const double texels = 0.5 * size * continentCapStretch(radiusRad) * radiusRad;
    int k = 0;
    while (k < levels && double(1 << k) < texels) ++k;
    return k < levels ? k : -1;
}

float continentMaxWithin(const ContinentMaxPyramid& pyramid, glm::dvec3 centre, double radiusRad) {
    const int k = continentMaxLevel(pyramid.size, static_cast<int>(pyramid.levels.size()), radiusRad);
    if (k < 0) return std::numeric_limits<float>::infinity();
    double s, t;
    const int face = noise::cubeFaceOf(centre, s, t);
    const int m = pyramid.size >> k;
    const int x = std::clamp(static_cast<int>(std::floor(s * m)), 0, m - 1);
    const int y = std::clamp(static_cast<int>(std::floor(t * m)), 0, m - 1);
    return pyramid.levels[static_cast<std::size_t>(k)][(static_cast<std::size_t>(face) * m + y) * m + x];
}

gl::Texture makeContinentMaxTexture(const ContinentMaxPyramid& pyramid) {
    const int levels = static_cast<int>(pyramid.levels.size());
    gl::Texture texture(GL_TEXTURE_CUBE_MAP);
    glTextureStorage2D(texture.id(), std::max(levels, 1), GL_R32F, std::max(pyramid.size, 1), std::max(pyramid.size, 1));
    for (int k = 0; k < levels; ++k) {
        const int m = pyramid.size >> k;
        for (int face = 0; face < 6; ++face)
            glTextureSubImage3D(texture.id(), k, 0, 0, face, m, m, 1, GL_RED, GL_FLOAT,
                                &pyramid.levels[static_cast<std::size_t>(k)][static_cast<std::size_t>(face) * m * m]);
    }
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAX_LEVEL, std::max(levels - 1, 0));
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(texture.id(), wrap, GL_CLAMP_TO_EDGE);
    texture.label("continent maxima " + std::to_string(pyramid.size) + "^2 x 6, " + std::to_string(levels) + " levels");
    return texture;
}

}  // namespace planet::terrain
