// The scattering density's quadrature (ComputeScatteringDensity in
// shaders/atmosphere/functions.glsl, Elek Eq. 12), in double, on reduced tables.
//
// ComputeScatteringDensity reads the previous order once per ring of directions
// (the nu slices of its table) instead of once per direction. Against it, the
// textbook form of the same midpoint rule, written out here as it stood before
// (each direction looks the previous order and the ground up by itself):
//   - on the same 16 x 32 (theta, phi) grid the two must agree to rounding: a
//     hoisting mistake (a slice, the ground's sun cosine, a mirrored direction)
//     breaks this at once;
//   - on a 128 x 256 grid the textbook form is the integral to within its own
//     error, and the 16 x 32 grid must stay within a tolerance of it (the largest
//     difference over the sampled texels, as a fraction of the largest density),
//     which an 8 x 16 grid does not (checked, so the tolerance keeps its power):
//     a quadrature with too few directions fails here.
// Measured 2026-12-02 (reduced tables, 135 texels), against the 128 x 256 grid:
//                 16 x 32 grid                        8 x 16 grid
//   earth   max/largest 2.29e-2, mean rel. 5.7e-2    6.97e-2, 8.5e-2
//   hazy    max/largest 6.67e-3, mean rel. 1.6e-2    2.80e-2, 3.5e-2
// (relative errors with a floor of 1e-3 of the largest density). So the 16 x 32
// grid is itself a few per cent from the integral of the tables it reads: its
// cells (11 degrees) are as wide as the Mie forward peak, and the incident light
// is only piecewise linear in nu between the table's slices.
// For the Earth preset and the hazy one (a thick haze, whose Mie forward peak
// is the hard part of the integrand).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "app/session.h"
#include "atmosphere/parameters.h"
#include "atmosphere/reference_tables.h"

using namespace planet;
using namespace planet::atmosphere;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The previous order (single scattering) and the ground's direct irradiance,
// as the order-2 density reads them, from the double reference.
struct Inputs {
    AtmosphereParameters atmosphere;
    AtmosphereTables single;  // transmittance; scattering rgb = single Rayleigh; single Mie
    Table2D directIrradiance;
};

Inputs makeInputs(const Scene& scene) {
    Inputs in{makeAtmosphereParameters(scene), computeReferenceTables(makeAtmosphereParameters(scene),
                                                                       TableSizes::reduced(), 1)
                                                   .tables,
              Table2D(TableSizes::reduced().irradiance_width, TableSizes::reduced().irradiance_height)};
    Model model(TableSizes::reduced(), /*precompute=*/true);
    for (int y = 0; y < in.directIrradiance.height; ++y)
        for (int x = 0; x < in.directIrradiance.width; ++x)
            in.directIrradiance.at(x, y) = glm::dvec4(
                model.ComputeDirectIrradianceTexture(in.atmosphere, in.single.transmittance, glm::dvec2(x + 0.5, y + 0.5)),
                1.0);
    return in;
}

// ComputeScatteringDensity as it stood before the per-ring lookups: the midpoint
// rule on `rings` x 2 `rings` directions, every direction with its own lookups.
glm::dvec3 textbookDensity(Model& m, const Inputs& in, const Table3D& multiple, double r, double mu, double mu_s,
                           double nu, int order, int rings) {
    const AtmosphereParameters& a = in.atmosphere;
    const glm::dvec3 omega(std::sqrt(1.0 - mu * mu), 0.0, mu);
    const double sun_x = omega.x == 0.0 ? 0.0 : (nu - mu * mu_s) / omega.x;
    const glm::dvec3 omega_s(sun_x, std::sqrt(std::max(1.0 - sun_x * sun_x - mu_s * mu_s, 0.0)), mu_s);
    const double dtheta = kPi / rings, dphi = kPi / rings;
    glm::dvec3 rayleigh(0.0), mie(0.0);
    double rayleighNorm = 0.0, mieNorm = 0.0;
    for (int l = 0; l < rings; ++l) {
        const double theta = (l + 0.5) * dtheta;
        const double cosTheta = std::cos(theta), sinTheta = std::sin(theta);
        const bool ground = m.RayIntersectsGround(a, r, cosTheta);
        double d = 0.0;
        glm::dvec3 groundTransmittance(0.0);
        if (ground) {
            d = m.DistanceToBottomAtmosphereBoundary(a, r, cosTheta);
            groundTransmittance = m.GetTransmittance(a, in.single.transmittance, r, cosTheta, d, true);
        }
        for (int k = 0; k < 2 * rings; ++k) {
            const double phi = (k + 0.5) * dphi;
            const glm::dvec3 omega_i(std::cos(phi) * sinTheta, std::sin(phi) * sinTheta, cosTheta);
            const double domega = dtheta * dphi * sinTheta;
            glm::dvec3 radiance = m.GetScatteringOfOrder(a, in.single.scattering, in.single.singleMie, multiple, r,
                                                         cosTheta, mu_s, glm::dot(omega_s, omega_i), ground, order - 1);
            if (ground) {
                const glm::dvec3 normal = glm::normalize(glm::dvec3(0.0, 0.0, r) + omega_i * d);
                radiance += groundTransmittance * a.ground_albedo / kPi *
                            m.GetIrradiance(a, in.directIrradiance, a.bottom_radius, glm::dot(normal, omega_s));
            }
            const double nu2 = glm::dot(omega, omega_i);
            const double pr = m.RayleighPhaseFunction(nu2) * domega;
            const double pm = m.MiePhaseFunction(a.mie_phase_function_g, nu2) * domega;
            rayleigh += radiance * pr;
            mie += radiance * pm;
            rayleighNorm += pr;
            mieNorm += pm;
        }
    }
    const double h = r - a.bottom_radius;
    return a.rayleigh_scattering * m.GetProfileDensity(a.rayleigh_density, h) * (rayleigh / rayleighNorm) +
           a.mie_scattering * m.GetProfileDensity(a.mie_density, h) * (mie / mieNorm);
}

struct Comparison {
    double maxRelative = 0.0;   // over texels and channels, floor 1e-3 of the largest reference value
    double meanRelative = 0.0;  // the same, averaged
    double maxOfLargest = 0.0;  // largest |difference| / largest reference value
    int texels = 0;
};

// ComputeScatteringDensity against textbookDensity(rings) (or textbookDensity(coarse)
// against textbookDensity(rings) when coarse > 0) on every `stride`-th texel.
Comparison compare(const Inputs& in, int order, int rings, int stride, int coarse = 0) {
    Model m(TableSizes::reduced(), /*precompute=*/true);
    const Table3D& multiple = in.single.scattering;  // order >= 3 reads it as "the previous order"
    const glm::ivec3 size = TableSizes::reduced().scatteringSize();
    std::vector<glm::dvec3> got, want;
    for (int i = 0; i < size.x * size.y * size.z; i += stride) {
        const glm::dvec3 frag(i % size.x + 0.5, (i / size.x) % size.y + 0.5, i / (size.x * size.y) + 0.5);
        double r, mu, mu_s, nu;
        bool ground;
        m.GetRMuMuSNuFromScatteringTextureFragCoord(in.atmosphere, frag, r, mu, mu_s, nu, ground);
        want.push_back(textbookDensity(m, in, multiple, r, mu, mu_s, nu, order, rings));
        got.push_back(coarse > 0 ? textbookDensity(m, in, multiple, r, mu, mu_s, nu, order, coarse)
                                 : m.ComputeScatteringDensityTexture(in.atmosphere, in.single.transmittance,
                                                                     in.single.scattering, in.single.singleMie,
                                                                     multiple, in.directIrradiance, frag, order));
    }
    double largest = 0.0;
    for (const glm::dvec3& w : want) largest = std::max({largest, w.r, w.g, w.b});
    Comparison c;
    c.texels = static_cast<int>(want.size());
    for (std::size_t i = 0; i < want.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
            const double d = std::abs(got[i][ch] - want[i][ch]);
            const double relative = d / std::max(want[i][ch], 1e-3 * largest);
            c.maxRelative = std::max(c.maxRelative, relative);
            c.meanRelative += relative / (3.0 * static_cast<double>(want.size()));
            c.maxOfLargest = std::max(c.maxOfLargest, d / largest);
        }
    return c;
}

const Inputs& inputs(const std::string& preset) {
    static const Inputs earth = makeInputs(Scene{});
    static const Inputs hazy = makeInputs(loadNamedPreset(DataPaths{PLANET_SOURCE_DIR}, "hazy").scene);
    return preset == "hazy" ? hazy : earth;
}

class ScatteringDensityQuadrature : public ::testing::TestWithParam<std::string> {};

TEST_P(ScatteringDensityQuadrature, PerRingLookupsEqualPerDirectionLookupsOnTheSameGrid) {
    for (int order : {2, 3}) {
        const Comparison c = compare(inputs(GetParam()), order, 16, 7);
        std::printf("  %s order %d: per-ring vs per-direction lookups, 16 x 32 grid, %d texels: max %.2e\n",
                    GetParam().c_str(), order, c.texels, c.maxRelative);
        EXPECT_LT(c.maxRelative, 1e-9) << "order " << order;
    }
}

TEST_P(ScatteringDensityQuadrature, GridIsFineEnoughAgainstAManyDirectionIntegral) {
    const Comparison c = compare(inputs(GetParam()), 2, 128, 61);
    const Comparison coarse = compare(inputs(GetParam()), 2, 128, 61, 8);
    std::printf("  %s: against a 128 x 256 grid, %d texels: 16 x 32 grid max %.3e mean %.3e max/largest %.3e; "
                "8 x 16 grid max %.3e mean %.3e max/largest %.3e\n",
                GetParam().c_str(), c.texels, c.maxRelative, c.meanRelative, c.maxOfLargest, coarse.maxRelative,
                coarse.meanRelative, coarse.maxOfLargest);
    // 1.5 times the 16 x 32 grid's figure (see the top of the file).
    const double tolerance = GetParam() == "hazy" ? 0.01 : 0.035;
    EXPECT_LT(c.maxOfLargest, tolerance);
    EXPECT_GT(coarse.maxOfLargest, tolerance) << "the tolerance no longer tells a coarse grid apart";
}

INSTANTIATE_TEST_SUITE_P(Presets, ScatteringDensityQuadrature, ::testing::Values("earth", "hazy"));

}  // namespace
