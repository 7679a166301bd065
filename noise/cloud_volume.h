// Cloud density volume: a tiling 3D texture of cloud density with the zero-density border of
// Michelic §5 (fig. 9), baked on the CPU from the shared noise, and its cache.
//
// Michelic §5 "Modeling" precomputes simplex and Worley noise into one 256^3 16-bit float
// texture, tiled across the planet every w (Eq. 12, c = fract(p / w)); values >= 0 are cloud
// material, < 0 no cloud, and around every cloud a border of zero density as wide as the
// large march step, so that the sampled value alone chooses a small step (>= 0: in or near a
// cloud) or a large one (< 0: nothing within the border), with no step back. Eq. 13's height
// signal h and Eq. 14's density (-1 where tex < 0, else h tex) are the renderer's.
//
// Layout. `size`^3 voxels, voxels[(z * size + y) * size + x]: x fastest, then rows y, then
// slices z, exactly what glTexImage3D reads, so the volume uploads as it is (GL_R16F from
// cloudVolumeHalf(), GL_REPEAT on all three axes, GL_LINEAR). Voxel (x, y, z) is the value
// at texture coordinate ((x + 0.5) / size, (y + 0.5) / size, (z + 0.5) / size) of the tile.
//
// Values.
//   > 0   cloud, density in [2^-14, 1] (2^-14 is half float's smallest normal number, so a
//         cloud voxel stays > 0 in half precision);
//   0     not cloud, but a cloud voxel within `borderVoxels` (Chebyshev distance, tiling:
//         max over the axes of the wrapped index difference <= borderVoxels);
//   -1    not cloud and no cloud voxel within borderVoxels.
// What a renderer may rely on: where the trilinearly filtered value at a point x is < 0 (one
// of the 8 voxels around x, weighted > 0, is -1, hence no cloud voxel within borderVoxels of
// it), the filtered value is <= 0 everywhere within Chebyshev distance borderVoxels - 1 voxels
// of x, so a large step of at most (borderVoxels - 1) voxels, tile width w / size each,
// skips no cloud. (A cloud voxel v adds density at y only if |y - v| < 1 voxel in every axis;
// the -1 voxel c is within 1 voxel of x; |c - v| >= borderVoxels + 1.) A coverage remap that
// only lowers values keeps this; one that turns a 0 or -1 into cloud does not.
//
// Bake (Schneider, "The real-time volumetric cloudscapes of Horizon Zero Dawn", SIGGRAPH 2015
// course; Hillaire, "Physically based sky, atmosphere and cloud rendering in Frostbite", 2016,
// and his TileableVolumeNoise): at the voxel's tile coordinate u in [0, 1)^3,
//   perlin  = 0.5 + 0.5 perlinFbmTiled(shapeFrequency u, shapeFrequency, shapeOctaves)  in [0, 1]
//   worley  = inverted Worley fBm: sum of 0.5^k (1 - F1) over octaves k with 2^k shapeFrequency
//             cells per tile, over the sum of weights (high near feature points: billows)
//   shape   = remap(perlin, worley - 1, 1, 0, 1)     (Schneider's Perlin-Worley "base cloud")
//   detail  = the same inverted Worley fBm with detailFrequency cells per tile
//   value   = remap(shape, erosion * detail, 1, 0, 1)    (the detail erodes the shapes' edges)
// with remap(v, a, b, c, d) = c + (v - a) (d - c) / (b - a). Every noise tiles with the
// volume (whole cells per tile), so opposite faces of the volume continue each other. Octaves
// with fewer than 2 voxels per cell are dropped (they would only alias). Then the threshold t
// with exactly round(cloudFraction size^3) voxels above it (fewer only where values tie),
// density = the voxel's rank among the cloud voxels, k / clouds for the k-th smallest value
// (at least 2^-14): a monotone map of the noise, so the shapes and their soft edges stay,
// with a uniform distribution, so that a coverage remap keeping values above 1 - c keeps
// the share c of the clouds; and the border by a separable
// Chebyshev distance transform (three 1D passes along x, y, z, wrapping, capped at
// borderVoxels + 1). Finally every value is rounded to half precision, so a fresh bake and a
// cached one are the same floats and the CPU sees what the GPU samples.
// Each noise and octave hashes its lattice with its own stream derived from the seed
// (noise::seedStream): an offset of a periodic noise's domain would only translate the tile.
// The Worley fBm runs the shared worleyF1 arithmetic over feature points hashed once per row
// of cells (the shared worleyFeatureOffset), not 27 hashes per voxel: the same values, an
// order of magnitude faster (noise/README.md has the times).
//
// Cache: one util/cache_entry.h entry <root>/volume-<key>/ holding cloud_volume.exr (one HALF
// channel "Y", width size, height size^2: slice z is rows z size .. z size + size - 1, row 0 =
// slice 0 row 0) and key.txt (key, version, size, parameters, checksum of the EXR bytes). The key hashes the
// parameters, kCloudVolumeVersion and a fingerprint of the noise functions, so a change of the
// noise code alone invalidates old entries. Written to a temporary folder and renamed into
// place; loadCloudVolume() trusts nothing (see there).
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "noise/continents.h"  // BakeProgress, logBakeProgress

namespace planet::noise {

// Bump when the bake (not the noise: that is fingerprinted) changes what it produces.
constexpr int kCloudVolumeVersion = 2;

// Values of a voxel that is not cloud (see the file header).
constexpr float kCloudBorder = 0.0f;  // a cloud voxel within borderVoxels
constexpr float kCloudEmpty = -1.0f;  // none within borderVoxels
// The smallest density of a cloud voxel: half float's smallest normal number, 2^-14.
constexpr float kCloudMinDensity = 1.0f / 16384.0f;

struct CloudVolumeParams {
    int seed = 1;               // any int; picks the lattices' streams (noise::seedStream)
    int size = 256;             // voxels per side of the tile, [16, 512]; 256^3 half = 32 MiB
    // Frequencies are whole numbers of cells per tile (the noise must tile with the volume).
    int shapeFrequency = 4;     // shape noise (Perlin and Worley) cells per tile, lowest octave, [1, 64]
    int shapeOctaves = 3;       // octaves of the shape's Perlin and Worley fBm (lacunarity 2), [1, 6]
    int detailFrequency = 16;   // erosion Worley cells per tile, lowest octave, [1, 256]
    int detailOctaves = 3;      // octaves of the erosion's Worley fBm (lacunarity 2), [1, 6]
    double erosion = 0.4;       // how deeply the detail eats into the shapes' edges, [0, 1]; 0: none
    double cloudFraction = 0.4; // share of the voxels that are cloud, [0.01, 0.99]
    int borderVoxels = 4;       // zero-density border around the clouds, voxels (Chebyshev), [1, 32];
                                // large march steps up to borderVoxels - 1 voxels are safe
    bool operator==(const CloudVolumeParams&) const = default;
};

struct CloudVolumeStats {
    double cloudFraction = 0.0;   // share of voxels > 0
    double borderFraction = 0.0;  // share of voxels == 0
    double emptyFraction = 0.0;   // share of voxels < 0
    double meanDensity = 0.0;     // mean value of the cloud voxels
    double bakeSeconds = 0.0;     // wall time of the bake; 0 when loaded from the cache
};

struct CloudVolume {
    int size = 0;                // voxels per side
    std::vector<float> voxels;   // size^3, index (z * size + y) * size + x; values rounded to half
    CloudVolumeStats stats;

    float at(int x, int y, int z) const { return voxels[index(x, y, z)]; }
    std::size_t index(int x, int y, int z) const {
        const auto n = static_cast<std::size_t>(size);
        return (static_cast<std::size_t>(z) * n + static_cast<std::size_t>(y)) * n + static_cast<std::size_t>(x);
    }
};

// The volume's mip levels 1 .. levels - 1 (fewer where the volume runs out of voxels), as
// glGenerateMipmap makes the GL texture's (a 2x2x2 box filter, each level from the one above,
// rounded to half): what the march samples where a pixel spans voxels (cloud_density.glsl,
// CloudVolumeLod), for the CPU reference of it.
std::vector<CloudVolume> cloudVolumeMips(const CloudVolume& volume, int levels);
// The levels the GL texture has (level 0 and three mips: a texel of the last spans 8 voxels,
// where the far field has taken over).
constexpr int kCloudVolumeMipLevels = 4;

// Bakes the volume (see the file header) on all cores. Throws std::invalid_argument for a
// parameter out of its range.
CloudVolume bakeCloudVolume(const CloudVolumeParams& params, const BakeProgress& progress = {});

// The raw value of every voxel (the bake's first pass, before the threshold: "value" in the
// file header), same order as CloudVolume::voxels, on all cores.
std::vector<float> bakeCloudVolumeNoise(const CloudVolumeParams& params, const BakeProgress& progress = {});

// The raw value of voxel (x, y, z) (any integers: the noise tiles) straight from the shared
// noise functions, 27 hashes per Worley F1: the reference bakeCloudVolumeNoise must equal.
float cloudVolumeNoiseAt(const CloudVolumeParams& params, int x, int y, int z);

// The shares of cloud, border and empty voxels and the clouds' mean density (bakeSeconds 0).
CloudVolumeStats measureCloudVolume(const CloudVolume& volume);

// The voxels as IEEE half floats (GL_HALF_FLOAT), same order: for glTexImage3D(GL_R16F).
std::vector<std::uint16_t> cloudVolumeHalf(const CloudVolume& volume);

// 16 hex digits: FNV-1a of kCloudVolumeVersion, a noise fingerprint and the parameters.
std::string cloudVolumeCacheKey(const CloudVolumeParams& params);

// Cache root of the clouds (the volume and the weather map): the sibling folder "clouds" of
// defaultContinentsCacheRoot(), i.e. cache/clouds, or "clouds" beside $PLANET_CACHE.
std::filesystem::path defaultCloudCacheRoot();

// Writes cloud_volume.exr and key.txt into `dir` atomically (temporary sibling folder, then
// rename; an existing entry is replaced). Throws FileError.
void saveCloudVolume(const CloudVolume& volume, const CloudVolumeParams& params, const std::filesystem::path& dir,
                     const std::string& key);

// The volume stored in `dir` if key.txt names `expectedKey`, this version and params.size,
// the EXR's checksum matches, OpenEXR reads it, its header key and size match, it has the
// HALF channel Y, and every value is -1, 0 or in [2^-14, 1]; otherwise nullopt with the
// reason in *reason. The stats are measured (bakeSeconds 0).
std::optional<CloudVolume> loadCloudVolume(const std::filesystem::path& dir, const std::string& expectedKey,
                                           int size, std::string* reason = nullptr);

// The volume for these parameters at run time: from the cache under `root`
// (<root>/volume-<key>/) when it holds a valid entry, else baked (progress on stderr after a
// second, and the time) and saved there. An unusable entry is reported (logWarning) and
// rebaked; a cache that cannot be written is reported and the baked volume used anyway.
// Throws std::invalid_argument for parameters out of range.
// `progress`, when given, is told the bake's progress too (from the calling thread).
CloudVolume loadOrBakeCloudVolume(const CloudVolumeParams& params, const std::filesystem::path& root,
                                  const BakeProgress& progress = {});

// ------------------------------------------------------------------ for the clouds' bakes

namespace cloud_bake {

// Runs task(i) for every i in [0, count) on all cores (the calling thread included, like
// bakeContinents); the calling thread reports progress(from + (to - from) * done / count).
template <class Task>
void parallelFor(int count, const Task& task, const BakeProgress& progress, double from, double to) {
    std::atomic<int> next{0}, done{0};
    auto worker = [&](bool caller) {
        for (int i = next++; i < count; i = next++) {
            task(i);
            const int finished = ++done;
            if (caller && progress) progress(from + (to - from) * finished / count);
        }
    };
    const int threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker, false);
    worker(true);
    for (std::thread& t : pool) t.join();
}

}  // namespace cloud_bake

}  // namespace planet::noise
