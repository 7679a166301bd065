// Elek's 3D table (shaders/atmosphere/elek_table.glsl, src/atmosphere/elek_table.h):
// the remapping and its inverse, the table against the 4D lookups it samples
// at azimuth 0, the GPU pass against the CPU build, and the error the dropped
// azimuth costs over a grid of views (compareElekWith4D). Reduced sizes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <random>

#include "atmosphere/elek_table.h"
#include "atmosphere/parameters.h"
#include "atmosphere/reference_tables.h"
#include "gl_test_support.h"

using namespace planet;
using namespace planet::atmosphere;

namespace {

AtmosphereParameters earth() { return makeAtmosphereParameters(Scene{}); }

// The CPU reference tables and their Elek table: costly, once for the file.
const AtmosphereTables& reference4D() {
    static const AtmosphereTables t = computeReferenceTables(earth(), TableSizes::reduced(), 4).tables;
    return t;
}
const ElekTables& referenceElek() {
    static const ElekTables t = computeElekTables(earth(), reference4D());
    return t;
}

double relativeError(const glm::dvec3& value, const glm::dvec3& ref, double floor) {
    double e = 0.0;
    for (int c = 0; c < 3; ++c) e = std::max(e, std::abs(value[c] - ref[c]) / std::max(std::abs(ref[c]), floor));
    return e;
}

double largestRgb(const Table3D& t) {
    double m = 0.0;
    for (const glm::dvec4& v : t.texels) m = std::max({m, v.r, v.g, v.b});
    return m;
}

}  // namespace

TEST(ElekTable, RemappingRoundTrip) {
    const AtmosphereParameters a = earth();
    Model model(TableSizes{});
    const double R = a.bottom_radius, top = a.top_radius;
    for (double r : {R, R + 0.5, R + 10.0, R + 37.0, top}) {
        for (double mu = -1.0; mu <= 1.0; mu += 0.0625) {
            const bool ground = model.RayIntersectsGround(a, r, mu);
            for (double mu_s : {-0.28, -0.2, -0.05, 0.0, 0.1, 0.5, 0.9, 1.0}) {
                const glm::dvec3 uvw = model.GetElekTextureUvwFromRMuMuS(a, r, mu, mu_s, ground);
                for (int c = 0; c < 3; ++c) {
                    EXPECT_GE(uvw[c], 0.0);
                    EXPECT_LE(uvw[c], 1.0);
                }
                EXPECT_EQ(uvw.y < 0.5, ground) << r << " " << mu;
                double r2, mu2, mu_s2;
                bool ground2;
                model.GetRMuMuSFromElekTextureUvw(a, uvw, r2, mu2, mu_s2, ground2);
                EXPECT_NEAR(r2, r, 1e-9 * r);
                EXPECT_NEAR(mu2, mu, 1e-9) << "r " << r << " mu_s " << mu_s;
                EXPECT_NEAR(mu_s2, mu_s, 1e-9);
                EXPECT_EQ(ground2, ground);
            }
        }
    }
    // Elek's W: mu_s = 1 at the last texel centre, W = 0 (mu_s = -0.8 / 2.8) at the first.
    EXPECT_NEAR(model.GetElekTextureUvwFromRMuMuS(a, R, 1.0, 1.0, false).x, 1.0 - 0.5 / 32.0, 1e-12);
    EXPECT_NEAR(model.GetElekTextureUvwFromRMuMuS(a, R, 1.0, -0.8 / 2.8, false).x, 0.5 / 32.0, 1e-12);
    EXPECT_NEAR(model.GetElekTextureUvwFromRMuMuS(a, R, 1.0, -0.9, false).x, 0.5 / 32.0, 1e-12);  // clamped
    // At the ground the split V is Elek's (1 + mu) / 2, up to each half's texel-centre mapping.
    EXPECT_NEAR(model.GetElekTextureUvwFromRMuMuS(a, R, 0.5, 0.3, false).y, 0.5 + 0.5 * (0.5 / 64.0 + 0.5 * 63.0 / 64.0),
                1e-12);
    // U = sqrt((r^2 - Rp^2) / (Ra^2 - Rp^2)).
    const double r = R + 10.0;
    const double U = std::sqrt((r * r - R * R) / (top * top - R * R));
    EXPECT_NEAR(model.GetElekTextureUvwFromRMuMuS(a, r, 0.3, 0.3, false).z, 0.5 / 32.0 + U * 31.0 / 32.0, 1e-12);
}

TEST(ElekTable, EqualsThe4DLookupAtZeroAzimuth) {
    const AtmosphereParameters a = earth();
    const AtmosphereTables& t4 = reference4D();
    const ElekTables& elek = referenceElek();
    Model model(t4.sizes);
    const double floor = 1e-3 * largestRgb(t4.scattering);
    const double mieFloor = 1e-3 * largestRgb(t4.singleMie);

    // At the Elek texel centres the lookup returns the texel: the 4D value exactly.
    double worstAtCentres = 0.0;
    const glm::ivec3 size = t4.sizes.elekSize();
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                double r, mu, mu_s;
                bool ground;
                model.GetRMuMuSFromElekTextureUvw(a, (glm::dvec3(x, y, z) + 0.5) / glm::dvec3(size), r, mu, mu_s,
                                                  ground);
                const double nu = model.ElekNuAtZeroAzimuth(mu, mu_s);
                glm::dvec3 mie4, mieElek;
                const glm::dvec3 s4 =
                    model.GetCombinedScattering(a, t4.scattering, t4.singleMie, r, mu, mu_s, nu, ground, mie4);
                const glm::dvec3 sElek =
                    model.GetCombinedScatteringElek(a, elek.scattering, elek.singleMie, r, mu, mu_s, ground, mieElek);
                worstAtCentres = std::max({worstAtCentres, relativeError(sElek, s4, floor),
                                           relativeError(mieElek, mie4, mieFloor)});
            }
    EXPECT_LT(worstAtCentres, 1e-9);

    // Between texel centres only the interpolation differs (Elek's grid is not the 4D one).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double sum = 0.0, worst = 0.0;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
        const double r = a.bottom_radius + (a.top_radius - a.bottom_radius) * unit(rng);
        const double mu = -1.0 + 2.0 * unit(rng);
        const double mu_s = -0.2 + 1.2 * unit(rng);
        const double nu = model.ElekNuAtZeroAzimuth(mu, mu_s);
        const bool ground = model.RayIntersectsGround(a, r, mu);
        glm::dvec3 mie4, mieElek;
        const glm::dvec3 s4 = model.GetCombinedScattering(a, t4.scattering, t4.singleMie, r, mu, mu_s, nu, ground, mie4);
        const glm::dvec3 sElek =
            model.GetCombinedScatteringElek(a, elek.scattering, elek.singleMie, r, mu, mu_s, ground, mieElek);
        const double e = relativeError(sElek, s4, floor);
        sum += e;
        worst = std::max(worst, e);
    }
    std::printf("  Elek vs 4D at omega = 0, random (r, mu, mu_s), reduced sizes: mean %.3f%%, max %.2f%%\n",
                100.0 * sum / n, 100.0 * worst);
    EXPECT_LT(sum / n, 0.05);
}

TEST(ElekTable, ComparisonWith4DReportsMemoryAndBoundedError) {
    const ElekComparison c = compareElekWith4D(earth(), reference4D(), referenceElek());
    std::printf("%s", describeElekComparison(c).c_str());
    const TableSizes s = TableSizes::reduced();
    EXPECT_EQ(c.bytes4D, 2u * 16u * 4u * 8u * 32u * 8u);  // nu 4 x mu_s 8, mu 32, r 8
    EXPECT_EQ(c.bytesElek, 2u * 16u * 8u * 32u * 8u);
    EXPECT_EQ(c.bytes4D, c.bytesElek * static_cast<std::size_t>(s.scattering_nu));  // same r, mu, mu_s: nu times less
    EXPECT_LT(c.bytesElek, c.bytes4D);
    EXPECT_EQ(c.samples, 4 * 11 * 19 * 13);
    EXPECT_TRUE(std::isfinite(c.meanRelativeError));
    EXPECT_TRUE(std::isfinite(c.maxRelativeError));
    EXPECT_LT(c.meanRelativeError, 0.30);
    EXPECT_GT(c.meanRelativeError, 0.0);
    // In the sun's vertical half-plane the table is the 4D one up to interpolation;
    // opposite the sun the dropped azimuth shows.
    EXPECT_LT(c.meanRelativeErrorAzimuth0, 0.05);
    EXPECT_LT(c.meanRelativeErrorAzimuth0, 0.5 * c.meanRelativeErrorAzimuth180);

    // Full sizes: the memory the README quotes.
    const TableSizes full;
    EXPECT_EQ(scattering4DBytes(full), 32u << 20);
    EXPECT_EQ(elekBytes(full), 4u << 20);
}

// ------------------------------------------------------------------- GPU

class ElekTableGpu : public test::GLTest {
protected:
    static std::filesystem::path shaderRoot() { return std::filesystem::path(PLANET_SOURCE_DIR) / "shaders"; }
    struct Result {
        AtmosphereTables tables;  // the GPU's 4D tables, read back
        ElekTables elek;          // the GPU's Elek tables, read back
        std::vector<std::string> steps;
    };
    // Computed once for the suite.
    static const Result& gpu() {
        if (!gpu_) {
            GpuPrecompute precompute(shaderRoot(), TableSizes::reduced());
            Result r;
            const GpuTables t = precompute.compute(
                earth(), 4, [&](const PrecomputeStep& s) { r.steps.push_back(s.name); }, /*elekTable=*/true);
            r.tables = readBack(t);
            r.elek = readBackElek(t);
            gpu_ = std::move(r);
        }
        return *gpu_;
    }
    static void TearDownTestSuite() {
        gpu_.reset();
        GLTest::TearDownTestSuite();
    }
    static inline std::optional<Result> gpu_;
};

namespace {

// Largest relative error over both tables' rgb, floor 1e-3 of each table's maximum.
double tableError(const ElekTables& value, const ElekTables& ref) {
    double worst = 0.0;
    for (auto member : {&ElekTables::scattering, &ElekTables::singleMie}) {
        const Table3D& v = value.*member;
        const Table3D& r = ref.*member;
        EXPECT_EQ(v.texels.size(), r.texels.size());
        const double floor = std::max(1e-3 * largestRgb(r), 1e-30);
        for (std::size_t i = 0; i < std::min(v.texels.size(), r.texels.size()); ++i)
            worst = std::max(worst, relativeError(glm::dvec3(v.texels[i]), glm::dvec3(r.texels[i]), floor));
    }
    return worst;
}

}  // namespace

TEST_F(ElekTableGpu, MatchesTheCpuBuildFromTheSame4DTables) {
    const Result& g = gpu();
    EXPECT_EQ(g.steps.back(), "Elek 3D table");
    // The CPU build (double) from the GPU's own 4D tables: only the pass differs.
    const double samePass = tableError(g.elek, computeElekTables(earth(), g.tables));
    // The CPU build from the CPU reference 4D tables: the 4D tables' own GPU-CPU
    // differences (up to 1.5%, test_atmosphere_gpu.cpp) add to it.
    const double fromReference = tableError(g.elek, referenceElek());
    std::printf("  GPU Elek table vs CPU: %.3e (same 4D input), %.3e (CPU reference input)\n", samePass, fromReference);
    EXPECT_LT(samePass, 0.01);
    EXPECT_LT(fromReference, 0.02);
}

TEST_F(ElekTableGpu, BuildsAfterAnUploadAndRoundTrips) {
    const Result& g = gpu();
    GpuPrecompute precompute(shaderRoot(), TableSizes::reduced());
    const GpuTables uploaded = upload(g.tables);  // as from the disk cache: Elek tables zero
    for (const glm::dvec4& v : readBackElek(uploaded).scattering.texels) ASSERT_EQ(v, glm::dvec4(0.0));
    precompute.computeElekTable(earth(), uploaded);
    EXPECT_LT(tableError(readBackElek(uploaded), g.elek), 1e-6);
    uploadElek(g.elek, uploaded);
    const ElekTables again = readBackElek(uploaded);
    EXPECT_EQ(again.scattering.texels, g.elek.scattering.texels);
    EXPECT_EQ(again.singleMie.texels, g.elek.singleMie.texels);
}

TEST_F(ElekTableGpu, IncrementalJobEndsWithTheElekStep) {
    const Result& g = gpu();
    GpuPrecompute precompute(shaderRoot(), TableSizes::reduced());
    std::vector<std::string> names;
    GpuPrecomputeJob job = precompute.start(earth(), 4, [&](const PrecomputeStep& s) { names.push_back(s.name); },
                                            /*layersPerChunk=*/3, /*elekTable=*/true);
    int chunks = 0;
    while (!job.step()) ASSERT_LT(++chunks, 1000);
    EXPECT_EQ(names, g.steps);
    EXPECT_LT(tableError(readBackElek(job.takeResult()), g.elek), 1e-6);
}
