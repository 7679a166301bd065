#include "atmosphere/table_cache.h"

#include "util/cache_entry.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <fstream>
#include <algorithm>
#include <map>
#include <sstream>
#include <unistd.h>
#include <vector>

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

constexpr const char* kKeyAttribute = "planetTableKey";
constexpr const char* kSizesAttribute = "planetTableSizes";
constexpr const char* kChannels[4] = {"R", "G", "B", "A"};

// One table as the 2D image it is stored as.
struct TableImage {
    const char* file;
    int width, height;  // image size: 3D tables are width x (height * depth)
};

std::vector<TableImage> tableImages(const TableSizes& s) {
    const glm::ivec3 s3 = s.scatteringSize();
    return {{"transmittance.exr", s.transmittance_width, s.transmittance_height},
            {"scattering.exr", s3.x, s3.y * s3.z},
            {"single_mie.exr", s3.x, s3.y * s3.z},
            {"irradiance.exr", s.irradiance_width, s.irradiance_height}};
}

std::string encodeExr(const std::vector<glm::dvec4>& texels, int width, int height, const std::string& key,
                      const TableSizes& sizes) {
    std::vector<float> pixels(texels.size() * 4);
    for (std::size_t i = 0; i < texels.size(); ++i)
        for (int c = 0; c < 4; ++c) pixels[4 * i + static_cast<std::size_t>(c)] = static_cast<float>(texels[i][c]);
    Imf::Header header(width, height);
    for (const char* name : kChannels) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    header.compression() = Imf::ZIP_COMPRESSION;
    header.insert(kKeyAttribute, Imf::StringAttribute(key));
    header.insert(kSizesAttribute, Imf::StringAttribute(sizesText(sizes)));
    Imf::StdOSStream stream;
    {
        Imf::OutputFile file(stream, header);
        Imf::FrameBuffer fb;
        const std::size_t xs = 4 * sizeof(float), ys = xs * static_cast<std::size_t>(width);
        char* base = reinterpret_cast<char*>(pixels.data());
        for (int c = 0; c < 4; ++c) fb.insert(kChannels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys));
        file.setFrameBuffer(fb);
        file.writePixels(height);
    }
    return stream.str();
}

// Decodes one table image; returns an empty string on success, else the reason.
std::string decodeExr(const std::string& bytes, const TableImage& image, const std::string& key,
                      std::vector<glm::dvec4>& texels) {
    try {
        Imf::StdISStream stream;
        stream.str(bytes);
        Imf::InputFile file(stream);
        const Imf::Header& header = file.header();
        const auto* k = header.findTypedAttribute<Imf::StringAttribute>(kKeyAttribute);
        if (!k) return "no " + std::string(kKeyAttribute) + " attribute";
        if (k->value() != key) return "its header key " + k->value() + " is not " + key;
        const Imath::Box2i dw = header.dataWindow();
        const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
        if (w != image.width || h != image.height)
            return "size " + std::to_string(w) + "x" + std::to_string(h) + ", expected " +
                   std::to_string(image.width) + "x" + std::to_string(image.height);
        for (const char* name : kChannels) {
            const Imf::Channel* channel = header.channels().findChannel(name);
            if (!channel) return "no channel " + std::string(name);
            if (channel->type != Imf::FLOAT) return "channel " + std::string(name) + " is not FLOAT";
        }
        std::vector<float> pixels(static_cast<std::size_t>(w) * h * 4);
        Imf::FrameBuffer fb;
        const std::size_t xs = 4 * sizeof(float), ys = xs * static_cast<std::size_t>(w);
        char* base = reinterpret_cast<char*>(pixels.data()) -
                     (static_cast<std::ptrdiff_t>(dw.min.x) * static_cast<std::ptrdiff_t>(xs) +
                      static_cast<std::ptrdiff_t>(dw.min.y) * static_cast<std::ptrdiff_t>(ys));
        for (int c = 0; c < 4; ++c) fb.insert(kChannels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys));
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        texels.resize(static_cast<std::size_t>(w) * h);
        for (std::size_t i = 0; i < texels.size(); ++i) {
            const float* p = &pixels[4 * i];
            for (int c = 0; c < 4; ++c)
                if (!std::isfinite(p[c]))
                    return "texel " + std::to_string(i) + " channel " + kChannels[c] + " is " + std::to_string(p[c]);
            texels[i] = glm::dvec4(p[0], p[1], p[2], p[3]);
        }
        return {};
    } catch (const std::exception& e) {
        return std::string("OpenEXR cannot read it: ") + e.what();
    }
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
    const std::vector<TableImage> images = tableImages(sizes);
    const std::vector<glm::dvec4>* texels[4] = {&tables.transmittance.texels, &tables.scattering.texels,
                                                &tables.singleMie.texels, &tables.irradiance.texels};
    const fs::path target = dir.lexically_normal();
    const std::string pid = std::to_string(::getpid());
    const fs::path tmp = target.string() + ".tmp" + pid;
    std::error_code ec;
    fs::remove_all(tmp, ec);

    std::ostringstream keyFile;
    keyFile << "# planet atmosphere tables; see src/atmosphere/table_cache.h\n"
            << "key " << key << "\nmodel_version " << kModelVersion << "\nsizes " << sizesText(sizes) << "\n";
    try {
        for (std::size_t i = 0; i < images.size(); ++i) {
            const TableImage& image = images[i];
            if (texels[i]->size() != static_cast<std::size_t>(image.width) * image.height)
                throw FileError("saveTables: table " + std::string(image.file) + " does not match its sizes");
            std::string bytes;
            try {
                bytes = encodeExr(*texels[i], image.width, image.height, key, sizes);
            } catch (const std::exception& e) {
                throw FileError("could not encode OpenEXR " + quote(target / image.file) + ": " + e.what());
            }
            writeFileAtomic(tmp / image.file, bytes);
            keyFile << image.file << " " << checksum(bytes) << "\n";
        }
        writeFileAtomic(tmp / "key.txt", keyFile.str());
    } catch (...) {
        fs::remove_all(tmp, ec);
        throw;
    }

    replaceFolder(tmp, target, "tables");
}

std::optional<AtmosphereTables> loadTables(const fs::path& dir, const std::string& expectedKey,
                                           const TableSizes& sizes, std::string* reason) {
    auto reject = [&](const std::string& why) -> std::optional<AtmosphereTables> {
        if (reason) *reason = why;
        return std::nullopt;
    };
    if (!fs::is_directory(dir)) return reject("no cache folder " + quote(dir));
    std::string keyText;
    try {
        keyText = readFile(dir / "key.txt");
    } catch (const FileError& e) {
        return reject(e.what());
    }
    const std::map<std::string, std::string> fields = parseKeyFile(keyText);
    auto field = [&](const std::string& name) {
        const auto it = fields.find(name);
        return it == fields.end() ? std::string() : it->second;
    };
    const fs::path keyPath = dir / "key.txt";
    if (field("key") != expectedKey)
        return reject(quote(keyPath) + " holds key " + field("key") + ", expected " + expectedKey);
    if (field("model_version") != std::to_string(kModelVersion))
        return reject(quote(keyPath) + " is for model version '" + field("model_version") + "', not " +
                      std::to_string(kModelVersion));
    if (field("sizes") != sizesText(sizes))
        return reject(quote(keyPath) + " holds sizes '" + field("sizes") + "', expected '" +
                      sizesText(sizes) + "'");

    AtmosphereTables tables(sizes);
    std::vector<glm::dvec4>* texels[4] = {&tables.transmittance.texels, &tables.scattering.texels,
                                          &tables.singleMie.texels, &tables.irradiance.texels};
    const std::vector<TableImage> images = tableImages(sizes);
    for (std::size_t i = 0; i < images.size(); ++i) {
        const fs::path path = dir / images[i].file;
        std::string bytes;
        try {
            bytes = readFile(path);
        } catch (const FileError& e) {
            return reject(e.what());
        }
        const std::string expected = field(images[i].file);
        if (expected.empty()) return reject(quote(keyPath) + " has no checksum for " + images[i].file);
        if (checksum(bytes) != expected)
            return reject(quote(path) + " is damaged (checksum " + checksum(bytes) + ", expected " +
                          expected + ")");
        const std::string why = decodeExr(bytes, images[i], expectedKey, *texels[i]);
        if (!why.empty()) return reject(quote(path) + ": " + why);
    }
    return tables;
}

}  // namespace planet::atmosphere
