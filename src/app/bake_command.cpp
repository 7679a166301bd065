// `planet bake`: the baked data a preset needs, on the CPU into their caches, with the
// time taken: the continents cube map (noise/continents.h; the sea fraction achieved, an
// optional equirectangular preview PNG) and, when the preset has clouds, the cloud density
// volume (noise/cloud_volume.h; its cloud, border and empty shares) and the weather map
// (noise/weather_map.h; optional preview). The parameters are the preset's (what the
// renderer will look for), --size, --seed and --sea-fraction overriding the continents'.
// --what picks one of them. A valid cache entry is reused unless --force; a damaged one is
// reported and rebaked. Progress goes to stderr once a bake has run a second.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/commands.h"
#include "app/session.h"
#include "clouds/cloud_resources.h"
#include "noise/cloud_volume.h"
#include "noise/continents.h"
#include "noise/weather_map.h"
#include "render/image_io.h"
#include "scene/preset.h"
#include "scene/scene.h"
#include "terrain/height.h"
#include "util/cache_entry.h"
#include "util/file_util.h"
#include "util/log.h"

namespace planet {

namespace fs = std::filesystem;

namespace {

constexpr int kPreviewWidth = 1024, kPreviewHeight = 512;

// Elevation in [-1, 1] to a map colour: sea from light to deep blue, land from green
// over brown to pale rock.
glm::dvec3 elevationColour(double e) {
    const glm::dvec3 shallow(70, 130, 200), deep(10, 30, 90);
    const glm::dvec3 lowland(60, 140, 60), hills(140, 110, 70), peaks(225, 215, 200);
    if (e < 0.0) return glm::mix(shallow, deep, std::min(1.0, -e));
    if (e < 0.5) return glm::mix(lowland, hills, e / 0.5);
    return glm::mix(hills, peaks, std::min(1.0, (e - 0.5) / 0.5));
}

// Equirectangular (longitude -180..180 left to right, latitude 90..-90 top to bottom),
// directions as directionFromLatLon (z north, longitude 0 on +x).
ImageRGBA8 previewImage(const noise::CubeMap& map) {
    ImageRGBA8 image;
    image.width = kPreviewWidth;
    image.height = kPreviewHeight;
    image.pixels.resize(static_cast<std::size_t>(kPreviewWidth) * kPreviewHeight * 4);
    for (int j = 0; j < kPreviewHeight; ++j) {
        const double lat = 90.0 - 180.0 * (j + 0.5) / kPreviewHeight;
        for (int i = 0; i < kPreviewWidth; ++i) {
            const double lon = -180.0 + 360.0 * (i + 0.5) / kPreviewWidth;
            const glm::dvec3 c = elevationColour(noise::sampleContinents(map, directionFromLatLon(lat, lon)).x);
            std::uint8_t* p = &image.pixels[(static_cast<std::size_t>(j) * kPreviewWidth + i) * 4];
            for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(std::clamp(std::lround(c[k]), 0L, 255L));
            p[3] = 255;
        }
    }
    return image;
}

// Equirectangular like previewImage: the weather map's coverage as brightness over a dark
// blue sea, tinted by the cloud type (stratus grey-blue, cumulus white, high cloud amber).
ImageRGBA8 weatherPreview(const noise::WeatherMap& map) {
    ImageRGBA8 image;
    image.width = kPreviewWidth;
    image.height = kPreviewHeight;
    image.pixels.resize(static_cast<std::size_t>(kPreviewWidth) * kPreviewHeight * 4);
    const glm::dvec3 clear(20, 40, 80), stratus(170, 180, 200), cumulus(250, 250, 250), high(240, 200, 140);
    for (int j = 0; j < kPreviewHeight; ++j) {
        const double lat = 90.0 - 180.0 * (j + 0.5) / kPreviewHeight;
        for (int i = 0; i < kPreviewWidth; ++i) {
            const double lon = -180.0 + 360.0 * (i + 0.5) / kPreviewWidth;
            const glm::vec2 w = noise::sampleWeather(map, directionFromLatLon(lat, lon));
            const glm::dvec3 cloud = w.y < 0.5 ? glm::mix(stratus, cumulus, w.y / 0.5) : glm::mix(cumulus, high, (w.y - 0.5) / 0.5);
            const glm::dvec3 c = glm::mix(clear, cloud, static_cast<double>(w.x));
            std::uint8_t* p = &image.pixels[(static_cast<std::size_t>(j) * kPreviewWidth + i) * 4];
            for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(std::clamp(std::lround(c[k]), 0L, 255L));
            p[3] = 255;
        }
    }
    return image;
}

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f s", s);
    return text;
}


// The continents, as the terrain pass will ask for them.
void bakeContinentsFor(const BakeOptions& options, const Scene& scene) {
    TerrainParams terrain = scene.terrain;
    if (options.size) terrain.continent_map_size = *options.size;
    if (options.seed) terrain.seed = *options.seed;
    if (options.seaFraction) terrain.sea_fraction = *options.seaFraction;
    const noise::ContinentParams params = terrain::continentParams(terrain);
    const int size = terrain.continent_map_size;

    const std::string key = noise::continentsCacheKey(params, size);
    const fs::path dir = (options.cache.empty() ? noise::defaultContinentsCacheRoot() : fs::path(options.cache)) / key;
    const std::string where = fs::absolute(dir).lexically_normal().string();
    std::cout << "planet bake: continents cube map for preset " << options.preset << ", 6 faces of " << size << "x"
              << size << ", seed " << params.seed << ", frequency " << params.frequency << ", " << params.octaves
              << " octaves, sea fraction " << params.seaFraction << "\n";

    auto report = [&](const CacheOutcome& o) {
        if (o.forced)
            std::cout << "--force: rebaking the map for key " << key << "\n";
        else if (!o.rejected.empty())
            std::cout << "cache at " << where << " is not usable, rebaking: " << o.rejected << "\n";
        else
            std::cout << "no cached map for key " << key << ", baking\n";
        std::cout.flush();
    };
    CacheOutcome outcome;
    const noise::CubeMap map = loadOrMake(
        dir, options.force, [&](std::string* reason) { return noise::loadContinents(dir, key, size, reason); },
        [&] { return noise::bakeContinents(params, size, noise::logBakeProgress()); },
        [&](const noise::CubeMap& baked) { noise::saveContinents(baked, params, dir, key); }, report, &outcome);
    if (outcome.hit) {
        std::cout << "cache hit: valid map in " << where << " (key " << key << ")\n";
    } else {
        std::cout << "baked in " << seconds(outcome.seconds) << " ("
                  << static_cast<double>(map.texels.size() * sizeof(glm::vec4)) / (1024.0 * 1024.0)
                  << " MiB as RGBA32F: elevation and its gradient)\n";
        if (!outcome.notSaved.empty()) throw FileError(outcome.notSaved);
        std::cout << "wrote " << where << "\n";
    }

    char fraction[96];
    std::snprintf(fraction, sizeof fraction, "sea fraction: %.5f achieved (by solid angle), %.5f requested\n",
                  noise::seaFractionOf(map), params.seaFraction);
    std::cout << fraction;

    if (!options.preview.empty()) {
        writePng(previewImage(map), options.preview);
        std::cout << "wrote preview " << fs::absolute(options.preview).lexically_normal().string() << " ("
                  << kPreviewWidth << "x" << kPreviewHeight << ", equirectangular)\n";
    }
}

// What a cache step says: hit, or why it baked, how long it took and where it wrote.
void reportCacheStep(const std::string& what, const fs::path& dir, const CacheOutcome& outcome) {
    const std::string where = fs::absolute(dir).lexically_normal().string();
    if (outcome.hit) {
        std::cout << "cache hit: valid " << what << " in " << where << "\n";
        return;
    }
    if (!outcome.rejected.empty()) std::cout << "the cached " << what << " was not usable: " << outcome.rejected << "\n";
    std::cout << what << " baked in " << seconds(outcome.seconds) << "\n";
    if (!outcome.notSaved.empty()) throw FileError(outcome.notSaved);
    std::cout << "wrote " << where << "\n";
}

// The cloud volume and the weather map, as the renderer's prepare step will ask for them.
void bakeCloudsFor(const BakeOptions& options, const Scene& scene) {
    const CloudParams& c = scene.clouds;
    if (!c.enabled || c.constant_density) {
        std::cout << "planet bake: preset " << options.preset << " draws no baked clouds (clouds.enabled false or "
                     "constant_density true): nothing to bake for them\n";
        return;
    }
    const fs::path root = options.cloudCache.empty() ? noise::defaultCloudCacheRoot() : fs::path(options.cloudCache);

    const noise::CloudVolumeParams v = clouds::volumeParamsOf(c);
    const std::string volumeKey = noise::cloudVolumeCacheKey(v);
    const fs::path volumeDir = root / ("volume-" + volumeKey);
    std::cout << "planet bake: cloud volume for preset " << options.preset << ", " << v.size << "^3 half floats, seed "
              << v.seed << ", shape " << v.shapeFrequency << " and detail " << v.detailFrequency
              << " cells per tile, erosion " << v.erosion << ", cloud fraction " << v.cloudFraction << ", border "
              << v.borderVoxels << " voxels\n";
    std::cout.flush();
    CacheOutcome outcome;
    const noise::CloudVolume volume = loadOrMake(
        volumeDir, options.force,
        [&](std::string* reason) { return noise::loadCloudVolume(volumeDir, volumeKey, v.size, reason); },
        [&] { return noise::bakeCloudVolume(v, noise::logBakeProgress()); },
        [&](const noise::CloudVolume& baked) { noise::saveCloudVolume(baked, v, volumeDir, volumeKey); }, {}, &outcome);
    reportCacheStep("cloud volume", volumeDir, outcome);
    char shares[160];
    std::snprintf(shares, sizeof shares,
                  "cloud volume: %.4f cloud, %.4f border (zero density), %.4f empty (large steps), mean density %.3f\n",
                  volume.stats.cloudFraction, volume.stats.borderFraction, volume.stats.emptyFraction,
                  volume.stats.meanDensity);
    std::cout << shares;

    const noise::WeatherParams w = clouds::weatherParamsOf(c);
    const int size = c.weather_map_size;
    const std::string weatherKey = noise::weatherMapCacheKey(w, size);
    const fs::path weatherDir = root / ("weather-" + weatherKey);
    std::cout << "planet bake: weather map, 6 faces of " << size << "x" << size << ", seed " << w.seed << ", frequency "
              << w.frequency << ", latitude bands " << w.latitudeBands << "\n";
    std::cout.flush();
    const noise::WeatherMap map = loadOrMake(
        weatherDir, options.force,
        [&](std::string* reason) { return noise::loadWeatherMap(weatherDir, weatherKey, size, reason); },
        [&] { return noise::bakeWeatherMap(w, size, noise::logBakeProgress()); },
        [&](const noise::WeatherMap& baked) { noise::saveWeatherMap(baked, w, weatherDir, weatherKey); }, {}, &outcome);
    reportCacheStep("weather map", weatherDir, outcome);
    char mean[96];
    std::snprintf(mean, sizeof mean, "weather map: mean coverage %.4f (by solid angle; the layer's coverage scales it)\n",
                  noise::meanCoverageOf(map));
    std::cout << mean;
    if (!options.weatherPreview.empty()) {
        writePng(weatherPreview(map), options.weatherPreview);
        std::cout << "wrote weather preview " << fs::absolute(options.weatherPreview).lexically_normal().string() << " ("
                  << kPreviewWidth << "x" << kPreviewHeight << ", equirectangular)\n";
    }
}

}  // namespace

int runBake(const BakeOptions& options) {
    if (options.size && (*options.size < 16 || *options.size > 2048))
        throw std::invalid_argument("--size " + std::to_string(*options.size) + " is outside [16, 2048]");
    if (options.seaFraction && !(*options.seaFraction >= 0.0 && *options.seaFraction <= 1.0))
        throw std::invalid_argument("--sea-fraction " + std::to_string(*options.seaFraction) + " is outside [0, 1]");
    if (options.what != "all" && options.what != "continents" && options.what != "clouds")
        throw std::invalid_argument("--what " + options.what + " is not all, continents or clouds");
    std::vector<std::string> outputs;
    for (const std::string& f : {options.preview, options.weatherPreview})
        if (!f.empty()) outputs.push_back(f);
    checkOutputsWritable(outputs);

    const DataPaths paths = findDataPaths(options.root);
    const PresetLoad preset = loadPreset(resolvePreset(options.preset, paths.assets()));
    for (const std::string& w : preset.warnings) logWarning(w);
    if (options.what != "clouds") bakeContinentsFor(options, preset.scene);
    if (options.what != "continents") bakeCloudsFor(options, preset.scene);
    return 0;
}

}  // namespace planet
