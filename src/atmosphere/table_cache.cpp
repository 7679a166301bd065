// The atmosphere table cache (see table_cache.h): the key, and the tables as the entry's
// images (util/cache_entry.h writes, checks and reads the entry).
#include "atmosphere/table_cache.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "util/cache_entry.h"
#include "util/file_util.h"

namespace planet::atmosphere {

namespace fs = std::filesystem;

namespace {

// The key hashes every parameter field by field (not the struct's bytes: padding).
void hashSpectrum(Fnv1a& h, const glm::dvec3& s) {
    for (int c = 0; c < 3; ++c) h.number(s[c]);
}

void hashProfile(Fnv1a& h, const DensityProfile& p) {
    for (const DensityProfileLayer& l : p.layers) {
        h.number(l.width);
        h.number(l.exp_term);
        h.number(l.exp_scale);
        h.number(l.linear_term);
        h.number(l.constant_term);
    }
}

std::string sizesText(const TableSizes& s) {
    std::ostringstream o;
    o << s.transmittance_width << ' ' << s.transmittance_height << ' ' << s.scattering_r << ' ' << s.scattering_mu
      << ' ' << s.scattering_mu_s << ' ' << s.scattering_nu << ' ' << s.irradiance_width << ' '
      << s.irradiance_height;
    return o.str();
}

// ------------------------------------------------------------------ images

const CacheFormat kFormat{"tables", "planet atmosphere tables; see src/atmosphere/table_cache.h", "planetTableKey",
                          CachePixel::Float, /*compress=*/true};
const std::vector<std::string> kChannels{"R", "G", "B", "A"};

// The four tables, each as the 2D image it is stored as (3D tables are width x (height * depth)).
struct TableImage {
    const char* file;
    int width, height;
};

std::vector<TableImage> tableImages(const TableSizes& s) {
    const glm::ivec3 s3 = s.scatteringSize();
    return {{"transmittance.exr", s.transmittance_width, s.transmittance_height},
            {"scattering.exr", s3.x, s3.y * s3.z},
            {"single_mie.exr", s3.x, s3.y * s3.z},
            {"irradiance.exr", s.irradiance_width, s.irradiance_height}};
}

// The tables' texels in float (the GPU's RGBA32F), one buffer per table, and the cache's
// images over them.
struct FloatTables {
    std::vector<std::vector<float>> pixels;
    std::vector<CacheImage> images;  // point into pixels: no copies

    FloatTables(const FloatTables&) = delete;
    FloatTables& operator=(const FloatTables&) = delete;
    explicit FloatTables(const TableSizes& sizes) {
        const std::vector<TableImage> tables = tableImages(sizes);
        pixels.resize(tables.size());
        for (std::size_t i = 0; i < tables.size(); ++i) {
            pixels[i].resize(static_cast<std::size_t>(tables[i].width) * static_cast<std::size_t>(tables[i].height) * 4);
            images.push_back({tables[i].file, tables[i].width, tables[i].height,
                              interleavedChannels(pixels[i].data(), kChannels)});
        }
    }
};

// The tables' texels in the order of tableImages().
template <class Tables>
auto texelsOf(Tables& t) {
    return std::array{&t.transmittance.texels, &t.scattering.texels, &t.singleMie.texels, &t.irradiance.texels};
}

}  // namespace

std::string atmosphereModelSource(const fs::path& shaderRoot) {
    std::vector<fs::path> files{shaderRoot / "atmosphere" / "definitions.glsl",
                                shaderRoot / "atmosphere" / "functions.glsl"};
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(shaderRoot / "atmosphere" / "precompute", ec))
        if (entry.path().extension() == ".comp") files.push_back(entry.path());
    std::sort(files.begin() + 2, files.end());
    std::string text;
    for (const fs::path& f : files) {
        std::ifstream in(f, std::ios::binary);
        text += f.filename().string() + "\n" + std::string(std::istreambuf_iterator<char>(in), {});
    }
    return text;
}

std::string tableCacheKey(const AtmosphereParameters& a, const TableSizes& s, int scatteringOrders,
                          const std::string& modelSource) {
    Fnv1a h;
    h.integer(kModelVersion);
    h.bytes(modelSource.data(), modelSource.size());
    hashSpectrum(h, a.solar_irradiance);
    h.number(a.sun_angular_radius);
    h.number(a.bottom_radius);
    h.number(a.top_radius);
    hashProfile(h, a.rayleigh_density);
    hashSpectrum(h, a.rayleigh_scattering);
    hashProfile(h, a.mie_density);
    hashSpectrum(h, a.mie_scattering);
    hashSpectrum(h, a.mie_extinction);
    h.number(a.mie_phase_function_g);
    hashProfile(h, a.absorption_density);
    hashSpectrum(h, a.absorption_extinction);
    hashSpectrum(h, a.ground_albedo);
    h.number(a.mu_s_min);
    // elek_rayleigh_phase is left out: it applies at render time and does not change the tables.
    for (int v : {s.transmittance_width, s.transmittance_height, s.scattering_r, s.scattering_mu, s.scattering_mu_s,
                  s.scattering_nu, s.irradiance_width, s.irradiance_height})
        h.integer(v);
    h.integer(scatteringOrders);
    return hex16(h.value());
}

fs::path defaultTableCacheRoot() {
    if (const char* env = std::getenv("PLANET_CACHE"); env && *env) return fs::path(env);
    return fs::path("cache") / "atmosphere";
}

void saveTables(const AtmosphereTables& tables, const fs::path& dir, const std::string& key) {
    const TableSizes& sizes = tables.sizes;
    FloatTables floats(sizes);
    for (std::size_t i = 0; i < floats.images.size(); ++i) {
        const std::vector<glm::dvec4>& texels = *texelsOf(tables)[i];
        std::vector<float>& pixels = floats.pixels[i];
        if (texels.size() * 4 != pixels.size())
            throw FileError("saveTables: table " + floats.images[i].file + " does not match its sizes");
        for (std::size_t t = 0; t < texels.size(); ++t)
            for (int c = 0; c < 4; ++c) pixels[4 * t + static_cast<std::size_t>(c)] = static_cast<float>(texels[t][c]);
    }
    writeCacheEntry(dir, kFormat, key, {{"model_version", std::to_string(kModelVersion)}, {"sizes", sizesText(sizes)}},
                    floats.images, {{"planetTableSizes", sizesText(sizes)}});
}

std::optional<AtmosphereTables> loadTables(const fs::path& dir, const std::string& expectedKey,
                                           const TableSizes& sizes, std::string* reason) {
    FloatTables floats(sizes);
    if (!readCacheEntry(dir, kFormat, expectedKey,
                        {{"model_version", std::to_string(kModelVersion)}, {"sizes", sizesText(sizes)}}, floats.images,
                        reason))
        return std::nullopt;
    AtmosphereTables tables(sizes);
    for (std::size_t i = 0; i < floats.images.size(); ++i) {
        std::vector<glm::dvec4>& texels = *texelsOf(tables)[i];
        const std::vector<float>& pixels = floats.pixels[i];
        texels.resize(pixels.size() / 4);
        for (std::size_t t = 0; t < texels.size(); ++t)
            texels[t] = glm::dvec4(pixels[4 * t], pixels[4 * t + 1], pixels[4 * t + 2], pixels[4 * t + 3]);
    }
    return tables;
}

}  // namespace planet::atmosphere
