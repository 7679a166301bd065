// Weather map: where the clouds are and what kind they are, a cube map over directions from
// the planet's centre (no pole seam), baked from the shared simplex fBm, and its cache.
//
// The cloud volume (noise/cloud_volume.h) tiles every w across the planet (Michelic Eq. 12);
// alone it would cover the globe with the same tile. This map modulates it on the planet's
// scale (Schneider 2015's weather texture, made spherical): per direction a coverage, so
// that from orbit clouds form fields, fronts and clear zones, and a cloud type.
//
// Layout: noise/continents.h's cube map (CubeMapOf: faces in OpenGL's order and orientation,
// texel (x, y) of face f at texels[(f * size + y) * size + x]) with two channels a texel, so
// that the continents' seamless bilinear filtering serves as the CPU sampler; a texel is
//   x  coverage in [0, 1]: the share of the volume's clouds kept there (0 clear, 1 overcast);
//   y  cloud type in [0, 1]:
//        0    stratus: a low, flat, even layer;
//        0.5  cumulus: heaped clouds in the lower part of the layer;
//        1    high thin cloud (altostratus / cirrostratus-like): a thin sheet near the top;
//      values in between blend their neighbours (0.25 stratocumulus, 0.75 altocumulus).
//      A vertical profile a renderer can take from it, as fractions of the layer depth
//      (0 = bottom, 1 = top): the cloud occupies [b(t), c(t)] with b, c piecewise linear
//      through (t, b, c) = (0, 0, 0.25), (0.5, 0, 0.7), (1, 0.8, 1), faded like Eq. 13 inside.
//   z w  0 (unused).
// Values are rounded to half precision (the cache stores HALF), so a fresh bake and a cached
// one are the same floats. On the GPU: a samplerCube, two channels (e.g. GL_RG16F).
//
// Bake, at each texel's unit direction d (world frame: +Z through the north pole) with
// o = seedOffset(seed, 2):
//   q       = frequency (d.x, d.y, 2 d.z) + o: features twice as long east-west as
//             north-south, as weather systems are;
//   q'      = q + (fbm(q / 2 + a), fbm(q / 2 + b), fbm(q / 2 + c)) (3 octaves; fixed
//             offsets a, b, c): domain warping, which curls the fields into fronts;
//   raw     = fbm(q', octaves) + latitudeBands B(latitude), with the zonal pattern
//             B = 0.3 g(lat, 0, 8) - 0.45 g(|lat|, 25, 10) + 0.3 g(|lat|, 55, 15),
//             g(x, m, s) = exp(-((x - m) / s)^2), lat in degrees: cloudy along the equator
//             (the ITCZ), clear under the subtropical highs, cloudy along the mid-latitude
//             storm tracks;
//   coverage = clamp(0.5 + 2.5 (raw - s), 0, 1), s found by bisection so that the
//             solid-angle-weighted mean of the coverage over the sphere is the parameter
//             (0 and 1 give exactly 0 and 1 everywhere);
//   type    = clamp(0.5 + 0.8 fbm(1.5 frequency d + o', 4) - 0.35 smoothstep(0.7, 1, coverage)
//             + 0.4 g(|lat|, 50, 15) (1 - coverage), 0, 1), o' = o's components rotated:
//             patches of all three kinds; overcast areas lean to stratus, the thinly covered
//             mid-latitudes to high thin cloud.
//
// Cache: <root>/weather-<key>/weather_map.exr (HALF channels "coverage" and "type", width
// size, height 6 size, the faces stacked in face order) and key.txt, the rules of
// noise/cloud_volume.h's (cloud_cache) and noise/continents.h's entries.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "noise/continents.h"

namespace planet::noise {

// Bump when the bake (not the noise: that is fingerprinted) changes what it produces.
constexpr int kWeatherMapVersion = 1;

// The map on the CPU: coverage (x) and type (y) per texel.
using WeatherMap = CubeMapOf<glm::vec2>;

struct WeatherParams {
    int seed = 1;                 // any int; picks the noise domain (seedOffset stream 2)
    double coverage = 0.5;        // mean coverage over the sphere (by solid angle), [0, 1]
    double frequency = 2.0;       // noise cycles per planet radius of the largest features, (0, 100]
    int octaves = 6;              // fBm octaves of the coverage, [1, 10]
    double latitudeBands = 0.5;   // strength of the zonal pattern (ITCZ, subtropics, storm tracks), [0, 2]
    bool operator==(const WeatherParams&) const = default;
};

// Bakes the map (see the file header) on all cores. faceSize in [4, 4096]; throws
// std::invalid_argument for that or a parameter out of its range.
WeatherMap bakeWeatherMap(const WeatherParams& params, int faceSize, const BakeProgress& progress = {});

// Coverage (x) and type (y) at `direction` (need not be unit length, must not be zero), with
// the seamless bilinear filtering of a samplerCube (sampleContinents).
glm::vec2 sampleWeather(const WeatherMap& map, glm::dvec3 direction);

// The solid-angle-weighted mean coverage over the sphere.
double meanCoverageOf(const WeatherMap& map);

// 16 hex digits: FNV-1a of kWeatherMapVersion, a noise fingerprint, params and faceSize.
std::string weatherMapCacheKey(const WeatherParams& params, int faceSize);

// Writes weather_map.exr and key.txt into `dir` atomically. Throws FileError.
void saveWeatherMap(const WeatherMap& map, const WeatherParams& params, const std::filesystem::path& dir,
                    const std::string& key);

// The map stored in `dir` if key.txt names `expectedKey`, this version and faceSize, the
// EXR's checksum matches, OpenEXR reads it, its header key and size match, it has both HALF
// channels and every value is in [0, 1]; otherwise nullopt with the reason in *reason.
std::optional<WeatherMap> loadWeatherMap(const std::filesystem::path& dir, const std::string& expectedKey, int faceSize,
                                      std::string* reason = nullptr);

// The map at run time: from the cache under `root` (<root>/weather-<key>/, root normally
// defaultCloudCacheRoot()) when valid, else baked (progress on stderr after a second, and the
// time) and saved there; an unusable entry is reported and rebaked, an unwritable cache
// reported. Throws std::invalid_argument for parameters out of range.
// `progress`, when given, is told the bake's progress too.
WeatherMap loadOrBakeWeatherMap(const WeatherParams& params, int faceSize, const std::filesystem::path& root,
                             const BakeProgress& progress = {});

}  // namespace planet::noise
