// Weather map: bake, sample, cache. See weather_map.h for the layout, the mapping of the
// cloud type and the formulas.
//
// The bake in three passes: (1) the raw coverage signal and the type's noise at every texel,
// rows spread over all cores; (2) the coverage shift s by bisection on the solid-angle-weighted
// mean (the mean of clamp(0.5 + k (raw - s), 0, 1) falls continuously and monotonically with
// s); (3) coverage and type from them, rounded to half.
#include "noise/weather_map.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/glm.hpp>

#include "noise/cloud_volume.h"  // cloud_bake
#include "noise/noise.h"
#include "util/cache_entry.h"
#include "util/file_util.h"

namespace planet::noise {

namespace fs = std::filesystem;

namespace {

void validate(const WeatherParams& p, int faceSize) {
    if (faceSize < 4 || faceSize > 4096)
        throw std::invalid_argument("weather map: face size " + std::to_string(faceSize) + " is outside [4, 4096]");
    if (!(p.coverage >= 0.0 && p.coverage <= 1.0))
        throw std::invalid_argument("weather map: coverage " + std::to_string(p.coverage) + " is outside [0, 1]");
    if (!(p.frequency > 0.0 && p.frequency <= 100.0))
        throw std::invalid_argument("weather map: frequency " + std::to_string(p.frequency) + " is outside (0, 100]");
    if (p.octaves < 1 || p.octaves > 10)
        throw std::invalid_argument("weather map: octaves " + std::to_string(p.octaves) + " is outside [1, 10]");
    if (!(p.latitudeBands >= 0.0 && p.latitudeBands <= 2.0))
        throw std::invalid_argument("weather map: latitude bands " + std::to_string(p.latitudeBands) +
                                    " is outside [0, 2]");
}

constexpr float kContrast = 2.5f;  // k of coverage = clamp(0.5 + k (raw - s), 0, 1)

float gauss(float x, float mean, float width) {
    const float t = (x - mean) / width;
    return std::exp(-t * t);
}

// The zonal pattern B(latitude in degrees) of weather_map.h.
float latitudeBand(float latitudeDeg) {
    const float a = std::abs(latitudeDeg);
    return 0.3f * gauss(latitudeDeg, 0.0f, 8.0f) - 0.45f * gauss(a, 25.0f, 10.0f) + 0.3f * gauss(a, 55.0f, 15.0f);
}

float coverageFrom(float raw, float shift) { return std::clamp(0.5f + kContrast * (raw - shift), 0.0f, 1.0f); }

float latitudeDegOf(glm::dvec3 d) { return static_cast<float>(glm::degrees(std::asin(std::clamp(d.z, -1.0, 1.0)))); }

}  // namespace

WeatherMap bakeWeatherMap(const WeatherParams& params, int faceSize, const BakeProgress& progress) {
    validate(params, faceSize);
    WeatherMap map;
    map.size = faceSize;
    map.texels.resize(6 * static_cast<std::size_t>(faceSize) * static_cast<std::size_t>(faceSize));

    // (1) Raw coverage signal (x) and the type's noise (y), per face row.
    const glm::vec3 offset = seedOffset(params.seed, 2);
    const glm::vec3 typeOffset(offset.y, offset.z, offset.x);
    const float frequency = static_cast<float>(params.frequency), bands = static_cast<float>(params.latitudeBands);
    const glm::vec3 warpA(17.25f, -3.5f, 8.75f), warpB(-9.5f, 21.0f, 4.25f), warpC(5.75f, 11.5f, -19.0f);
    cloud_bake::parallelFor(
        6 * faceSize,
        [&](int row) {
            const int face = row / faceSize, y = row % faceSize;
            for (int x = 0; x < faceSize; ++x) {
                const glm::dvec3 d = cubeTexelDirection(face, x, y, faceSize);
                const glm::vec3 q = frequency * glm::vec3(d.x, d.y, 2.0 * d.z) + offset;
                const glm::vec3 warp(fbm(0.5f * q + warpA, 3), fbm(0.5f * q + warpB, 3), fbm(0.5f * q + warpC, 3));
                const float raw = fbm(q + 1.0f * warp, params.octaves) + bands * latitudeBand(latitudeDegOf(d));
                const float typeNoise = fbm(1.5f * frequency * glm::vec3(d) + typeOffset, 4);
                map.at(face, x, y) = glm::vec2(raw, typeNoise);
            }
        },
        progress, 0.0, 0.9);

    // (2) The shift s that gives the mean coverage, by bisection (weights: texel solid angles).
    std::vector<double> weight(static_cast<std::size_t>(faceSize) * static_cast<std::size_t>(faceSize));
    for (int y = 0; y < faceSize; ++y)
        for (int x = 0; x < faceSize; ++x)
            weight[static_cast<std::size_t>(y * faceSize + x)] = cubeTexelSolidAngle(x, y, faceSize);
    auto meanFor = [&](float shift) {
        double sum = 0.0, total = 0.0;
        for (int f = 0; f < 6; ++f)
            for (int y = 0; y < faceSize; ++y)
                for (int x = 0; x < faceSize; ++x) {
                    const double w = weight[static_cast<std::size_t>(y * faceSize + x)];
                    sum += w * coverageFrom(map.at(f, x, y).x, shift);
                    total += w;
                }
        return sum / total;
    };
    const auto [lowest, highest] = std::minmax_element(map.texels.begin(), map.texels.end(),
                                                       [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x; });
    // At lo every texel is 1 (0.5 + k (raw - lo) >= 1), at hi every texel 0.
    float lo = lowest->x - 1.0f / kContrast, hi = highest->x + 1.0f / kContrast;
    if (params.coverage <= 0.0) lo = hi;
    else if (params.coverage >= 1.0) hi = lo;
    for (int i = 0; i < 40 && hi - lo > 1.0e-7f * (1.0f + std::abs(lo)); ++i) {
        const float mid = 0.5f * (lo + hi);
        (meanFor(mid) > params.coverage ? lo : hi) = mid;
    }
    const float shift = 0.5f * (lo + hi);
    if (progress) progress(0.97);

    // (3) Coverage and type, in half precision.
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < faceSize; ++y)
            for (int x = 0; x < faceSize; ++x) {
                glm::vec2& t = map.at(f, x, y);
                const float coverage = coverageFrom(t.x, shift);
                const float lat = std::abs(latitudeDegOf(cubeTexelDirection(f, x, y, faceSize)));
                const float type = std::clamp(0.5f + 0.8f * t.y - 0.35f * glm::smoothstep(0.7f, 1.0f, coverage) +
                                                  0.4f * gauss(lat, 50.0f, 15.0f) * (1.0f - coverage),
                                              0.0f, 1.0f);
                t = glm::vec2(static_cast<float>(Imath::half(coverage)), static_cast<float>(Imath::half(type)));
            }
    if (progress) progress(1.0);
    return map;
}

glm::vec2 sampleWeather(const WeatherMap& map, glm::dvec3 direction) { return sampleCubeMap(map, direction); }

double meanCoverageOf(const WeatherMap& map) {
    double sum = 0.0, total = 0.0;
    for (int y = 0; y < map.size; ++y)
        for (int x = 0; x < map.size; ++x) {
            const double w = cubeTexelSolidAngle(x, y, map.size);
            for (int f = 0; f < 6; ++f) {
                sum += w * map.at(f, x, y).x;
                total += w;
            }
        }
    return total > 0.0 ? sum / total : 0.0;
}

// ------------------------------------------------------------------ cache

namespace {

const CacheFormat kWeatherFormat{"weather map", "planet clouds' weather map; see noise/weather_map.h",
                                 "planetWeatherMapKey", CachePixel::Half, false};
constexpr const char* kWeatherFile = "weather_map.exr";

CacheFields checkedFields(int faceSize) {
    return {{"version", std::to_string(kWeatherMapVersion)}, {"size", std::to_string(faceSize)}};
}

// One image, the faces stacked, with two channels over the texels' x and y.
std::vector<CacheImage> weatherImages(WeatherMap& map) {
    float* base = &map.texels.front().x;
    return {{kWeatherFile, map.size, 6 * map.size, {{"coverage", base, sizeof(glm::vec2)}, {"type", base + 1, sizeof(glm::vec2)}}}};
}

}  // namespace

std::string weatherMapCacheKey(const WeatherParams& p, int faceSize) {
    Fnv1a h;
    h.integer(kWeatherMapVersion);
    // Fingerprint of the noise code (simplex fBm and the seed's offset).
    for (const glm::vec3 q : {glm::vec3(1.25f, -3.5f, 7.75f), glm::vec3(-41.3f, 17.9f, 0.37f)}) h.number(fbm(q, 10));
    for (int c = 0; c < 3; ++c) h.number(seedOffset(p.seed, 2)[c]);
    h.integer(p.seed);
    h.number(p.coverage);
    h.number(p.frequency);
    h.integer(p.octaves);
    h.number(p.latitudeBands);
    h.integer(faceSize);
    return hex16(h.value());
}

void saveWeatherMap(const WeatherMap& map, const WeatherParams& p, const fs::path& dir, const std::string& key) {
    if (map.size < 1 || map.texels.size() != 6 * static_cast<std::size_t>(map.size) * static_cast<std::size_t>(map.size))
        throw FileError("saveWeatherMap: the map's texels do not match its size");
    CacheFields fields = checkedFields(map.size);
    fields.insert(fields.end(), {{"seed", std::to_string(p.seed)},
                                 {"coverage", exactText(p.coverage)},
                                 {"frequency", exactText(p.frequency)},
                                 {"octaves", std::to_string(p.octaves)},
                                 {"latitude_bands", exactText(p.latitudeBands)}});
    writeCacheEntry(dir, kWeatherFormat, key, fields, weatherImages(const_cast<WeatherMap&>(map)));
}

std::optional<WeatherMap> loadWeatherMap(const fs::path& dir, const std::string& expectedKey, int faceSize,
                                      std::string* reason) {
    auto reject = [&](const std::string& why) -> std::optional<WeatherMap> {
        if (reason) *reason = why;
        return std::nullopt;
    };
    if (faceSize < 4 || faceSize > 4096) return reject("face size " + std::to_string(faceSize) + " is outside [4, 4096]");
    WeatherMap map;
    map.size = faceSize;
    map.texels.assign(6 * static_cast<std::size_t>(faceSize) * static_cast<std::size_t>(faceSize), glm::vec2(0.0f));
    if (!readCacheEntry(dir, kWeatherFormat, expectedKey, checkedFields(faceSize), weatherImages(map), reason))
        return std::nullopt;
    for (std::size_t i = 0; i < map.texels.size(); ++i) {
        const glm::vec2 t = map.texels[i];
        if (!(t.x >= 0.0f && t.x <= 1.0f && t.y >= 0.0f && t.y <= 1.0f))
            return reject(quote(dir / kWeatherFile) + ": texel " + std::to_string(i) + " has coverage " + std::to_string(t.x) + " and type " +
                          std::to_string(t.y) + ", not both in [0, 1]");
    }
    return map;
}

WeatherMap loadOrBakeWeatherMap(const WeatherParams& params, int faceSize, const fs::path& root, const BakeProgress& progress) {
    validate(params, faceSize);
    const std::string key = weatherMapCacheKey(params, faceSize);
    const fs::path dir = root / ("weather-" + key);
    return loadOrBakeLogged(
        "weather map", std::to_string(faceSize) + "^2 x 6 texels, seed " + std::to_string(params.seed), dir,
        [&](std::string* reason) { return loadWeatherMap(dir, key, faceSize, reason); },
        [&] { return bakeWeatherMap(params, faceSize, alsoLogged(progress)); },
        [&](const WeatherMap& map) { saveWeatherMap(map, params, dir, key); });
}

}  // namespace planet::noise
