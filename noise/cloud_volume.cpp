// Cloud density volume: bake, border, cache. See cloud_volume.h for the layout, the values
// and the guarantee the border gives the march.
//
// The bake in four passes over the voxels: (1) the noise, slices spread over all cores, the
// Worley octaves over feature points hashed once per row of cells (WorleyRows); (2) the
// cloud threshold, by nth_element on a copy of the values (exact, 4 bytes a voxel for a
// moment); (3) the Chebyshev distance to the nearest cloud voxel, capped at borderVoxels + 1,
// as three 1D passes (separable: the distance is the max over axes, minimised over cloud
// voxels, so each pass takes min over k of max(|k|, the previous pass's distance at i + k));
// (4) density, 0 or -1 from the threshold and the distance, rounded to half.
#include "noise/cloud_volume.h"

#include <Imath/half.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <glm/glm.hpp>

#include "noise/noise.h"
#include "util/cache_entry.h"
#include "util/file_util.h"
#include "util/log.h"

namespace planet::noise {

namespace fs = std::filesystem;

namespace {

void validate(const CloudVolumeParams& p) {
    auto check = [](bool ok, const std::string& what, double value, const char* range) {
        if (!ok) throw std::invalid_argument("cloud volume: " + what + " " + std::to_string(value) + " is outside " + range);
    };
    check(p.size >= 16 && p.size <= 512, "size", p.size, "[16, 512]");
    check(p.shapeFrequency >= 1 && p.shapeFrequency <= 64, "shape frequency", p.shapeFrequency, "[1, 64]");
    check(p.shapeOctaves >= 1 && p.shapeOctaves <= 6, "shape octaves", p.shapeOctaves, "[1, 6]");
    check(p.detailFrequency >= 1 && p.detailFrequency <= 256, "detail frequency", p.detailFrequency, "[1, 256]");
    check(p.detailOctaves >= 1 && p.detailOctaves <= 6, "detail octaves", p.detailOctaves, "[1, 6]");
    check(p.erosion >= 0.0 && p.erosion <= 1.0, "erosion", p.erosion, "[0, 1]");
    check(p.cloudFraction >= 0.01 && p.cloudFraction <= 0.99, "cloud fraction", p.cloudFraction, "[0.01, 0.99]");
    check(p.borderVoxels >= 1 && p.borderVoxels <= 32, "border", p.borderVoxels, "[1, 32] voxels");
}

// ------------------------------------------------------------------ noise

// Purposes for seedStream: each noise and octave hashes its lattice in its own stream.
constexpr unsigned kPerlinStream = 1, kShapeWorleyStream = 16, kDetailWorleyStream = 32;

// An inverted Worley fBm: sum over octaves of weight (1 - F1), F1 clamped to [0, 1].
struct WorleyOctave {
    int period;       // cells per tile
    unsigned stream;  // feature points' stream
    float weight;     // 0.5^k over the sum of the octaves' 0.5^k
};

// Octaves k = 0 .. octaves-1 with 2^k frequency cells per tile, those with at least 2 voxels a cell.
std::vector<WorleyOctave> worleyOctaves(int frequency, int octaves, int size, int seed, unsigned purpose) {
    std::vector<WorleyOctave> result;
    float total = 0.0f;
    for (int k = 0, period = frequency; k < octaves && 2 * period <= size; ++k, period *= 2) {
        const float weight = std::ldexp(1.0f, -k);
        result.push_back({period, seedStream(seed, purpose + static_cast<unsigned>(k)), weight});
        total += weight;
    }
    for (WorleyOctave& o : result) o.weight /= total;
    return result;
}

// Worley F1 along one row of voxels (fixed y and z): the feature offsets of the 3 x 3 rows of
// cells around the row's cell row, every cell of the period once, and worleyF1's own
// arithmetic over them (shaders/noise/worley.glsl), so the value is noise::worley(p, period,
// stream) bit for bit (tests/test_cloud_volume.cpp checks) at a fraction of the hashing.
class WorleyRows {
public:
    explicit WorleyRows(const WorleyOctave& octave) : octave_(octave) {
        offsets_.resize(9 * static_cast<std::size_t>(octave.period));
    }

    // Prepares the rows of cells around cell row (cy, cz), both in [0, period).
    void select(int cy, int cz) {
        if (cy == cy_ && cz == cz_) return;
        cy_ = cy;
        cz_ = cz;
        const int n = octave_.period;
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i)
                for (int cx = 0; cx < n; ++cx)
                    offsets_[static_cast<std::size_t>((j * 3 + i) * n + cx)] = worleyFeatureOffset(
                        glm::ivec3(cx, cy + i - 1, cz + j - 1), static_cast<float>(n), octave_.stream);
    }

    // F1 at p, whose cell is (cx, cy_, cz_) with local coordinates `local` in [0, 1]^3.
    float f1(int cx, glm::vec3 local) const {
        const int n = octave_.period;
        float nearest2 = 1.0e9f;
        for (int dz = -1; dz <= 1; dz++)
            for (int dy = -1; dy <= 1; dy++) {
                const glm::vec3* row = &offsets_[static_cast<std::size_t>(((dz + 1) * 3 + dy + 1) * n)];
                for (int dx = -1; dx <= 1; dx++) {
                    int x = cx + dx;
                    x = x < 0 ? x + n : x >= n ? x - n : x;
                    const glm::vec3 d = glm::vec3(float(dx), float(dy), float(dz)) + row[x] - local;
                    nearest2 = std::min(nearest2, glm::dot(d, d));
                }
            }
        return std::sqrt(nearest2);
    }

private:
    WorleyOctave octave_;
    std::vector<glm::vec3> offsets_;
    int cy_ = -1, cz_ = -1;
};

float remap(float v, float lo, float hi, float newLo, float newHi) {
    return newLo + (v - lo) * (newHi - newLo) / std::max(hi - lo, 1.0e-6f);
}

// Inverted Worley fBm at tile coordinate u; f1(k, p) is octave k's F1 at p (cells).
template <class F1>
float invertedWorleyFbm(const std::vector<WorleyOctave>& octaves, glm::vec3 u, const F1& f1) {
    float sum = 0.0f;
    for (std::size_t k = 0; k < octaves.size(); ++k)
        sum += octaves[k].weight * (1.0f - std::min(f1(k, u * static_cast<float>(octaves[k].period)), 1.0f));
    return sum;
}

// The noises of a bake and how they combine into the raw value (cloud_volume.h, "Bake").
struct NoiseLayout {
    explicit NoiseLayout(const CloudVolumeParams& p)
        : shape(worleyOctaves(p.shapeFrequency, p.shapeOctaves, p.size, p.seed, kShapeWorleyStream)),
          detail(worleyOctaves(p.detailFrequency, p.detailOctaves, p.size, p.seed, kDetailWorleyStream)),
          perlinStream(seedStream(p.seed, kPerlinStream)),
          shapeCells(static_cast<float>(p.shapeFrequency)),
          erosion(static_cast<float>(p.erosion)) {
        // Perlin octaves with at least 2 voxels a cell, like the Worley ones.
        for (int period = p.shapeFrequency; perlinOctaves < p.shapeOctaves && 2 * period <= p.size; period *= 2)
            ++perlinOctaves;
    }

    // The raw value at tile coordinate u; shapeF1 and detailF1 as invertedWorleyFbm's f1.
    template <class ShapeF1, class DetailF1>
    float value(glm::vec3 u, const ShapeF1& shapeF1, const DetailF1& detailF1) const {
        const float perlin =
            perlinOctaves > 0 ? 0.5f + 0.5f * perlinFbmTiled(u * shapeCells, shapeCells, perlinOctaves, 0.5f, perlinStream)
                              : 0.5f;
        const float worley = shape.empty() ? 1.0f : invertedWorleyFbm(shape, u, shapeF1);
        const float base = remap(perlin, worley - 1.0f, 1.0f, 0.0f, 1.0f);
        const float eroding = detail.empty() ? 0.0f : erosion * invertedWorleyFbm(detail, u, detailF1);
        return remap(base, eroding, 1.0f, 0.0f, 1.0f);
    }

    std::vector<WorleyOctave> shape, detail;
    unsigned perlinStream;
    float shapeCells, erosion;
    int perlinOctaves = 0;
};

glm::vec3 tileCoordinate(int x, int y, int z, int n) {
    return (glm::vec3(float(x), float(y), float(z)) + 0.5f) / static_cast<float>(n);
}

}  // namespace

float cloudVolumeNoiseAt(const CloudVolumeParams& params, int x, int y, int z) {
    validate(params);
    const NoiseLayout layout(params);
    auto reference = [](const std::vector<WorleyOctave>& octaves) {
        return [&octaves](std::size_t k, glm::vec3 p) {
            return worley(p, static_cast<float>(octaves[k].period), octaves[k].stream);
        };
    };
    return layout.value(tileCoordinate(x, y, z, params.size), reference(layout.shape), reference(layout.detail));
}

std::vector<float> bakeCloudVolumeNoise(const CloudVolumeParams& params, const BakeProgress& progress) {
    validate(params);
    const int n = params.size;
    const NoiseLayout layout(params);
    std::vector<float> values(static_cast<std::size_t>(n) * n * n);
    cloud_bake::parallelFor(
        n,
        [&](int z) {
            std::vector<WorleyRows> shapeRows(layout.shape.begin(), layout.shape.end()),
                detailRows(layout.detail.begin(), layout.detail.end());
            auto fast = [](std::vector<WorleyRows>& rows) {
                return [&rows](std::size_t k, glm::vec3 p) {
                    const glm::vec3 cellOrigin = glm::floor(p);
                    const glm::ivec3 cell(cellOrigin);
                    rows[k].select(cell.y, cell.z);
                    return rows[k].f1(cell.x, p - cellOrigin);
                };
            };
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                    values[(static_cast<std::size_t>(z) * n + static_cast<std::size_t>(y)) * n + static_cast<std::size_t>(x)] =
                        layout.value(tileCoordinate(x, y, z, n), fast(shapeRows), fast(detailRows));
        },
        progress, 0.0, 0.9);
    return values;
}

namespace {

// ------------------------------------------------------------------ border

// One pass of the capped Chebyshev distance transform along `axis`: every line of the
// volume along it becomes d'(i) = min over |k| <= border of max(|k|, d(i + k)), wrapping.
void distancePass(std::vector<std::uint8_t>& distance, int n, int axis, int border) {
    const std::size_t stride = axis == 0 ? 1 : axis == 1 ? static_cast<std::size_t>(n) : static_cast<std::size_t>(n) * n;
    cloud_bake::parallelFor(
        n * n,
        [&](int line) {
            // The first voxel of the line: the two other coordinates from `line`.
            const std::size_t a = static_cast<std::size_t>(line % n), b = static_cast<std::size_t>(line / n);
            const std::size_t first = axis == 0   ? b * n * n + a * n
                                      : axis == 1 ? b * n * n + a
                                                  : b * n + a;
            std::vector<std::uint8_t> in(static_cast<std::size_t>(n + 2 * border));  // the line, wrapped, padded
            for (int i = -border; i < n + border; ++i) {
                const int wrapped = ((i % n) + n) % n;
                in[static_cast<std::size_t>(i + border)] = distance[first + static_cast<std::size_t>(wrapped) * stride];
            }
            for (int i = 0; i < n; ++i) {
                int d = in[static_cast<std::size_t>(i + border)];
                for (int k = 1; k <= border && k < d; ++k)
                    d = std::min(d, std::max(k, static_cast<int>(std::min(in[static_cast<std::size_t>(i + border - k)],
                                                                           in[static_cast<std::size_t>(i + border + k)]))));
                distance[first + static_cast<std::size_t>(i) * stride] = static_cast<std::uint8_t>(d);
            }
        },
        {}, 0.0, 0.0);
}

}  // namespace

// ------------------------------------------------------------------ bake

CloudVolume bakeCloudVolume(const CloudVolumeParams& params, const BakeProgress& progress) {
    validate(params);
    const auto start = std::chrono::steady_clock::now();
    const int n = params.size;
    const std::size_t count = static_cast<std::size_t>(n) * n * n;
    CloudVolume volume;
    volume.size = n;
    volume.voxels = bakeCloudVolumeNoise(params, progress);  // (1)

    // (2) The threshold: the largest value that is not cloud, with `clouds` voxels above it.
    const auto clouds = static_cast<std::size_t>(
        std::clamp(std::llround(params.cloudFraction * static_cast<double>(count)), 1LL, static_cast<long long>(count) - 1));
    float threshold = 0.0f;
    {
        std::vector<float> sorted = volume.voxels;
        const auto kth = sorted.begin() + static_cast<std::ptrdiff_t>(count - clouds - 1);
        std::nth_element(sorted.begin(), kth, sorted.end());
        threshold = *kth;
    }
    if (progress) progress(0.93);

    // (3) Chebyshev distance to the nearest cloud voxel, capped at border + 1.
    const int border = params.borderVoxels;
    std::vector<std::uint8_t> distance(count);
    for (std::size_t i = 0; i < count; ++i)
        distance[i] = volume.voxels[i] > threshold ? 0 : static_cast<std::uint8_t>(border + 1);
    for (int axis = 0; axis < 3; ++axis) distancePass(distance, n, axis, border);
    if (progress) progress(0.98);

    // (4) Density, border or empty, in half precision. A cloud voxel's density is its rank
    // among the cloud voxels (k / clouds for the k-th smallest value): a monotone map of the
    // noise, so the shapes and their soft edges stay, with a uniform distribution, so that
    // keeping the values above 1 - c (the coverage remap) keeps the share c of the clouds.
    std::vector<std::uint32_t> cloudVoxels;
    cloudVoxels.reserve(clouds);
    for (std::size_t i = 0; i < count; ++i)
        if (volume.voxels[i] > threshold) cloudVoxels.push_back(static_cast<std::uint32_t>(i));
    std::sort(cloudVoxels.begin(), cloudVoxels.end(), [&](std::uint32_t a, std::uint32_t b) {
        return volume.voxels[a] < volume.voxels[b] || (volume.voxels[a] == volume.voxels[b] && a < b);
    });
    for (std::size_t i = 0; i < count; ++i)
        if (!(volume.voxels[i] > threshold)) volume.voxels[i] = distance[i] <= border ? kCloudBorder : kCloudEmpty;
    for (std::size_t k = 0; k < cloudVoxels.size(); ++k) {
        const float rank = static_cast<float>(static_cast<double>(k + 1) / static_cast<double>(cloudVoxels.size()));
        volume.voxels[cloudVoxels[k]] = static_cast<float>(Imath::half(std::max(rank, kCloudMinDensity)));
    }
    volume.stats = measureCloudVolume(volume);
    volume.stats.bakeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (progress) progress(1.0);
    return volume;
}

CloudVolumeStats measureCloudVolume(const CloudVolume& volume) {
    CloudVolumeStats s;
    std::size_t cloud = 0, border = 0;
    double densitySum = 0.0;
    for (const float v : volume.voxels) {
        if (v > 0.0f) {
            ++cloud;
            densitySum += v;
        } else if (v == 0.0f) {
            ++border;
        }
    }
    const double count = static_cast<double>(std::max<std::size_t>(volume.voxels.size(), 1));
    s.cloudFraction = static_cast<double>(cloud) / count;
    s.borderFraction = static_cast<double>(border) / count;
    s.emptyFraction = 1.0 - s.cloudFraction - s.borderFraction;
    s.meanDensity = cloud > 0 ? densitySum / static_cast<double>(cloud) : 0.0;
    return s;
}

std::vector<CloudVolume> cloudVolumeMips(const CloudVolume& volume, int levels) {
    std::vector<CloudVolume> mips;
    mips.reserve(static_cast<std::size_t>(std::max(levels, 1)));  // `above` points into it
    const CloudVolume* above = &volume;
    for (int level = 1; level < levels && above->size >= 2; ++level) {
        CloudVolume mip;
        mip.size = above->size / 2;
        mip.voxels.resize(static_cast<std::size_t>(mip.size) * mip.size * mip.size);
        for (int z = 0; z < mip.size; ++z)
            for (int y = 0; y < mip.size; ++y)
                for (int x = 0; x < mip.size; ++x) {
                    double sum = 0.0;
                    for (int k = 0; k < 8; ++k) sum += above->at(2 * x + (k & 1), 2 * y + ((k >> 1) & 1), 2 * z + (k >> 2));
                    mip.voxels[mip.index(x, y, z)] = static_cast<float>(Imath::half(static_cast<float>(sum / 8.0)));
                }
        mips.push_back(std::move(mip));
        above = &mips.back();
    }
    return mips;
}

std::vector<std::uint16_t> cloudVolumeHalf(const CloudVolume& volume) {
    std::vector<std::uint16_t> bits(volume.voxels.size());
    for (std::size_t i = 0; i < bits.size(); ++i) bits[i] = Imath::half(volume.voxels[i]).bits();
    return bits;
}

// ------------------------------------------------------------------ cache

namespace {

const CacheFormat kVolumeFormat{"cloud volume", "planet cloud density volume; see noise/cloud_volume.h",
                                "planetCloudVolumeKey", CachePixel::Half,
                                // Uncompressed: noise hardly compresses and the load is what a user waits for.
                                false};
constexpr const char* kVolumeFile = "cloud_volume.exr";

CacheFields checkedFields(int size) {
    return {{"version", std::to_string(kCloudVolumeVersion)}, {"size", std::to_string(size)}};
}

// One image of width size and height size^2 over the voxels (readCacheEntry fills them,
// writeCacheEntry only reads them).
std::vector<CacheImage> volumeImages(CloudVolume& volume) {
    return {{kVolumeFile, volume.size, volume.size * volume.size, {{"Y", volume.voxels.data(), sizeof(float)}}}};
}

}  // namespace

std::string cloudVolumeCacheKey(const CloudVolumeParams& p) {
    Fnv1a h;
    h.integer(kCloudVolumeVersion);
    // Fingerprint of the noise code: a change in the Perlin or Worley noise or the seed
    // streams changes the key even when kCloudVolumeVersion was not bumped.
    for (const glm::vec3 q : {glm::vec3(1.25f, -3.5f, 7.75f), glm::vec3(-41.3f, 17.9f, 0.37f)}) {
        h.number(perlinTiled(q, 4.0f, 3u));
        h.number(perlinFbmTiled(q, 8.0f, 6, 0.5f, 5u));
        h.number(worley(q, 16.0f, 7u));
    }
    h.integer(seedStream(p.seed, kPerlinStream));
    h.integer(p.seed);
    h.integer(p.size);
    h.integer(p.shapeFrequency);
    h.integer(p.shapeOctaves);
    h.integer(p.detailFrequency);
    h.integer(p.detailOctaves);
    h.number(p.erosion);
    h.number(p.cloudFraction);
    h.integer(p.borderVoxels);
    return hex16(h.value());
}

fs::path defaultCloudCacheRoot() { return defaultContinentsCacheRoot().parent_path() / "clouds"; }

void saveCloudVolume(const CloudVolume& volume, const CloudVolumeParams& p, const fs::path& dir, const std::string& key) {
    const int n = volume.size;
    if (n < 1 || volume.voxels.size() != static_cast<std::size_t>(n) * n * n)
        throw FileError("saveCloudVolume: the voxels do not match the size");
    CacheFields fields = checkedFields(n);
    fields.insert(fields.end(), {{"seed", std::to_string(p.seed)},
                                 {"shape_frequency", std::to_string(p.shapeFrequency)},
                                 {"shape_octaves", std::to_string(p.shapeOctaves)},
                                 {"detail_frequency", std::to_string(p.detailFrequency)},
                                 {"detail_octaves", std::to_string(p.detailOctaves)},
                                 {"erosion", exactText(p.erosion)},
                                 {"cloud_fraction", exactText(p.cloudFraction)},
                                 {"border_voxels", std::to_string(p.borderVoxels)}});
    writeCacheEntry(dir, kVolumeFormat, key, fields, volumeImages(const_cast<CloudVolume&>(volume)));
}

std::optional<CloudVolume> loadCloudVolume(const fs::path& dir, const std::string& expectedKey, int size,
                                           std::string* reason) {
    auto reject = [&](const std::string& why) -> std::optional<CloudVolume> {
        if (reason) *reason = why;
        return std::nullopt;
    };
    if (size < 16 || size > 512) return reject("size " + std::to_string(size) + " is outside [16, 512]");
    CloudVolume volume;
    volume.size = size;
    volume.voxels.assign(static_cast<std::size_t>(size) * size * size, 0.0f);
    if (!readCacheEntry(dir, kVolumeFormat, expectedKey, checkedFields(size), volumeImages(volume), reason))
        return std::nullopt;
    for (std::size_t i = 0; i < volume.voxels.size(); ++i) {
        const float v = volume.voxels[i];
        if (!(v == kCloudEmpty || v == kCloudBorder || (v >= kCloudMinDensity && v <= 1.0f)))
            return reject(quote(dir / kVolumeFile) + ": voxel " + std::to_string(i) + " holds " + std::to_string(v) +
                          ", not -1, 0 or a density in [2^-14, 1]");
    }
    volume.stats = measureCloudVolume(volume);
    return volume;
}

CloudVolume loadOrBakeCloudVolume(const CloudVolumeParams& params, const fs::path& root, const BakeProgress& progress) {
    validate(params);
    const std::string key = cloudVolumeCacheKey(params);
    const fs::path dir = root / ("volume-" + key);
    return loadOrBakeLogged(
        "cloud volume", std::to_string(params.size) + "^3 voxels, seed " + std::to_string(params.seed), dir,
        [&](std::string* reason) { return loadCloudVolume(dir, key, params.size, reason); },
        [&] {
            CloudVolume volume = bakeCloudVolume(params, alsoLogged(progress));
            logInfo("cloud volume: cloud " + std::to_string(volume.stats.cloudFraction) + ", border " +
                    std::to_string(volume.stats.borderFraction) + ", empty " + std::to_string(volume.stats.emptyFraction));
            return volume;
        },
        [&](const CloudVolume& volume) { saveCloudVolume(volume, params, dir, key); });
}

}  // namespace planet::noise
