// The baked cloud density volume (noise/cloud_volume.h), CPU only: the fast noise pass against
// the shared noise functions, tiling, the cloud fraction, Michelic's zero-density border
// (exact, and the guarantee it gives a march that filters trilinearly), half precision,
// determinism and seeds, and the cache (tier (a) and (d) of STYLE habit 9).
#include <gtest/gtest.h>

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>

#include <glm/glm.hpp>

#include "noise/cloud_volume.h"
#include "util/file_util.h"

using namespace planet;
namespace fs = std::filesystem;

namespace {

// Small enough for brute-force checks; 4 shape cells of 8 voxels, detail octaves 16 and 32
// cells per tile would alias, so only the first two are kept (2 voxels a cell at least).
noise::CloudVolumeParams smallParams(int size = 32) {
    noise::CloudVolumeParams p;
    p.size = size;
    p.detailFrequency = 8;
    return p;
}

// One bake per parameter set for the whole file.
const noise::CloudVolume& bakedSmall() {
    static const noise::CloudVolume volume = noise::bakeCloudVolume(smallParams());
    return volume;
}

int wrap(int i, int n) { return ((i % n) + n) % n; }

// The trilinearly filtered value at p in voxel units (voxel centres at integer + 0.5), GL_REPEAT.
float trilinear(const noise::CloudVolume& v, glm::vec3 p) {
    const glm::vec3 q = p - 0.5f;
    const glm::vec3 f = glm::floor(q);
    const glm::vec3 w = q - f;
    const glm::ivec3 c(f);
    float sum = 0.0f;
    for (int k = 0; k < 8; ++k) {
        const glm::ivec3 o(k & 1, (k >> 1) & 1, (k >> 2) & 1);
        const float weight = (o.x ? w.x : 1.0f - w.x) * (o.y ? w.y : 1.0f - w.y) * (o.z ? w.z : 1.0f - w.z);
        sum += weight * v.at(wrap(c.x + o.x, v.size), wrap(c.y + o.y, v.size), wrap(c.z + o.z, v.size));
    }
    return sum;
}

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(PLANET_TEST_OUT) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

}  // namespace

TEST(CloudVolume, FastNoisePassEqualsTheSharedNoiseFunctions) {
    // The bake's Worley F1 runs worleyF1's arithmetic over feature points hashed once per row
    // of cells; here every voxel checked against noise::worley's own 27 hashes. Default
    // frequencies at 64^3 (detail octaves 16 and 32 cells per tile).
    const noise::CloudVolumeParams p = smallParams(64);
    const std::vector<float> fast = noise::bakeCloudVolumeNoise(p);
    std::mt19937 rng(1);
    std::uniform_int_distribution<int> voxel(0, p.size - 1);
    float worst = 0.0f;
    for (int i = 0; i < 3000; ++i) {
        const int x = voxel(rng), y = voxel(rng), z = voxel(rng);
        const float reference = noise::cloudVolumeNoiseAt(p, x, y, z);
        worst = std::max(worst, std::abs(fast[(static_cast<std::size_t>(z) * 64 + y) * 64 + x] - reference));
    }
    EXPECT_EQ(worst, 0.0f);  // the same float operations in the same order
}

TEST(CloudVolume, NoiseTilesSoOppositeFacesContinueEachOther) {
    const noise::CloudVolumeParams p = smallParams();
    const int n = p.size;
    // The noise one voxel beyond a face is the noise at the opposite face.
    float worst = 0.0f;
    for (int a = 0; a < n; a += 3)
        for (int b = 0; b < n; b += 5) {
            worst = std::max(worst, std::abs(noise::cloudVolumeNoiseAt(p, n, a, b) - noise::cloudVolumeNoiseAt(p, 0, a, b)));
            worst = std::max(worst, std::abs(noise::cloudVolumeNoiseAt(p, a, -1, b) - noise::cloudVolumeNoiseAt(p, a, n - 1, b)));
            worst = std::max(worst, std::abs(noise::cloudVolumeNoiseAt(p, a, b, n) - noise::cloudVolumeNoiseAt(p, a, b, 0)));
        }
    EXPECT_LT(worst, 1.0e-4f);  // float rounding of u * period beyond the tile
    // And in the baked volume: the step across the wrap (last slice to first) is like any other.
    const noise::CloudVolume& v = bakedSmall();
    for (int axis = 0; axis < 3; ++axis) {
        double across = 0.0, inside = 0.0;
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) {
                auto at = [&](int i) {
                    return axis == 0 ? v.at(i, a, b) : axis == 1 ? v.at(a, i, b) : v.at(a, b, i);
                };
                across += std::abs(at(n - 1) - at(0));
                for (int i = 0; i + 1 < n; ++i) inside += std::abs(at(i + 1) - at(i)) / (n - 1);
            }
        std::printf("axis %d: mean |step| across the wrap %.4f, inside %.4f\n", axis, across / (n * n), inside / (n * n));
        EXPECT_LT(across, 1.5 * inside) << "axis " << axis;
    }
}

TEST(CloudVolume, CloudFractionIsTheTargetAndValuesAreCloudBorderOrEmptyInHalf) {
    for (const double fraction : {0.2, 0.4, 0.6}) {
        noise::CloudVolumeParams p = smallParams();
        p.cloudFraction = fraction;
        const noise::CloudVolume v = fraction == 0.4 ? bakedSmall() : noise::bakeCloudVolume(p);
        ASSERT_EQ(v.voxels.size(), static_cast<std::size_t>(32 * 32 * 32));
        std::size_t cloud = 0;
        for (const float value : v.voxels) {
            ASSERT_TRUE(value == -1.0f || value == 0.0f || (value >= noise::kCloudMinDensity && value <= 1.0f)) << value;
            ASSERT_EQ(static_cast<float>(Imath::half(value)), value);
            if (value > 0.0f) ++cloud;
        }
        EXPECT_NEAR(static_cast<double>(cloud) / static_cast<double>(v.voxels.size()), fraction, 1.0e-3);
        EXPECT_NEAR(v.stats.cloudFraction, fraction, 1.0e-3);
        EXPECT_NEAR(v.stats.cloudFraction + v.stats.borderFraction + v.stats.emptyFraction, 1.0, 1e-12);
        EXPECT_EQ(*std::max_element(v.voxels.begin(), v.voxels.end()), 1.0f);
        EXPECT_NEAR(v.stats.meanDensity, 0.5, 0.01) << "densities are ranks: uniform in (0, 1]";
    }
}

TEST(CloudVolume, BorderIsExactlyTheVoxelsWithinBorderVoxelsOfACloud) {
    // Brute force: a voxel < 0 has no cloud voxel within Chebyshev distance borderVoxels
    // (wrapped), a voxel == 0 has one. Also for a border of 1 and 7.
    for (const int border : {4, 1, 7}) {
        noise::CloudVolumeParams p = smallParams();
        p.borderVoxels = border;
        const noise::CloudVolume v = border == 4 ? bakedSmall() : noise::bakeCloudVolume(p);
        const int n = v.size;
        int wrong = 0;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const float value = v.at(x, y, z);
                    if (value > 0.0f) continue;
                    bool near = false;
                    for (int dz = -border; dz <= border && !near; ++dz)
                        for (int dy = -border; dy <= border && !near; ++dy)
                            for (int dx = -border; dx <= border && !near; ++dx)
                                near = v.at(wrap(x + dx, n), wrap(y + dy, n), wrap(z + dz, n)) > 0.0f;
                    if (near != (value == 0.0f)) ++wrong;
                }
        EXPECT_EQ(wrong, 0) << "border " << border;
    }
}

TEST(CloudVolume, NegativeFilteredValueMeansNoCloudWithinTheLargeStep) {
    // The renderer's guarantee (cloud_volume.h): where the trilinear value is < 0, it is <= 0
    // along any step of up to borderVoxels - 1 voxels. Random points and directions, the
    // step sampled finely.
    // A sparse volume (at 40 % cloud and a 4-voxel border a 32^3 tile has no empty voxel).
    noise::CloudVolumeParams params = smallParams();
    params.cloudFraction = 0.08;
    params.borderVoxels = 3;
    const noise::CloudVolume v = noise::bakeCloudVolume(params);
    ASSERT_GT(v.stats.emptyFraction, 0.05);
    const float step = static_cast<float>(params.borderVoxels - 1);
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> u(0.0f, static_cast<float>(v.size));
    std::normal_distribution<float> g(0.0f, 1.0f);
    int tested = 0, violations = 0;
    for (int attempt = 0; attempt < 400000 && tested < 4000; ++attempt) {
        const glm::vec3 p(u(rng), u(rng), u(rng));
        if (!(trilinear(v, p) < 0.0f)) continue;
        ++tested;
        const glm::vec3 d = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
        for (int i = 1; i <= 64; ++i)
            if (trilinear(v, p + d * (step * static_cast<float>(i) / 64.0f)) > 0.0f) {
                ++violations;
                break;
            }
    }
    EXPECT_EQ(tested, 4000);
    EXPECT_EQ(violations, 0);
}

TEST(CloudVolume, SameSeedSameBytesAnotherSeedAnotherVolume) {
    const noise::CloudVolume again = noise::bakeCloudVolume(smallParams());
    EXPECT_EQ(again.voxels, bakedSmall().voxels);
    noise::CloudVolumeParams other = smallParams();
    other.seed = 2;
    const noise::CloudVolume different = noise::bakeCloudVolume(other);
    std::size_t differs = 0;
    for (std::size_t i = 0; i < different.voxels.size(); ++i)
        if ((different.voxels[i] > 0.0f) != (bakedSmall().voxels[i] > 0.0f)) ++differs;
    // Two unrelated volumes with 40 % cloud disagree on about 2 * 0.4 * 0.6 = 48 % of the voxels.
    EXPECT_GT(static_cast<double>(differs) / static_cast<double>(different.voxels.size()), 0.3);
}

TEST(CloudVolume, HalfBitsAreTheVoxels) {
    const noise::CloudVolume& v = bakedSmall();
    const std::vector<std::uint16_t> bits = noise::cloudVolumeHalf(v);
    ASSERT_EQ(bits.size(), v.voxels.size());
    for (std::size_t i = 0; i < bits.size(); i += 7) {
        Imath::half h;
        h.setBits(bits[i]);
        ASSERT_EQ(static_cast<float>(h), v.voxels[i]);
    }
}

TEST(CloudVolume, RejectsParametersOutOfRange) {
    auto bake = [](auto change) {
        noise::CloudVolumeParams p = smallParams();
        change(p);
        return noise::bakeCloudVolume(p);
    };
    EXPECT_THROW(bake([](auto& p) { p.size = 8; }), std::invalid_argument);
    EXPECT_THROW(bake([](auto& p) { p.size = 1024; }), std::invalid_argument);
    EXPECT_THROW(bake([](auto& p) { p.shapeFrequency = 0; }), std::invalid_argument);
    EXPECT_THROW(bake([](auto& p) { p.erosion = 1.5; }), std::invalid_argument);
    EXPECT_THROW(bake([](auto& p) { p.cloudFraction = 1.0; }), std::invalid_argument);
    EXPECT_THROW(bake([](auto& p) { p.borderVoxels = 0; }), std::invalid_argument);
    EXPECT_THROW(bake([](auto& p) { p.borderVoxels = 33; }), std::invalid_argument);
}

TEST(CloudVolume, CacheRoundTripsAndRejectsDamageWithAReasonThenRebakes) {
    const fs::path root = freshDir("cloud_volume_cache");
    const noise::CloudVolumeParams p = smallParams();
    const std::string key = noise::cloudVolumeCacheKey(p);
    EXPECT_EQ(key.size(), 16u);
    const fs::path dir = root / ("volume-" + key);

    // First call bakes and saves; the second loads the same floats.
    const noise::CloudVolume baked = noise::loadOrBakeCloudVolume(p, root);
    EXPECT_EQ(baked.voxels, bakedSmall().voxels);
    ASSERT_TRUE(fs::exists(dir / "cloud_volume.exr"));
    ASSERT_TRUE(fs::exists(dir / "key.txt"));
    std::string reason;
    const std::optional<noise::CloudVolume> loaded = noise::loadCloudVolume(dir, key, p.size, &reason);
    ASSERT_TRUE(loaded) << reason;
    EXPECT_EQ(loaded->voxels, baked.voxels);
    EXPECT_EQ(loaded->stats.bakeSeconds, 0.0);
    EXPECT_EQ(loaded->stats.cloudFraction, baked.stats.cloudFraction);
    // HALF, uncompressed: two bytes a voxel and OpenEXR's line offsets and headers (16 bytes a row).
    EXPECT_LT(fs::file_size(dir / "cloud_volume.exr"), 32u * 32u * 32u * 3u);
    EXPECT_GT(fs::file_size(dir / "cloud_volume.exr"), 32u * 32u * 32u * 2u);

    // Wrong key, wrong size: refused with a reason.
    EXPECT_FALSE(noise::loadCloudVolume(dir, "0123456789abcdef", p.size, &reason));
    EXPECT_NE(reason.find("expected 0123456789abcdef"), std::string::npos) << reason;
    EXPECT_FALSE(noise::loadCloudVolume(dir, key, 64, &reason));
    EXPECT_NE(reason.find("size"), std::string::npos) << reason;

    // One flipped byte in the middle of the pixels: damaged.
    {
        std::string bytes = readFile(dir / "cloud_volume.exr");
        bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x40);
        writeFileAtomic(dir / "cloud_volume.exr", bytes);
    }
    EXPECT_FALSE(noise::loadCloudVolume(dir, key, p.size, &reason));
    EXPECT_NE(reason.find("damaged"), std::string::npos) << reason;
    const noise::CloudVolume rebaked = noise::loadOrBakeCloudVolume(p, root);
    EXPECT_EQ(rebaked.voxels, baked.voxels);
    EXPECT_TRUE(noise::loadCloudVolume(dir, key, p.size, &reason)) << reason;

    // A well-formed entry holding a value that is not -1, 0 or a density: refused on its values.
    noise::CloudVolume bad = baked;
    bad.voxels[5] = -0.5f;
    noise::saveCloudVolume(bad, p, dir, key);
    EXPECT_FALSE(noise::loadCloudVolume(dir, key, p.size, &reason));
    EXPECT_NE(reason.find("voxel 5"), std::string::npos) << reason;

    // Another parameter, another key.
    noise::CloudVolumeParams other = p;
    other.erosion = 0.3;
    EXPECT_NE(noise::cloudVolumeCacheKey(other), key);
}

TEST(CloudVolume, CacheRootIsTheSiblingOfTheContinents) {
    EXPECT_EQ(noise::defaultCloudCacheRoot().filename(), "clouds");
    EXPECT_EQ(noise::defaultCloudCacheRoot().parent_path(), noise::defaultContinentsCacheRoot().parent_path());
}
