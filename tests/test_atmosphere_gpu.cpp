// The GPU precomputation (shaders/atmosphere/precompute/*.comp, single
// precision) against the CPU reference (the same functions in double), texel
// by texel, on reduced tables; plus the incremental job, the upload/readBack
// round trip, and an atmosphere without particles. Tier (c) of STYLE habit 9.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "atmosphere/parameters.h"
#include "atmosphere/precompute_gpu.h"
#include "atmosphere/reference_tables.h"
#include "gl_test_support.h"
#include "table_error.h"

using namespace planet;
using namespace planet::atmosphere;

namespace {

constexpr int kOrders = 4;

AtmosphereParameters earth() { return makeAtmosphereParameters(Scene{}); }

std::filesystem::path shaderRoot() { return std::filesystem::path(PLANET_SOURCE_DIR) / "shaders"; }

using test::TableError;

bool allFinite(const std::vector<glm::dvec4>& texels) {
    for (const glm::dvec4& v : texels)
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(v[c])) return false;
    return true;
}

double maxAbsDifference(const std::vector<glm::dvec4>& a, const std::vector<glm::dvec4>& b) {
    double d = 0.0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(a[i][c] - b[i][c]));
    return a.size() == b.size() ? d : INFINITY;
}

class AtmosphereGpu : public test::GLTest {
protected:
    // The CPU reference in double: costly, computed once for the suite.
    static const ReferenceResult& reference() {
        static const ReferenceResult r = computeReferenceTables(earth(), TableSizes::reduced(), kOrders);
        return r;
    }
    // The GPU tables (read back), computed once per suite: textures die with
    // the suite's context, their read back copies do not.
    static const AtmosphereTables& gpuEarth() {
        if (!gpuEarth_) {
            GpuPrecompute precompute(shaderRoot(), TableSizes::reduced());
            gpuEarth_ = readBack(precompute.compute(earth(), kOrders, [](const PrecomputeStep& s) {
                gpuSteps_.push_back(s);
            }));
        }
        return *gpuEarth_;
    }
    static void TearDownTestSuite() {
        gpuEarth_.reset();
        GLTest::TearDownTestSuite();
    }
    static inline std::optional<AtmosphereTables> gpuEarth_;
    static inline std::vector<PrecomputeStep> gpuSteps_;
};

TEST_F(AtmosphereGpu, MatchesCpuReferenceTexelByTexel) {
    const AtmosphereTables& gpu = gpuEarth();
    const AtmosphereTables& ref = reference().tables;
    ASSERT_EQ(gpu.sizes, ref.sizes);

    // Tolerance: 1% relative error per texel (floor: 1e-3 of the table's
    // maximum), for every texel of transmittance and irradiance. The two
    // scattering tables reach 1.02% (reduced sizes, llvmpipe and a CPU float
    // emulation of functions.glsl alike) in a handful of texels, for two
    // reasons inherent to evaluating the shared functions in single precision:
    //  - rays tangent to the ground (mu row next to the horizon split): the
    //    distance to the ground is recomputed from mu as -r mu - sqrt(disc),
    //    disc = r^2 (mu^2 - 1) + R^2 ~ 0 from terms ~4e7 km^2, so float
    //    rounding (a few km^2) becomes a ray up to 2 km (0.8%) short;
    //  - the ray's ground end: r_d comes out 1 ulp (0.5 m) above R, and the sun
    //    horizon factor sqrt(1 - (R/r)^2) has infinite slope at r = R, moving
    //    the horizon by 4e-4 rad (a tenth of the sun disc) when the sun sets there.
    // So those tables allow 1.5% at the worst texel but still 1% for all but
    // 0.1% of their texels (fixes belong in functions.glsl, see the report).
    struct Row {
        const char* name;
        const std::vector<glm::dvec4>& gpu;
        const std::vector<glm::dvec4>& ref;
        double maxTolerance;
    };
    const Row rows[] = {{"transmittance", gpu.transmittance.texels, ref.transmittance.texels, 0.01},
                        {"scattering", gpu.scattering.texels, ref.scattering.texels, 0.015},
                        {"single Mie", gpu.singleMie.texels, ref.singleMie.texels, 0.015},
                        {"irradiance", gpu.irradiance.texels, ref.irradiance.texels, 0.01}};
    for (const Row& row : rows) {
        const TableError e = test::compareTables(row.gpu, row.ref);
        std::printf("  %-14s max relative error %.3e (texel %zu channel %d: gpu %.6e ref %.6e), %zu of %zu texels > 1%%\n",
                    row.name, e.maxRelative, e.worstTexel, e.worstChannel, e.gpu, e.ref, e.texelsOver1Percent,
                    row.ref.size());
        EXPECT_LT(e.maxRelative, row.maxTolerance) << row.name;
        EXPECT_LE(static_cast<double>(e.texelsOver1Percent), 1e-3 * static_cast<double>(row.ref.size())) << row.name;
    }

    // Same steps as the reference, in the same order.
    ASSERT_EQ(gpuSteps_.size(), reference().steps.size());
    for (std::size_t i = 0; i < gpuSteps_.size(); ++i) EXPECT_EQ(gpuSteps_[i].name, reference().steps[i].name);
}

TEST_F(AtmosphereGpu, TablesAreFinite) {
    const AtmosphereTables& gpu = gpuEarth();
    EXPECT_TRUE(allFinite(gpu.transmittance.texels));
    EXPECT_TRUE(allFinite(gpu.scattering.texels));
    EXPECT_TRUE(allFinite(gpu.singleMie.texels));
    EXPECT_TRUE(allFinite(gpu.irradiance.texels));
}

TEST_F(AtmosphereGpu, IncrementalJobMatchesBlockingCompute) {
    const AtmosphereTables& blocking = gpuEarth();
    GpuPrecompute precompute(shaderRoot(), TableSizes::reduced());
    std::vector<std::string> names;
    GpuPrecomputeJob job = precompute.start(earth(), kOrders, [&](const PrecomputeStep& s) { names.push_back(s.name); },
                                            /*layersPerChunk=*/3);  // 8 layers: uneven chunks on purpose
    double last = job.progress();
    EXPECT_EQ(last, 0.0);
    int chunks = 0;
    while (!job.step()) {
        ++chunks;
        EXPECT_GE(job.progress(), last);
        last = job.progress();
        ASSERT_LT(chunks, 1000);
    }
    EXPECT_DOUBLE_EQ(job.progress(), 1.0);
    EXPECT_GT(chunks, 3 + 3 * (kOrders - 1));  // the 3D passes really were split
    EXPECT_EQ(names, (std::vector<std::string>{"transmittance", "direct irradiance", "single scattering", "order 2",
                                               "order 3", "order 4"}));
    const AtmosphereTables incremental = readBack(job.takeResult());
    // The same shaders on the same texels: identical up to the driver's freedom
    // to schedule (1e-6 relative to each table's range).
    auto check = [](const char* name, const std::vector<glm::dvec4>& a, const std::vector<glm::dvec4>& b) {
        double range = 0.0;
        for (const glm::dvec4& v : b)
            for (int c = 0; c < 4; ++c) range = std::max(range, std::abs(v[c]));
        EXPECT_LE(maxAbsDifference(a, b), 1e-6 * range) << name;
    };
    check("transmittance", incremental.transmittance.texels, blocking.transmittance.texels);
    check("scattering", incremental.scattering.texels, blocking.scattering.texels);
    check("single Mie", incremental.singleMie.texels, blocking.singleMie.texels);
    check("irradiance", incremental.irradiance.texels, blocking.irradiance.texels);
}

TEST_F(AtmosphereGpu, UploadReadBackRoundTrip) {
    const AtmosphereTables& tables = gpuEarth();
    const AtmosphereTables again = readBack(upload(tables));
    ASSERT_EQ(again.sizes, tables.sizes);
    // Float -> double -> float is exact: bitwise equal.
    EXPECT_EQ(maxAbsDifference(again.transmittance.texels, tables.transmittance.texels), 0.0);
    EXPECT_EQ(maxAbsDifference(again.scattering.texels, tables.scattering.texels), 0.0);
    EXPECT_EQ(maxAbsDifference(again.singleMie.texels, tables.singleMie.texels), 0.0);
    EXPECT_EQ(maxAbsDifference(again.irradiance.texels, tables.irradiance.texels), 0.0);
}

TEST_F(AtmosphereGpu, NoParticlesMeansNoExtinctionAndNoScattering) {
    AtmosphereParameters vacuum = earth();
    vacuum.rayleigh_scattering = vacuum.mie_scattering = vacuum.mie_extinction = vacuum.absorption_extinction =
        glm::dvec3(0.0);
    GpuPrecompute precompute(shaderRoot(), TableSizes::reduced());
    const AtmosphereTables t = readBack(precompute.compute(vacuum, 2));
    for (const glm::dvec4& v : t.transmittance.texels) {
        ASSERT_EQ(glm::dvec3(v), glm::dvec3(1.0));
    }
    for (const auto* table : {&t.scattering.texels, &t.singleMie.texels}) {
        for (const glm::dvec4& v : *table) {
            ASSERT_EQ(glm::dvec3(v), glm::dvec3(0.0));
        }
    }
    for (const glm::dvec4& v : t.scattering.texels) ASSERT_EQ(v.a, 0.0);
    for (const glm::dvec4& v : t.irradiance.texels) ASSERT_EQ(glm::dvec3(v), glm::dvec3(0.0));
}

}  // namespace
