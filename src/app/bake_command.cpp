// `planet bake`: the continents cube map (noise/continents.h) baked on the CPU into its
// cache, with the time taken and the sea fraction achieved, and optionally an
// equirectangular preview PNG. The parameters are the preset's [terrain] ones (what the
// terrain pass will look for), --size, --seed and --sea-fraction overriding them. A valid
// cache entry is reused unless --force; a damaged one is reported and rebaked. Progress
// goes to stderr once the bake has run a second.
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
#include "noise/continents.h"
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

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f s", s);
    return text;
}

}  // namespace

int runBake(const BakeOptions& options) {
    if (options.size && (*options.size < 16 || *options.size > 2048))
        throw std::invalid_argument("--size " + std::to_string(*options.size) + " is outside [16, 2048]");
    if (options.seaFraction && !(*options.seaFraction >= 0.0 && *options.seaFraction <= 1.0))
        throw std::invalid_argument("--sea-fraction " + std::to_string(*options.seaFraction) + " is outside [0, 1]");
    if (!options.preview.empty()) checkOutputsWritable({options.preview});

    // The preset's [terrain] parameters, as the terrain pass will ask for them.
    const DataPaths paths = findDataPaths(options.root);
    const PresetLoad preset = loadPreset(resolvePreset(options.preset, paths.assets()));
    for (const std::string& w : preset.warnings) logWarning(w);
    TerrainParams terrain = preset.scene.terrain;
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
    return 0;
}

}  // namespace planet
