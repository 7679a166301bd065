// The atmosphere tables from the cache or precomputed (src/atmosphere/table_store.h): the
// first call computes and saves, the next is a hit that computes nothing, --force and a
// damaged entry compute again (the latter saying why), NaN tables are returned but not
// cached, and the GPU variant uploads what the CPU one would read. CPU tests use a fake
// computation (synthetic tables); the GPU test precomputes reduced tables under a
// headless context.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "atmosphere/parameters.h"
#include "atmosphere/table_cache.h"
#include "atmosphere/table_store.h"
#include "gl_test_support.h"
#include "test_util.h"
#include "util/file_util.h"

namespace fs = std::filesystem;
using namespace planet;
using namespace planet::atmosphere;
using test::contains;

namespace {

AtmosphereParameters earth() { return makeAtmosphereParameters(Scene{}); }
fs::path shaderRoot() { return test::repoPaths().shaders(); }
constexpr int kOrders = 2;

fs::path freshRoot(const std::string& name) {
    const fs::path root = fs::path(PLANET_TEST_OUT) / "table_store" / name;
    fs::remove_all(root);
    return root;
}

// A stand-in for the precomputation: distinct finite values, two named steps.
AtmosphereTables fakeTables(const TableSizes& sizes, double bad = 0.5) {
    AtmosphereTables t(sizes);
    double v = 0.25;
    for (std::vector<glm::dvec4>* texels :
         {&t.transmittance.texels, &t.scattering.texels, &t.singleMie.texels, &t.irradiance.texels})
        for (glm::dvec4& texel : *texels) texel = glm::dvec4(v += 0.5, 1.0, 2.0, bad);
    return t;
}

}  // namespace

TEST(TableStore, ComputesOnceThenHitsForcesAndRebuildsADamagedEntry) {
    const fs::path root = freshRoot("cpu");
    const TableSizes sizes = TableSizes::reduced();
    int computed = 0;
    std::vector<std::string> steps, told;
    const ComputeTablesFn compute = [&](const ProgressFn& onStep) {
        ++computed;
        onStep({"transmittance", 0.0});
        onStep({"order 2", 0.0});
        return fakeTables(sizes);
    };
    TableStoreOptions options;
    options.onStep = [&](const PrecomputeStep& s) { steps.push_back(s.name); };
    std::vector<std::string> keys;
    options.onCompute = [&](const TableStoreReport& r) {
        told.push_back(r.forced ? "forced" : r.rejected.empty() ? "none" : "rejected: " + r.rejected);
        keys.push_back(r.key);
    };
    TableStoreReport report;

    AtmosphereTables first = loadOrComputeTables(compute, earth(), sizes, kOrders, root, shaderRoot(), options, &report);
    EXPECT_EQ(computed, 1);
    EXPECT_FALSE(report.hit);
    EXPECT_EQ(report.notSaved, "");
    EXPECT_EQ(report.dir, root / report.key);
    EXPECT_EQ(steps, (std::vector<std::string>{"transmittance", "order 2"}));
    EXPECT_EQ(told, (std::vector<std::string>{"none"}));
    EXPECT_EQ(keys, (std::vector<std::string>{tableCacheKey(earth(), sizes, kOrders, atmosphereModelSource(shaderRoot()))}));
    EXPECT_EQ(report.key, keys[0]);
    ASSERT_TRUE(loadTables(report.dir, report.key, sizes));

    const AtmosphereTables second =
        loadOrComputeTables(compute, earth(), sizes, kOrders, root, shaderRoot(), options, &report);
    EXPECT_TRUE(report.hit);
    EXPECT_EQ(computed, 1);
    EXPECT_EQ(told.size(), 1u);  // nothing to say before a hit
    EXPECT_EQ(second.scattering.texels, first.scattering.texels);  // these values are exact in float

    options.force = true;
    loadOrComputeTables(compute, earth(), sizes, kOrders, root, shaderRoot(), options, &report);
    EXPECT_EQ(computed, 2);
    EXPECT_TRUE(report.forced);
    options.force = false;

    writeFileAtomic(report.dir / "irradiance.exr", "damaged");
    loadOrComputeTables(compute, earth(), sizes, kOrders, root, shaderRoot(), options, &report);
    EXPECT_EQ(computed, 3);
    EXPECT_TRUE(contains(report.rejected, "irradiance.exr")) << report.rejected;
    ASSERT_EQ(told.size(), 3u);
    EXPECT_TRUE(contains(told[2], "rejected: ")) << told[2];
    EXPECT_TRUE(loadTables(report.dir, report.key, sizes));  // saved again

    // Another number of orders is another entry.
    loadOrComputeTables(compute, earth(), sizes, kOrders + 1, root, shaderRoot(), options, &report);
    EXPECT_EQ(computed, 4);
    EXPECT_NE(report.key, keys[0]);
    EXPECT_EQ(std::distance(fs::directory_iterator(root), fs::directory_iterator()), 2);
}

TEST(TableStore, NonFiniteTablesAreReturnedButNotCached) {
    const fs::path root = freshRoot("nan");
    const TableSizes sizes = TableSizes::reduced();
    const ComputeTablesFn compute = [&](const ProgressFn&) {
        return fakeTables(sizes, std::numeric_limits<double>::quiet_NaN());
    };
    TableStoreReport report;
    const AtmosphereTables t = loadOrComputeTables(compute, earth(), sizes, kOrders, root, shaderRoot(), {}, &report);
    EXPECT_TRUE(std::isnan(t.irradiance.texels[0].a));
    EXPECT_TRUE(contains(report.notSaved, "NaN or Inf")) << report.notSaved;
    EXPECT_FALSE(fs::exists(report.dir));
}

class TableStoreGpu : public test::GLTest {};

TEST_F(TableStoreGpu, UploadsFromTheCacheWhatItPrecomputedAndSaved) {
    const fs::path root = freshRoot("gpu");
    GpuPrecompute precompute(shaderRoot(), TableSizes::reduced());
    TableStoreReport report;
    const GpuTables computed = loadOrComputeTables(precompute, earth(), kOrders, root, shaderRoot(), {}, &report);
    EXPECT_FALSE(report.hit);
    EXPECT_EQ(report.notSaved, "");
    EXPECT_GT(report.seconds, 0.0);
    const GpuTables cached = loadOrComputeTables(precompute, earth(), kOrders, root, shaderRoot(), {}, &report);
    EXPECT_TRUE(report.hit);
    // The cache stores RGBA32F, what the GPU holds: the upload is the computation, bit for bit.
    const AtmosphereTables a = readBack(computed), b = readBack(cached);
    EXPECT_EQ(a.transmittance.texels, b.transmittance.texels);
    EXPECT_EQ(a.scattering.texels, b.scattering.texels);
    EXPECT_EQ(a.singleMie.texels, b.singleMie.texels);
    EXPECT_EQ(a.irradiance.texels, b.irradiance.texels);
    // And the CPU variant reads the same entry without computing.
    const AtmosphereTables cpu = loadOrComputeTables(
        [](const ProgressFn&) -> AtmosphereTables { throw std::logic_error("computed"); }, earth(),
        TableSizes::reduced(), kOrders, root, shaderRoot(), {}, &report);
    EXPECT_TRUE(report.hit);
    EXPECT_EQ(cpu.scattering.texels, a.scattering.texels);
}
