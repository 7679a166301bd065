// Continents cube map: bake, sample, cache. See continents.h for the layout and conventions.
//
// The bake in three passes: (1) fBm and its analytic gradient at every texel's direction,
// rows spread over all cores; (2) a solid-angle-weighted histogram of the values (65536 bins between the
// extremes), which locates the bin holding the sea-level quantile; (3) only that bin's
// texels sorted, to place sea level between two neighbouring values. Memory stays at the
// map itself plus one bin, so a 4096^2 face size works; the result is the same as a full
// sort would give.
#include "noise/continents.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <thread>
#include <utility>

#include <glm/glm.hpp>

#include "noise/noise.h"
#include "util/cache_entry.h"
#include "util/file_util.h"
#include "util/log.h"

namespace planet::noise {

namespace fs = std::filesystem;

namespace {

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

// ------------------------------------------------------------------ cache entry

const CacheFormat kFormat{"continents", "planet continents cube map; see noise/continents.h", "planetContinentsKey",
                          CachePixel::Float,
                          // Uncompressed: float noise and its gradient do not compress (ZIP saved 2 % at
                          // 512) and decompressing tripled the load time the renderer waits for at start-up.
                          /*compress=*/false};
constexpr const char* kImageFile = "continents.exr";

// continents.exr over the map's texels: x, y, z, w are the channels Y, dYdx, dYdy, dYdz.
std::vector<CacheImage> images(CubeMap& map) {
    static_assert(sizeof(glm::vec4) == 4 * sizeof(float));
    return {{kImageFile, map.size, 6 * map.size,
             interleavedChannels(&map.texels.data()->x, {"Y", "dYdx", "dYdy", "dYdz"})}};
}

// key.txt's fields a valid entry must hold.
CacheFields checkedFields(int faceSize) {
    return {{"version", std::to_string(kContinentsVersion)}, {"size", std::to_string(faceSize)}};
}

}  // namespace

// ------------------------------------------------------------------ geometry

namespace {

// The point (sc, tc) of a face's plane at distance 1 (sc, tc in [-1, 1] on the face; beyond
// it, the plane's extension), unnormalised. GL 4.5 Table 8.19 inverted:
// s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2.
glm::dvec3 facePoint(int face, double sc, double tc) {
    switch (face) {
        case 0: return {1.0, -tc, -sc};   // +X: sc = -z, tc = -y
        case 1: return {-1.0, -tc, sc};   // -X: sc = +z, tc = -y
        case 2: return {sc, 1.0, tc};     // +Y: sc = +x, tc = +z
        case 3: return {sc, -1.0, -tc};   // -Y: sc = +x, tc = -z
        case 4: return {sc, -tc, 1.0};    // +Z: sc = +x, tc = -y
        default: return {-sc, -tc, -1.0};  // -Z: sc = -x, tc = -y
    }
}

}  // namespace

glm::dvec3 cubeTexelDirection(int face, int x, int y, int size) {
    const glm::dvec3 d = facePoint(face, 2.0 * (x + 0.5) / size - 1.0, 2.0 * (y + 0.5) / size - 1.0);
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

// (noise/continents.h.) Beyond an edge the texel is found by selecting the face of a point a
// quarter texel beyond it: its position along the edge moves by under a quarter texel when
// projected onto the neighbour, and a texel centre is half a texel from its texel's boundary.
bool seamlessTap(int size, int face, int i, int j, int& tapFace, int& x, int& y) {
    const int n = size;
    const bool insideI = i >= 0 && i < n, insideJ = j >= 0 && j < n;
    if (insideI && insideJ) {
        tapFace = face;
        x = i;
        y = j;
        return true;
    }
    if (!insideI && !insideJ) return false;
    const double beyond = 1.0 + 0.5 / n;
    const double sc = insideI ? 2.0 * (i + 0.5) / n - 1.0 : (i < 0 ? -beyond : beyond);
    const double tc = insideJ ? 2.0 * (j + 0.5) / n - 1.0 : (j < 0 ? -beyond : beyond);
    double s = 0.0, t = 0.0;
    tapFace = cubeFaceOf(facePoint(face, sc, tc), s, t);
    auto index = [n](double c) { return std::clamp(static_cast<int>(std::floor(c * n)), 0, n - 1); };
    x = index(s);
    y = index(t);
    return true;
}

namespace {

template <class Texel>
const Texel* seamlessTexel(const CubeMapOf<Texel>& map, int face, int i, int j) {
    int tapFace = 0, x = 0, y = 0;
    return seamlessTap(map.size, face, i, j, tapFace, x, y) ? &map.at(tapFace, x, y) : nullptr;
}

// The bilinear, seamless filter of sampleContinents, for a map of any texel type (a glm
// vector of floats); computed in double.
template <class Texel>
Texel sampleSeamless(const CubeMapOf<Texel>& map, glm::dvec3 direction) {
    using Double = glm::vec<Texel::length(), double>;
    double s = 0.0, t = 0.0;
    const int face = cubeFaceOf(direction, s, t);
    const int n = map.size;
    const double u = s * n - 0.5, v = t * n - 0.5;
    const double fu = std::floor(u), fv = std::floor(v);
    const double wx = u - fu, wy = v - fv;
    const int i = static_cast<int>(fu), j = static_cast<int>(fv);
    // Taps (i, j), (i+1, j), (i, j+1), (i+1, j+1); at most one is missing (beyond a corner),
    // and it becomes the mean of the other three.
    const Texel* taps[4] = {seamlessTexel(map, face, i, j), seamlessTexel(map, face, i + 1, j),
                            seamlessTexel(map, face, i, j + 1), seamlessTexel(map, face, i + 1, j + 1)};
    Double value[4], sum(0.0);
    int missing = -1;
    for (int k = 0; k < 4; ++k) {
        if (taps[k]) {
            value[k] = Double(*taps[k]);
            sum += value[k];
        } else {
            missing = k;
        }
    }
    if (missing >= 0) value[missing] = sum / 3.0;
    const Double top = (1.0 - wx) * value[0] + wx * value[1];
    const Double bottom = (1.0 - wx) * value[2] + wx * value[3];
    return Texel((1.0 - wy) * top + wy * bottom);
}

}  // namespace

glm::vec4 sampleContinents(const CubeMap& map, glm::dvec3 direction) { return sampleSeamless(map, direction); }
glm::vec2 sampleCubeMap(const CubeMapOf<glm::vec2>& map, glm::dvec3 direction) {
    return sampleSeamless(map, direction);
}

double seaFractionOf(const CubeMap& map) {
    double sea = 0.0, total = 0.0;
    for (int y = 0; y < map.size; ++y)
        for (int x = 0; x < map.size; ++x) {
            const double w = cubeTexelSolidAngle(x, y, map.size);
            for (int f = 0; f < 6; ++f) {
                total += w;
                if (map.elevation(f, x, y) < 0.0f) sea += w;
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

    // (1) Raw fBm and its tangential gradient with respect to the direction d (chain rule:
    // d fbm(f d + o) / dd = f grad fbm), one face row per task; the calling thread reports progress.
    const glm::dvec3 offset(seedOffset(params.seed, 0));
    const int rows = 6 * faceSize;
    std::atomic<int> next{0}, done{0};
    auto worker = [&](bool caller) {
        for (int row = next++; row < rows; row = next++) {
            const int face = row / faceSize, y = row % faceSize;
            for (int x = 0; x < faceSize; ++x) {
                const glm::dvec3 d = cubeTexelDirection(face, x, y, faceSize);
                glm::vec3 noiseGradient;
                const float value = fbmGrad(glm::vec3(d * params.frequency + offset), params.octaves, 2.0f, 0.5f,
                                            noiseGradient);
                const glm::dvec3 g = params.frequency * glm::dvec3(noiseGradient);
                map.at(face, x, y) = glm::vec4(value, glm::vec3(g - glm::dot(g, d) * d));
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
    const auto byElevation = [](const glm::vec4& a, const glm::vec4& b) { return a.x < b.x; };
    const auto [minIt, maxIt] = std::minmax_element(map.texels.begin(), map.texels.end(), byElevation);
    const double lo = minIt->x, hi = maxIt->x;
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
                const float v = map.elevation(f, x, y);
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
                if (binOf(map.elevation(f, x, y)) == bin)
                    candidates.emplace_back(map.elevation(f, x, y), cubeTexelSolidAngle(x, y, faceSize));
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

    // Shift, then scale each side to reach -1 and +1 (the sign is kept, so is the coastline);
    // the gradient takes its side's scale.
    const double seaScale = seaLevel > lo ? 1.0 / (seaLevel - lo) : 0.0;
    const double landScale = hi > seaLevel ? 1.0 / (hi - seaLevel) : 0.0;
    for (glm::vec4& texel : map.texels) {
        const double h = texel.x - seaLevel;
        const double scale = h < 0.0 ? seaScale : landScale;
        texel = glm::vec4(static_cast<float>(std::clamp(h * scale, -1.0, 1.0)),
                          glm::vec3(scale * glm::dvec3(texel.y, texel.z, texel.w)));
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
        glm::vec3 g;
        h.number(simplex(q));
        h.number(fbmGrad(q, 10, 2.0f, 0.5f, g));
        for (int c = 0; c < 3; ++c) h.number(g[c]);
    }
    for (int c = 0; c < 3; ++c) h.number(seedOffset(p.seed, 0)[c]);  // the seed's noise domain
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
    CacheFields fields = checkedFields(map.size);
    fields.insert(fields.end(), {{"seed", std::to_string(p.seed)},
                                 {"frequency", exactText(p.frequency)},
                                 {"octaves", std::to_string(p.octaves)},
                                 {"sea_fraction", exactText(p.seaFraction)}});
    // writeCacheEntry only reads the texels.
    writeCacheEntry(dir, kFormat, key, fields, images(const_cast<CubeMap&>(map)));
}

std::optional<CubeMap> loadContinents(const fs::path& dir, const std::string& expectedKey, int faceSize,
                                      std::string* reason) {
    if (faceSize < 1 || faceSize > 8192) {  // bakeContinents' range; also bounds what is allocated here
        if (reason) *reason = "face size " + std::to_string(faceSize) + " is outside [1, 8192]";
        return std::nullopt;
    }
    CubeMap map;
    map.size = faceSize;
    map.texels.assign(6 * static_cast<std::size_t>(map.size) * static_cast<std::size_t>(map.size), glm::vec4(0.0f));
    if (!readCacheEntry(dir, kFormat, expectedKey, checkedFields(faceSize), images(map), reason)) return std::nullopt;
    for (std::size_t i = 0; i < map.texels.size(); ++i)
        if (!(map.texels[i].x >= -1.0f && map.texels[i].x <= 1.0f)) {  // the gradient: finite, readCacheEntry checked
            if (reason)
                *reason = quote(dir / kImageFile) + ": texel " + std::to_string(i) + " has elevation " +
                          std::to_string(map.texels[i].x) + ", not in [-1, 1]";
            return std::nullopt;
        }
    return map;
}

BakeProgress logBakeProgress() {
    const auto start = std::chrono::steady_clock::now();
    return [start, reported = 0](double fraction) mutable {
        const int percent = static_cast<int>(100.0 * fraction);
        if (percent < reported + 10 || std::chrono::steady_clock::now() - start < std::chrono::seconds(1)) return;
        reported = percent / 10 * 10;
        logInfo("bake: " + std::to_string(reported) + "%");
    };
}

BakeProgress alsoLogged(const BakeProgress& progress) {
    return [log = logBakeProgress(), progress](double fraction) mutable {
        log(fraction);
        if (progress) progress(fraction);
    };
}

CubeMap loadOrBakeContinents(const ContinentParams& params, int faceSize, const fs::path& root) {
    validate(params, faceSize);
    const std::string key = continentsCacheKey(params, faceSize);
    const fs::path dir = root / key;
    return loadOrBakeLogged(
        "continents", std::to_string(faceSize) + "^2 x 6 texels, seed " + std::to_string(params.seed), dir,
        [&](std::string* reason) { return loadContinents(dir, key, faceSize, reason); },
        [&] { return bakeContinents(params, faceSize, logBakeProgress()); },
        [&](const CubeMap& baked) { saveContinents(baked, params, dir, key); });
}

}  // namespace planet::noise
