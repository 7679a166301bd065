// Continents cube map: bake, sample, cache. See continents.h for the layout and conventions.
//
// The bake in three passes: (1) fBm at every texel's direction, rows spread over all
// cores; (2) a solid-angle-weighted histogram of the values (65536 bins between the
// extremes), which locates the bin holding the sea-level quantile; (3) only that bin's
// texels sorted, to place sea level between two neighbouring values. Memory stays at the
// map itself plus one bin, so a 4096^2 face size works; the result is the same as a full
// sort would give.
#include "noise/continents.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <unistd.h>
#include <utility>

#include "noise/noise.h"
#include "util/cache_entry.h"
#include "util/file_util.h"

namespace planet::noise {

namespace fs = std::filesystem;

namespace {

// SplitMix64 (Steele, Lea, Flood 2014): a well-mixed 64-bit value per call.
std::uint64_t splitMix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// The seed's offset of the noise domain, in [-100, 100)^3. Small enough that float
// noise keeps its precision at 10 octaves (100 * 2^9 = 5e4: float spacing 4e-3 lattice
// cells, far below a texel), large enough that seeds give unrelated maps.
glm::dvec3 seedOffset(int seed) {
    std::uint64_t state = static_cast<std::uint64_t>(static_cast<std::int64_t>(seed));
    glm::dvec3 o;
    for (int i = 0; i < 3; ++i) o[i] = static_cast<double>(splitMix64(state) >> 11) * 0x1.0p-53 * 200.0 - 100.0;
    return o;
}

void validate(const ContinentParams& p, int faceSize) {
    if (faceSize < 1 || faceSize > 8192)
        throw std::invalid_argument("continents: face size " + std::to_string(faceSize) + " is outside [1, 8192]");
    if (!(p.frequency > 0.0 && p.frequency <= 1000.0))
        throw std::invalid_argument("continents: frequency " + std::to_string(p.frequency) +
                                    " is outside (0, 1000]");
    if (p.octaves < 1 || p.octaves > 10)
        throw std::invalid_argument("continents: octaves " + std::to_string(p.octaves) + " is outside [1, 10]");
    if (!(p.seaFraction >= 0.0 && p.seaFraction <= 1.0))
        throw std::invalid_argument("continents: sea fraction " + std::to_string(p.seaFraction) +
                                    " is outside [0, 1]");
}

// ------------------------------------------------------------------ EXR

constexpr const char* kKeyAttribute = "planetContinentsKey";
constexpr const char* kChannel = "Y";
constexpr const char* kImageFile = "continents.exr";

std::string encodeExr(const CubeMap& map, const std::string& key) {
    const int width = map.size, height = 6 * map.size;
    Imf::Header header(width, height);
    header.channels().insert(kChannel, Imf::Channel(Imf::FLOAT));
    header.compression() = Imf::ZIP_COMPRESSION;
    header.insert(kKeyAttribute, Imf::StringAttribute(key));
    Imf::StdOSStream stream;
    {
        Imf::OutputFile file(stream, header);
        Imf::FrameBuffer fb;
        // OpenEXR's Slice takes a non-const base; it only reads through it when writing.
        char* base = reinterpret_cast<char*>(const_cast<float*>(map.texels.data()));
        fb.insert(kChannel, Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * static_cast<std::size_t>(width)));
        file.setFrameBuffer(fb);
        file.writePixels(height);
    }
    return stream.str();
}

// Decodes continents.exr into map (size already set); empty string on success, else the reason.
std::string decodeExr(const std::string& bytes, const std::string& key, CubeMap& map) {
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
        if (w != map.size || h != 6 * map.size)
            return "size " + std::to_string(w) + "x" + std::to_string(h) + ", expected " + std::to_string(map.size) +
                   "x" + std::to_string(6 * map.size);
        const Imf::Channel* channel = header.channels().findChannel(kChannel);
        if (!channel) return "no channel " + std::string(kChannel);
        if (channel->type != Imf::FLOAT) return "channel " + std::string(kChannel) + " is not FLOAT";
        map.texels.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0f);
        const std::size_t xs = sizeof(float), ys = xs * static_cast<std::size_t>(w);
        char* base = reinterpret_cast<char*>(map.texels.data()) -
                     (static_cast<std::ptrdiff_t>(dw.min.x) * static_cast<std::ptrdiff_t>(xs) +
                      static_cast<std::ptrdiff_t>(dw.min.y) * static_cast<std::ptrdiff_t>(ys));
        Imf::FrameBuffer fb;
        fb.insert(kChannel, Imf::Slice(Imf::FLOAT, base, xs, ys));
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        for (std::size_t i = 0; i < map.texels.size(); ++i)
            if (!(map.texels[i] >= -1.0f && map.texels[i] <= 1.0f))
                return "texel " + std::to_string(i) + " is " + std::to_string(map.texels[i]) + ", not in [-1, 1]";
        return {};
    } catch (const std::exception& e) {
        return std::string("OpenEXR cannot read it: ") + e.what();
    }
}

}  // namespace

// ------------------------------------------------------------------ geometry

glm::dvec3 cubeTexelDirection(int face, int x, int y, int size) {
    // GL 4.5 Table 8.19 inverted: s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2.
    const double sc = 2.0 * (x + 0.5) / size - 1.0, tc = 2.0 * (y + 0.5) / size - 1.0;
    glm::dvec3 d;
    switch (face) {
        case 0: d = {1.0, -tc, -sc}; break;   // +X: sc = -z, tc = -y
        case 1: d = {-1.0, -tc, sc}; break;   // -X: sc = +z, tc = -y
        case 2: d = {sc, 1.0, tc}; break;     // +Y: sc = +x, tc = +z
        case 3: d = {sc, -1.0, -tc}; break;   // -Y: sc = +x, tc = -z
        case 4: d = {sc, -tc, 1.0}; break;    // +Z: sc = +x, tc = -y
        default: d = {-sc, -tc, -1.0}; break;  // -Z: sc = -x, tc = -y
    }
    return d / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

int cubeFaceOf(glm::dvec3 d, double& s, double& t) {
    const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    int face;
    double sc, tc, ma;
    if (ax >= ay && ax >= az) {
        face = d.x >= 0.0 ? 0 : 1;
        ma = ax;
        sc = d.x >= 0.0 ? -d.z : d.z;
        tc = -d.y;
    } else if (ay >= az) {
        face = d.y >= 0.0 ? 2 : 3;
        ma = ay;
        sc = d.x;
        tc = d.y >= 0.0 ? d.z : -d.z;
    } else {
        face = d.z >= 0.0 ? 4 : 5;
        ma = az;
        sc = d.z >= 0.0 ? d.x : -d.x;
        tc = -d.y;
    }
    s = 0.5 * (sc / ma + 1.0);
    t = 0.5 * (tc / ma + 1.0);
    return face;
}

double cubeTexelSolidAngle(int x, int y, int size) {
    // The solid angle of the face rectangle [0, a] x [0, b] at distance 1 is
    // atan(a b / sqrt(a^2 + b^2 + 1)); a texel is the signed sum over its four corners.
    auto corner = [](double a, double b) { return std::atan2(a * b, std::sqrt(a * a + b * b + 1.0)); };
    const double x0 = 2.0 * x / size - 1.0, x1 = 2.0 * (x + 1) / size - 1.0;
    const double y0 = 2.0 * y / size - 1.0, y1 = 2.0 * (y + 1) / size - 1.0;
    return corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0);
}

float sampleContinents(const CubeMap& map, glm::dvec3 direction) {
    double s = 0.0, t = 0.0;
    const int face = cubeFaceOf(direction, s, t);
    const int n = map.size;
    const double u = s * n - 0.5, v = t * n - 0.5;
    const double fu = std::floor(u), fv = std::floor(v);
    const double wx = u - fu, wy = v - fv;
    auto clampIndex = [n](double i) { return static_cast<int>(std::clamp(i, 0.0, static_cast<double>(n - 1))); };
    const int x0 = clampIndex(fu), x1 = clampIndex(fu + 1.0), y0 = clampIndex(fv), y1 = clampIndex(fv + 1.0);
    const double top = (1.0 - wx) * map.at(face, x0, y0) + wx * map.at(face, x1, y0);
    const double bottom = (1.0 - wx) * map.at(face, x0, y1) + wx * map.at(face, x1, y1);
    return static_cast<float>((1.0 - wy) * top + wy * bottom);
}

double seaFractionOf(const CubeMap& map) {
    double sea = 0.0, total = 0.0;
    for (int y = 0; y < map.size; ++y)
        for (int x = 0; x < map.size; ++x) {
            const double w = cubeTexelSolidAngle(x, y, map.size);
            for (int f = 0; f < 6; ++f) {
                total += w;
                if (map.at(f, x, y) < 0.0f) sea += w;
            }
        }
    return total > 0.0 ? sea / total : 0.0;
}

// ------------------------------------------------------------------ bake

CubeMap bakeContinents(const ContinentParams& params, int faceSize, const BakeProgress& progress) {
    validate(params, faceSize);
    CubeMap map;
    map.size = faceSize;
    map.texels.resize(6 * static_cast<std::size_t>(faceSize) * static_cast<std::size_t>(faceSize));

    // (1) Raw fBm, one face row per task; the calling thread reports progress.
    const glm::dvec3 offset = seedOffset(params.seed);
    const int rows = 6 * faceSize;
    std::atomic<int> next{0}, done{0};
    auto worker = [&](bool caller) {
        for (int row = next++; row < rows; row = next++) {
            const int face = row / faceSize, y = row % faceSize;
            for (int x = 0; x < faceSize; ++x) {
                const glm::dvec3 p = cubeTexelDirection(face, x, y, faceSize) * params.frequency + offset;
                map.at(face, x, y) = fbm(glm::vec3(p), params.octaves);
            }
            const int finished = ++done;
            if (caller && progress) progress(0.95 * finished / rows);
        }
    };
    const int threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker, false);
    worker(true);
    for (std::thread& t : pool) t.join();

    // (2) Solid-angle-weighted histogram between the extremes.
    const auto [minIt, maxIt] = std::minmax_element(map.texels.begin(), map.texels.end());
    const double lo = *minIt, hi = *maxIt;
    constexpr int kBins = 1 << 16;
    const double binScale = hi > lo ? kBins / (hi - lo) : 0.0;
    auto binOf = [&](float v) { return std::min(kBins - 1, static_cast<int>((v - lo) * binScale)); };
    std::vector<double> binWeight(kBins, 0.0);
    std::vector<float> binMin(kBins, std::numeric_limits<float>::infinity()),
        binMax(kBins, -std::numeric_limits<float>::infinity());
    double total = 0.0;
    for (int y = 0; y < faceSize; ++y)
        for (int x = 0; x < faceSize; ++x) {
            const double w = cubeTexelSolidAngle(x, y, faceSize);
            for (int f = 0; f < 6; ++f) {
                const float v = map.at(f, x, y);
                const int b = binOf(v);
                binWeight[static_cast<std::size_t>(b)] += w;
                binMin[static_cast<std::size_t>(b)] = std::min(binMin[static_cast<std::size_t>(b)], v);
                binMax[static_cast<std::size_t>(b)] = std::max(binMax[static_cast<std::size_t>(b)], v);
                total += w;
            }
        }
    if (progress) progress(0.97);

    // (3) The bin where the cumulative weight reaches the target, then its texels in order:
    // sea level goes between the last sea texel and the first land texel, at the count
    // whose cumulative weight is nearest the target.
    const double target = params.seaFraction * total;
    int bin = 0;
    double before = 0.0;
    while (bin < kBins - 1 && before + binWeight[static_cast<std::size_t>(bin)] < target)
        before += binWeight[static_cast<std::size_t>(bin++)];
    std::vector<std::pair<float, double>> candidates;  // (value, solid angle) in the bin
    for (int y = 0; y < faceSize; ++y)
        for (int x = 0; x < faceSize; ++x)
            for (int f = 0; f < 6; ++f)
                if (binOf(map.at(f, x, y)) == bin) candidates.emplace_back(map.at(f, x, y), cubeTexelSolidAngle(x, y, faceSize));
    std::sort(candidates.begin(), candidates.end());
    std::size_t seaCount = 0;
    double cumulative = before, bestError = std::abs(before - target);
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        cumulative += candidates[i].second;
        if (std::abs(cumulative - target) < bestError) {
            bestError = std::abs(cumulative - target);
            seaCount = i + 1;
        }
    }
    // The highest sea value and the lowest land value, from this bin or its neighbours.
    std::optional<double> below, above;
    if (seaCount > 0) below = candidates[seaCount - 1].first;
    else
        for (int b = bin - 1; b >= 0 && !below; --b)
            if (binWeight[static_cast<std::size_t>(b)] > 0.0) below = binMax[static_cast<std::size_t>(b)];
    if (seaCount < candidates.size()) above = candidates[seaCount].first;
    else
        for (int b = bin + 1; b < kBins && !above; ++b)
            if (binWeight[static_cast<std::size_t>(b)] > 0.0) above = binMin[static_cast<std::size_t>(b)];
    // No sea: the lowest texel sits at 0 (land). No land: sea level just above the highest.
    const double seaLevel = below && above ? 0.5 * (*below + *above) : above ? *above : *below + 1e-6 * (1.0 + std::abs(*below));

    // Shift, then scale each side to reach -1 and +1 (the sign is kept, so is the coastline).
    const double seaScale = seaLevel > lo ? 1.0 / (seaLevel - lo) : 0.0;
    const double landScale = hi > seaLevel ? 1.0 / (hi - seaLevel) : 0.0;
    for (float& v : map.texels) {
        const double h = v - seaLevel;
        v = static_cast<float>(std::clamp(h * (h < 0.0 ? seaScale : landScale), -1.0, 1.0));
    }
    if (progress) progress(1.0);
    return map;
}

// ------------------------------------------------------------------ cache

std::string continentsCacheKey(const ContinentParams& p, int faceSize) {
    Fnv1a h;
    h.integer(kContinentsVersion);
    // Fingerprint of the noise code: a change in simplex / fbm changes the key even
    // when kContinentsVersion was not bumped.
    for (const glm::vec3 q : {glm::vec3(1.25f, -3.5f, 7.75f), glm::vec3(-41.3f, 17.9f, 0.37f)}) {
        h.number(simplex(q));
        h.number(fbm(q, 10));
    }
    h.integer(p.seed);
    h.number(p.frequency);
    h.integer(p.octaves);
    h.number(p.seaFraction);
    h.integer(faceSize);
    return hex16(h.value());
}

fs::path defaultContinentsCacheRoot() {
    if (const char* env = std::getenv("PLANET_CACHE"); env && *env) {
        fs::path p = fs::path(env).lexically_normal();
        if (p.filename().empty()) p = p.parent_path();  // "dir/" -> "dir"
        return p.parent_path() / "continents";
    }
    return fs::path("cache") / "continents";
}

void saveContinents(const CubeMap& map, const ContinentParams& p, const fs::path& dir, const std::string& key) {
    if (map.size < 1 || map.texels.size() != 6 * static_cast<std::size_t>(map.size) * static_cast<std::size_t>(map.size))
        throw FileError("saveContinents: the map's texels do not match its size");
    const fs::path target = dir.lexically_normal();
    const std::string pid = std::to_string(::getpid());
    const fs::path tmp = target.string() + ".tmp" + pid;
    std::error_code ec;
    fs::remove_all(tmp, ec);
    try {
        std::string bytes;
        try {
            bytes = encodeExr(map, key);
        } catch (const std::exception& e) {
            throw FileError("could not encode OpenEXR " + quote(target / kImageFile) + ": " + e.what());
        }
        writeFileAtomic(tmp / kImageFile, bytes);
        std::ostringstream keyFile;
        keyFile.precision(17);
        keyFile << "# planet continents cube map; see noise/continents.h\n"
                << "key " << key << "\nversion " << kContinentsVersion << "\nsize " << map.size << "\nseed " << p.seed
                << "\nfrequency " << p.frequency << "\noctaves " << p.octaves << "\nsea_fraction " << p.seaFraction
                << "\n" << kImageFile << " " << checksum(bytes) << "\n";
        writeFileAtomic(tmp / "key.txt", keyFile.str());
    } catch (...) {
        fs::remove_all(tmp, ec);
        throw;
    }
    replaceFolder(tmp, target, "continents");
}

std::optional<CubeMap> loadContinents(const fs::path& dir, const std::string& expectedKey, int faceSize,
                                      std::string* reason) {
    auto reject = [&](const std::string& why) -> std::optional<CubeMap> {
        if (reason) *reason = why;
        return std::nullopt;
    };
    if (!fs::is_directory(dir)) return reject("no cache folder " + quote(dir));
    const fs::path keyPath = dir / "key.txt";
    std::string keyText;
    try {
        keyText = readFile(keyPath);
    } catch (const FileError& e) {
        return reject(e.what());
    }
    const std::map<std::string, std::string> fields = parseKeyFile(keyText);
    auto field = [&](const std::string& name) {
        const auto it = fields.find(name);
        return it == fields.end() ? std::string() : it->second;
    };
    if (field("key") != expectedKey)
        return reject(quote(keyPath) + " holds key " + field("key") + ", expected " + expectedKey);
    if (field("version") != std::to_string(kContinentsVersion))
        return reject(quote(keyPath) + " is for version '" + field("version") + "', not " +
                      std::to_string(kContinentsVersion));
    if (field("size") != std::to_string(faceSize))
        return reject(quote(keyPath) + " holds size '" + field("size") + "', expected " + std::to_string(faceSize));
    const fs::path imagePath = dir / kImageFile;
    std::string bytes;
    try {
        bytes = readFile(imagePath);
    } catch (const FileError& e) {
        return reject(e.what());
    }
    const std::string expected = field(kImageFile);
    if (expected.empty()) return reject(quote(keyPath) + " has no checksum for " + kImageFile);
    if (checksum(bytes) != expected)
        return reject(quote(imagePath) + " is damaged (checksum " + checksum(bytes) + ", expected " + expected + ")");
    CubeMap map;
    map.size = faceSize;
    const std::string why = decodeExr(bytes, expectedKey, map);
    if (!why.empty()) return reject(quote(imagePath) + ": " + why);
    return map;
}

}  // namespace planet::noise
