// The atmosphere table cache (src/atmosphere/table_cache.h), CPU only: the key
// follows every input, tables round trip through the EXR files to float
// precision, and a damaged, foreign or non-finite cache is never trusted.
// Tier (d) of STYLE habit 9.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <set>
#include <sstream>
#include <string>

#include "atmosphere/parameters.h"
#include "atmosphere/reference_tables.h"
#include "atmosphere/table_cache.h"
#include "test_util.h"
#include "util/file_util.h"

namespace fs = std::filesystem;
using namespace planet;
using namespace planet::atmosphere;

namespace {

AtmosphereParameters earth() { return makeAtmosphereParameters(Scene{}); }

// Tables of the given sizes filled with distinct values, none exactly representable in float.
AtmosphereTables syntheticTables(const TableSizes& sizes) {
    AtmosphereTables t;
    t.sizes = sizes;
    t.transmittance = Table2D(sizes.transmittance_width, sizes.transmittance_height);
    t.scattering = Table3D(sizes.scatteringSize());
    t.singleMie = Table3D(sizes.scatteringSize());
    t.irradiance = Table2D(sizes.irradiance_width, sizes.irradiance_height);
    double v = 0.1;
    for (std::vector<glm::dvec4>* texels :
         {&t.transmittance.texels, &t.scattering.texels, &t.singleMie.texels, &t.irradiance.texels})
        for (glm::dvec4& texel : *texels) {
            texel = glm::dvec4(v, 2.0 * v + 1e-9, std::sin(v), 1.0 / (1.0 + v));
            v += 0.0137;
        }
    return t;
}

// Largest |a - b| / max(|b|, 1e-30) over all texels of all tables.
double maxRelativeDifference(const AtmosphereTables& a, const AtmosphereTables& b) {
    double worst = 0.0;
    const std::vector<glm::dvec4>* as[4] = {&a.transmittance.texels, &a.scattering.texels, &a.singleMie.texels,
                                            &a.irradiance.texels};
    const std::vector<glm::dvec4>* bs[4] = {&b.transmittance.texels, &b.scattering.texels, &b.singleMie.texels,
                                            &b.irradiance.texels};
    for (int t = 0; t < 4; ++t) {
        if (as[t]->size() != bs[t]->size()) return INFINITY;
        for (std::size_t i = 0; i < as[t]->size(); ++i)
            for (int c = 0; c < 4; ++c)
                worst = std::max(worst, std::abs((*as[t])[i][c] - (*bs[t])[i][c]) /
                                            std::max(std::abs((*bs[t])[i][c]), 1e-30));
    }
    return worst;
}

class TableCache : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::path(PLANET_TEST_OUT) / "table_cache" / info->name();
        fs::remove_all(dir);
    }
    // A saved synthetic cache entry; returns its folder.
    fs::path saveSynthetic(const std::string& key = "0123456789abcdef") {
        const fs::path entry = dir / key;
        saveTables(syntheticTables(sizes), entry, key);
        return entry;
    }
    void expectRejected(const fs::path& entry, const std::string& key, const std::string& reasonPart) {
        std::string reason;
        EXPECT_FALSE(loadTables(entry, key, sizes, &reason).has_value());
        EXPECT_TRUE(test::contains(reason, reasonPart)) << "reason: " << reason;
    }
    TableSizes sizes = TableSizes::reduced();
    fs::path dir;
};

// FNV-1a of a file's bytes, as key.txt records it (to forge a matching checksum).
std::string fnv1aHex(const std::string& bytes) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : bytes) {
        h ^= c;
        h *= 0x100000001b3ull;
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

// Rewrites key.txt's checksum line for `file` to match its current bytes.
void forgeChecksum(const fs::path& entry, const std::string& file) {
    std::istringstream in(readFile(entry / "key.txt"));
    std::string out, line;
    while (std::getline(in, line))
        out += (line.starts_with(file + " ") ? file + " " + fnv1aHex(readFile(entry / file)) : line) + "\n";
    writeFileAtomic(entry / "key.txt", out);
}

}  // namespace

TEST_F(TableCache, KeyIsStableAndChangesWithEveryInput) {
    const AtmosphereParameters base = earth();
    const std::string key = tableCacheKey(base, sizes, 4);
    EXPECT_EQ(key.size(), 16u);
    EXPECT_EQ(key.find_first_not_of("0123456789abcdef"), std::string::npos) << key;
    EXPECT_EQ(tableCacheKey(earth(), TableSizes::reduced(), 4), key);  // equal input, equal key

    // One change at a time; every resulting key must differ from the base and from each other.
    std::vector<std::function<void(AtmosphereParameters&)>> edits = {
        [](auto& a) { a.solar_irradiance.r *= 1.01; },  [](auto& a) { a.solar_irradiance.b *= 1.01; },
        [](auto& a) { a.sun_angular_radius *= 1.01; },  [](auto& a) { a.bottom_radius += 1.0; },
        [](auto& a) { a.top_radius += 1.0; },           [](auto& a) { a.rayleigh_density.layers[1].exp_scale *= 1.01; },
        [](auto& a) { a.rayleigh_density.layers[0].width = 1.0; },
        [](auto& a) { a.rayleigh_scattering.g *= 1.01; }, [](auto& a) { a.mie_density.layers[1].exp_term = 0.5; },
        [](auto& a) { a.mie_scattering.r *= 1.01; },    [](auto& a) { a.mie_extinction.b *= 1.01; },
        [](auto& a) { a.mie_phase_function_g = 0.7; },  [](auto& a) { a.absorption_density.layers[0].linear_term *= 1.01; },
        [](auto& a) { a.absorption_density.layers[1].constant_term *= 1.01; },
        [](auto& a) { a.absorption_extinction.g *= 1.01; }, [](auto& a) { a.ground_albedo.r = 0.3; },
        [](auto& a) { a.mu_s_min = -0.3; },
    };
    std::set<std::string> keys{key};
    for (std::size_t i = 0; i < edits.size(); ++i) {
        AtmosphereParameters a = base;
        edits[i](a);
        EXPECT_TRUE(keys.insert(tableCacheKey(a, sizes, 4)).second) << "parameter edit " << i;
    }
    int TableSizes::*fields[] = {&TableSizes::transmittance_width, &TableSizes::transmittance_height,
                                 &TableSizes::scattering_r,        &TableSizes::scattering_mu,
                                 &TableSizes::scattering_mu_s,     &TableSizes::scattering_nu,
                                 &TableSizes::irradiance_width,    &TableSizes::irradiance_height};
    for (auto field : fields) {
        TableSizes s = sizes;
        s.*field += 1;
        EXPECT_TRUE(keys.insert(tableCacheKey(base, s, 4)).second) << "size field";
    }
    for (int orders : {1, 2, 3, 5, 10}) EXPECT_TRUE(keys.insert(tableCacheKey(base, sizes, orders)).second) << orders;
    // Elek's Rayleigh phase is applied at render time: the same tables serve both.
    AtmosphereParameters elek = base;
    elek.elek_rayleigh_phase = 1.0 - elek.elek_rayleigh_phase;
    EXPECT_EQ(tableCacheKey(elek, sizes, 4), key);
    // An edited model (its shader text) gives another key.
    const std::string source = atmosphereModelSource(fs::path(PLANET_SOURCE_DIR) / "shaders");
    EXPECT_NE(source.find("ComputeScatteringDensity"), std::string::npos);
    EXPECT_NE(source.find("multiple_scattering.comp"), std::string::npos);
    EXPECT_NE(tableCacheKey(base, sizes, 4, source), tableCacheKey(base, sizes, 4, source + " "));
}

TEST_F(TableCache, DefaultRootFollowsPlanetCache) {
    const char* old = std::getenv("PLANET_CACHE");
    const std::string saved = old ? old : "";
    ::unsetenv("PLANET_CACHE");
    EXPECT_EQ(defaultTableCacheRoot(), fs::path("cache") / "atmosphere");
    ::setenv("PLANET_CACHE", "/tmp/somewhere", 1);
    EXPECT_EQ(defaultTableCacheRoot(), fs::path("/tmp/somewhere"));
    if (old)
        ::setenv("PLANET_CACHE", saved.c_str(), 1);
    else
        ::unsetenv("PLANET_CACHE");
}

TEST_F(TableCache, ReferenceTablesRoundTripToFloatPrecision) {
    const ReferenceResult ref = computeReferenceTables(earth(), sizes, 2);
    const std::string key = tableCacheKey(earth(), sizes, 2);
    const fs::path entry = dir / key;
    saveTables(ref.tables, entry, key);
    for (const char* file : {"transmittance.exr", "scattering.exr", "single_mie.exr", "irradiance.exr", "key.txt"})
        EXPECT_TRUE(fs::exists(entry / file)) << file;
    // Nothing temporary left beside the entry.
    int siblings = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++siblings;
    EXPECT_EQ(siblings, 1);

    std::string reason;
    const std::optional<AtmosphereTables> loaded = loadTables(entry, key, sizes, &reason);
    ASSERT_TRUE(loaded.has_value()) << reason;
    EXPECT_EQ(loaded->sizes, sizes);
    EXPECT_EQ(loaded->scattering.depth, ref.tables.scattering.depth);
    // Stored as 32-bit float: half an ulp of relative error at most.
    EXPECT_LE(maxRelativeDifference(*loaded, ref.tables), 0.5 * std::numeric_limits<float>::epsilon());

    // Saving again over an existing entry replaces it.
    saveTables(syntheticTables(sizes), entry, key);
    const auto again = loadTables(entry, key, sizes, &reason);
    ASSERT_TRUE(again.has_value()) << reason;
    EXPECT_LE(maxRelativeDifference(*again, syntheticTables(sizes)), 0.5 * std::numeric_limits<float>::epsilon());
}

TEST_F(TableCache, MissingFolderOrFileIsRejected) {
    expectRejected(dir / "nothing", "0123456789abcdef", "no cache folder");
    const fs::path entry = saveSynthetic();
    fs::remove(entry / "single_mie.exr");
    expectRejected(entry, "0123456789abcdef", "single_mie.exr");
    const fs::path other = saveSynthetic("00000000000000ff");
    fs::remove(other / "key.txt");
    expectRejected(other, "00000000000000ff", "key.txt");
}

TEST_F(TableCache, TruncatedFileIsRejected) {
    const fs::path entry = saveSynthetic();
    const std::string bytes = readFile(entry / "scattering.exr");
    writeFileAtomic(entry / "scattering.exr", bytes.substr(0, bytes.size() / 2));
    expectRejected(entry, "0123456789abcdef", "scattering.exr");
    // Even with a checksum that matches the truncated bytes, OpenEXR's failure is a rejection.
    forgeChecksum(entry, "scattering.exr");
    expectRejected(entry, "0123456789abcdef", "OpenEXR");
}

TEST_F(TableCache, OverwrittenBytesAreRejected) {
    const fs::path entry = saveSynthetic();
    std::string bytes = readFile(entry / "transmittance.exr");
    for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 16; ++i) bytes[i] = static_cast<char>(0x5a);
    writeFileAtomic(entry / "transmittance.exr", bytes);
    expectRejected(entry, "0123456789abcdef", "damaged");
}

TEST_F(TableCache, WrongKeyOrSizesAreRejected) {
    const fs::path entry = saveSynthetic();
    expectRejected(entry, "fedcba9876543210", "expected fedcba9876543210");
    TableSizes other = sizes;
    other.scattering_nu = 2;
    std::string reason;
    EXPECT_FALSE(loadTables(entry, "0123456789abcdef", other, &reason).has_value());
    EXPECT_TRUE(test::contains(reason, "sizes")) << reason;
    // A file copied in from another entry carries that entry's key in its header.
    const fs::path foreign = saveSynthetic("00000000000000aa");
    fs::copy_file(foreign / "irradiance.exr", entry / "irradiance.exr", fs::copy_options::overwrite_existing);
    forgeChecksum(entry, "irradiance.exr");
    expectRejected(entry, "0123456789abcdef", "header key");
}

TEST_F(TableCache, NonFiniteTexelsAreRejected) {
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        AtmosphereTables t = syntheticTables(sizes);
        t.scattering.at(3, 2, 1).g = bad;
        const fs::path entry = dir / "0123456789abcdef";
        saveTables(t, entry, "0123456789abcdef");
        expectRejected(entry, "0123456789abcdef", "scattering.exr");
    }
}
