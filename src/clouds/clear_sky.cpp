#include "clouds/clear_sky.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "terrain/continent_bound.h"

namespace planet::clouds {

double clearCapRadius(int size, int level, double axisAngle) {
    const double texels = std::ldexp(1.0, level);
    double lo = 0.0, hi = 0.5 * M_PI - axisAngle;
    for (int i = 0; i < 60; ++i) {  // (size / 2) r / cos^2(a + r) grows with r
        const double r = 0.5 * (lo + hi), c = std::cos(axisAngle + r);
        (0.5 * size * r <= texels * c * c ? lo : hi) = r;
    }
    return lo;
}

namespace {

// The weather's coverage on a grid `factor` times coarser: each texel the largest of the fine texels
// it covers.
noise::WeatherMap coarseMaxima(const noise::WeatherMap& weather, int factor) {
    noise::WeatherMap coarse;
    coarse.size = weather.size / factor;
    coarse.texels.assign(6 * static_cast<std::size_t>(coarse.size) * coarse.size, glm::vec2(0.0f));
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < weather.size; ++y)
            for (int x = 0; x < weather.size; ++x) {
                glm::vec2& c = coarse.at(face, x / factor, y / factor);
                c.x = std::max(c.x, weather.elevation(face, x, y));
            }
    return coarse;
}

}  // namespace

ClearSkyMap buildClearSkyMap(const noise::WeatherMap& weather, int maxSize) {
    ClearSkyMap map;
    if (weather.size < 1) return map;
    int factor = 1;
    while (weather.size / factor > maxSize && weather.size % (2 * factor) == 0) factor *= 2;
    const noise::WeatherMap coarse = factor > 1 ? coarseMaxima(weather, factor) : weather;
    const terrain::ContinentMaxPyramid pyramid = terrain::buildContinentMaxPyramid(coarse, kClearSkyLevels);
    const int m = map.size = coarse.size, levels = static_cast<int>(pyramid.levels.size());
    map.radians.assign(6 * static_cast<std::size_t>(m) * m, 0.0f);
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < m; ++y)
            for (int x = 0; x < m; ++x) {
                // The texel's farthest point from its face's axis (a corner): where the stretch is largest.
                const double s = std::max(std::abs(2.0 * x / m - 1.0), std::abs(2.0 * (x + 1) / m - 1.0));
                const double t = std::max(std::abs(2.0 * y / m - 1.0), std::abs(2.0 * (y + 1) / m - 1.0));
                const double axisAngle = std::atan(std::sqrt(s * s + t * t));
                for (int k = levels - 1; k >= 0; --k) {  // the coarsest level that says clear: the widest cap
                    const int mk = m >> k;
                    if ((x >> k) >= mk || (y >> k) >= mk) continue;
                    const float highest =
                        pyramid.levels[static_cast<std::size_t>(k)][(static_cast<std::size_t>(face) * mk + (y >> k)) * mk + (x >> k)];
                    if (highest > 0.0f) continue;
                    map.radians[(static_cast<std::size_t>(face) * m + y) * m + x] =
                        static_cast<float>(0.99 * clearCapRadius(m, k, axisAngle));
                    break;
                }
            }
    return map;
}

double clearSkyAngleAt(const ClearSkyMap& map, glm::dvec3 direction) {
    if (map.size < 1) return 0.0;
    double s, t;
    const int face = noise::cubeFaceOf(direction, s, t);
    const int m = map.size;
    const int x = std::clamp(static_cast<int>(std::floor(s * m)), 0, m - 1);
    const int y = std::clamp(static_cast<int>(std::floor(t * m)), 0, m - 1);
    return map.radians[(static_cast<std::size_t>(face) * m + y) * m + x];
}

double clearSkyChord(double angleRad) { return 2.0 * std::sin(0.5 * angleRad); }

gl::Texture makeClearSkyTexture(const ClearSkyMap& map) {
    const int m = std::max(map.size, 1);
    gl::Texture texture(GL_TEXTURE_CUBE_MAP);
    glTextureStorage2D(texture.id(), 1, GL_R32F, m, m);
    std::vector<float> chords(6 * static_cast<std::size_t>(m) * m, 0.0f);
    for (std::size_t i = 0; i < map.radians.size(); ++i) chords[i] = static_cast<float>(clearSkyChord(map.radians[i]));
    glTextureSubImage3D(texture.id(), 0, 0, 0, 0, m, m, 6, GL_RED, GL_FLOAT, chords.data());  // the faces in GL's order
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(texture.id(), wrap, GL_CLAMP_TO_EDGE);
    texture.label(map.size > 0 ? "clear sky " + std::to_string(m) + "^2 x 6" : std::string("clear sky (none)"));
    return texture;
}

}  // namespace planet::clouds
