// The clouds: the shared model (shaders/clouds/cloud_model.glsl compiled as C++) against
// worked values, and the GPU's unified march (clouds/cloud_march.glsl through
// clouds/cloud_probe.comp) against closed forms on a layer of constant density.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "atmosphere/parameters.h"
#include "atmosphere/precompute_gpu.h"
#include "atmosphere/uniforms.h"
#include "clouds/cloud_block.h"
#include "clouds/cloud_model.h"
#include "clouds/cloud_probe.h"
#include "gl_test_support.h"

using namespace planet;
using namespace planet::clouds;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Length of the part of the ray o + t d (t >= 0) inside the sphere of radius R: an
// independent formulation (inside length of a ball, clipped at t = 0), not the model's.
double insideBall(const glm::dvec3& o, const glm::dvec3& d, double R) {
    const double b = glm::dot(o, d);
    const double c = glm::dot(o, o) - R * R;
    const double disc = b * b - c;
    if (disc <= 0.0) return 0.0;
    const double t0 = -b - std::sqrt(disc), t1 = -b + std::sqrt(disc);
    return std::max(0.0, t1 - std::max(t0, 0.0)) * (t1 > 0.0);
}
// The same for the part of the ray with t in [0, maxT].
double insideBallUpTo(const glm::dvec3& o, const glm::dvec3& d, double R, double maxT) {
    const double b = glm::dot(o, d);
    const double c = glm::dot(o, o) - R * R;
    const double disc = b * b - c;
    if (disc <= 0.0) return 0.0;
    const double t0 = std::max(-b - std::sqrt(disc), 0.0), t1 = std::min(-b + std::sqrt(disc), maxT);
    return std::max(0.0, t1 - t0);
}
double shellChord(const glm::dvec3& o, const glm::dvec3& d, double bottom, double top, double maxT = 1e30) {
    return insideBallUpTo(o, d, top, maxT) - insideBallUpTo(o, d, bottom, maxT);
}

}  // namespace

TEST(CloudModel, HeightSignalIsZeroAtTheBoundsAndOneInTheMiddle) {  // Michelic Eq. 13
    EXPECT_DOUBLE_EQ(glsl::CloudHeightSignal(6361.0, 6361.0, 6364.0), 0.0);
    EXPECT_DOUBLE_EQ(glsl::CloudHeightSignal(6364.0, 6361.0, 6364.0), 0.0);
    EXPECT_DOUBLE_EQ(glsl::CloudHeightSignal(6362.5, 6361.0, 6364.0), 1.0);
    EXPECT_DOUBLE_EQ(glsl::CloudHeightSignal(6361.75, 6361.0, 6364.0), 0.75);  // 1 - (-0.5)^2
    EXPECT_DOUBLE_EQ(glsl::CloudHeightSignal(6000.0, 6361.0, 6364.0), 0.0);    // clamped below
    // Eq. 14 under the whole coverage: negative texture values stay the "no cloud" marker, others
    // scale by h.
    EXPECT_DOUBLE_EQ(glsl::CloudDensityFromTextureAndCoverage(-0.3, 0.8, 1.0), -1.0);
    EXPECT_DOUBLE_EQ(glsl::CloudDensityFromTextureAndCoverage(0.5, 0.8, 1.0), 0.4);
}

// Eq. 14 with the weather's coverage (CloudDensityFromTextureAndCoverage): the remap after the height
// signal, so that a cloud narrows towards its bottom and top instead of ending in a wall under a lid.
TEST(CloudModel, UnderAPartialCoverageACloudNarrowsTowardsItsBottomAndTop) {
    // Under a partial coverage the remap comes after h: at mid-height (h = 1) the coverage keeps the
    // values above 1 - coverage, stretched to [0, 1] ((0.9 - 0.5) / 0.5); lower in the profile the
    // same value is cloud no longer ((0.9 x 0.5 - 0.5) / 0.5 < 0: clamped), where h x remap(value)
    // kept 0.5 x 0.8 = 0.4 (the wall under a flat lid); a higher one is, thinner ((1 x 0.6 - 0.5) / 0.5).
    EXPECT_DOUBLE_EQ(glsl::CloudDensityFromTextureAndCoverage(0.9, 1.0, 0.5), 0.8);
    EXPECT_DOUBLE_EQ(glsl::CloudDensityFromTextureAndCoverage(0.9, 0.5, 0.5), 0.0);
    EXPECT_NEAR(glsl::CloudDensityFromTextureAndCoverage(1.0, 0.6, 0.5), 0.2, 1e-12);
    EXPECT_DOUBLE_EQ(glsl::CloudDensityFromTextureAndCoverage(-0.3, 0.5, 0.5), -1.0);
    EXPECT_DOUBLE_EQ(glsl::CloudCoverageRemap(0.9, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(glsl::CloudCoverageRemap(0.9, 1.0), 0.9);
    EXPECT_DOUBLE_EQ(glsl::CloudCoverageRemap(-1.0, 0.5), -1.0);
}

TEST(CloudModel, LocalCoverageMakesTheParameterTheMeanOfTheMap) {
    // The map's coverage is uniform-ish with mean 1/2; the local coverage must average to
    // the parameter for a map of mean 1/2 (linear in the map in each half), be 0 at 0, 1
    // at 1, the map itself at 1/2, and never leave [0, 1].
    for (double coverage : {0.0, 0.1, 0.3, 0.5, 0.7, 0.95, 1.0}) {
        double mean = 0.0;
        const int n = 1000;
        for (int i = 0; i < n; ++i) {
            const double map = (i + 0.5) / n;  // uniform on [0, 1]: mean 1/2
            const double local = glsl::CloudLocalCoverage(map, coverage);
            ASSERT_GE(local, 0.0);
            ASSERT_LE(local, 1.0);
            mean += local / n;
        }
        EXPECT_NEAR(mean, coverage, 1e-9) << coverage;
    }
    EXPECT_DOUBLE_EQ(glsl::CloudLocalCoverage(0.3, 0.5), 0.3);
    EXPECT_DOUBLE_EQ(glsl::CloudLocalCoverage(0.3, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(glsl::CloudLocalCoverage(0.3, 1.0), 1.0);
    // Continuous at 1/2 from both sides.
    EXPECT_NEAR(glsl::CloudLocalCoverage(0.3, 0.5 - 1e-9), glsl::CloudLocalCoverage(0.3, 0.5 + 1e-9), 1e-8);
}

TEST(CloudModel, TypeProfilesPlaceStratusLowCumulusMidAndHighCloudAtTheTop) {
    // Stratus (0) fills [0, 0.25], cumulus (0.5) [0, 0.7], high cloud (1) [0.8, 1]; each
    // peaks at 1 in the middle of its interval and is 0 at its ends, like Eq. 13.
    struct Case { double type, bottom, top; };
    for (const Case c : {Case{0.0, 0.0, 0.25}, Case{0.5, 0.0, 0.7}, Case{1.0, 0.8, 1.0}}) {
        EXPECT_DOUBLE_EQ(glsl::CloudTypeHeightSignal(0.5 * (c.bottom + c.top), c.type), 1.0) << c.type;
        EXPECT_DOUBLE_EQ(glsl::CloudTypeHeightSignal(c.bottom, c.type), 0.0) << c.type;
        EXPECT_DOUBLE_EQ(glsl::CloudTypeHeightSignal(c.top, c.type), 0.0) << c.type;
        EXPECT_DOUBLE_EQ(glsl::CloudTypeHeightSignal(c.top + 0.01, c.type), 0.0) << c.type;
        // A quarter of the way in: 1 - (-1/2)^2.
        EXPECT_NEAR(glsl::CloudTypeHeightSignal(c.bottom + 0.25 * (c.top - c.bottom), c.type), 0.75, 1e-12) << c.type;
    }
    // In between, the interval moves continuously (stratocumulus between stratus and cumulus).
    EXPECT_NEAR(glsl::CloudTypeHeightSignal(0.2, 0.25), glsl::CloudTypeHeightSignal(0.2, 0.25 + 1e-9), 1e-6);
    EXPECT_GT(glsl::CloudTypeHeightSignal(0.5, 0.75), 0.0);  // altocumulus in the upper middle
    EXPECT_EQ(glsl::CloudTypeHeightSignal(0.5, 0.0), 0.0);   // no stratus half way up
}

TEST(CloudModel, FarFieldPathInClosedFormIsTheIntegralOfTheFarFieldDensity) {
    // CloudFarFieldPath against a fine numerical integral of CloudFarFieldDensity with the
    // type's height signal along straight paths (heights linear along them), up, down, across
    // a profile's edge and nearly level; and straight up through the whole layer the column's
    // transmittance is 1 - 0.98 coverage, what the far field is built for.
    const double E = 40.0, D = 2.5;
    for (double type : {0.0, 0.3, 0.5, 0.8, 1.0}) {
        double b = 0.0, c = 0.0;
        glsl::CloudTypeBounds(type, b, c);
        const double span = c - b;
        for (double coverage : {0.1, 0.5, 0.9}) {
            struct Path { double fa, fb, way; };
            for (const Path p : {Path{0.0, 1.0, 2.5}, Path{0.1, 0.35, 4.0}, Path{0.6, 0.2, 1.2}, Path{0.5, 0.50001, 1.0},
                                 Path{0.05, 0.9, 30.0}}) {
                const int n = 200000;
                double numeric = 0.0;
                for (int i = 0; i < n; ++i) {
                    const double f = p.fa + (p.fb - p.fa) * (i + 0.5) / n;
                    const double h = glsl::CloudTypeHeightSignal(f, type);
                    numeric += glsl::CloudFarFieldDensity(coverage, h, (2.0 / 3.0) * span, D, E) * p.way / n;
                }
                const double closed =
                    glsl::CloudFarFieldPath(coverage, span, (p.fa - b) / span, (p.fb - b) / span, p.way, D, E);
                EXPECT_NEAR(closed, numeric, 1e-6 + 1e-6 * numeric) << type << " " << coverage << " " << p.fa;
            }
            const double column = glsl::CloudFarFieldPath(coverage, span, -b / span, (1.0 - b) / span, D, D, E);
            EXPECT_NEAR(std::exp(-E * column), 1.0 - 0.98 * coverage, 1e-12) << type << " " << coverage;
        }
    }
}

TEST(CloudModel, PhaseFunctionIntegratesToOneWithMeanCosineG) {
    for (double g : {-0.5, 0.0, 0.3, 0.8}) {
        double integral = 0.0, meanCos = 0.0;
        const int n = 200000;
        for (int i = 0; i < n; ++i) {
            const double mu = -1.0 + (i + 0.5) * 2.0 / n;
            const double p = glsl::HenyeyGreenstein(g, mu) * 2.0 * kPi * (2.0 / n);
            integral += p;
            meanCos += p * mu;
        }
        EXPECT_NEAR(integral, 1.0, 1e-6) << g;
        EXPECT_NEAR(meanCos, g, 1e-4) << g;
        EXPECT_NEAR(glsl::CloudPhase(g, -0.3, 0.25, 0.4),
                    0.75 * glsl::HenyeyGreenstein(g, 0.4) + 0.25 * glsl::HenyeyGreenstein(-0.3, 0.4), 1e-15);
    }
}

TEST(CloudModel, LayerIntervalsHaveTheShellsChordFromEveryCamera) {
    // Rays from below, inside, above the layer and from space, in every direction: the
    // intervals' total length is the chord through the shell, computed independently,
    // they are ordered, inside [0, max], and each midpoint lies in the shell.
    const double bottom = 6361.5, top = 6364.0;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int rays = 0, twice = 0;
    for (double altitude : {0.002, 0.5, 1.4, 1.6, 3.0, 3.99, 4.5, 10.0, 400.0, 36000.0}) {
        for (int k = 0; k < 400; ++k) {
            glm::dvec3 d(u(rng), u(rng), u(rng));
            if (glm::length(d) < 1e-3) continue;
            d = glm::normalize(d);
            if (k < 40) d = glm::normalize(glm::dvec3(std::cos(k * 0.04), 0.0, -std::sin(k * 0.004)));  // grazing
            const glm::dvec3 o(0.0, 0.0, 6360.0 + altitude);
            const double r = glm::length(o), mu = glm::dot(o, d) / r;
            for (double maxDistance : {1e9, 50.0}) {
                glm::dvec2 a, b;
                const int count = glsl::CloudLayerIntervals(r, mu, maxDistance, bottom, top, a, b);
                double total = 0.0;
                if (count >= 1) total += a.y - a.x;
                if (count == 2) total += b.y - b.x;
                // The expected chord, clipped at maxDistance by sampling the shell's indicator.
                double expected = shellChord(o, d, bottom, top);
                if (maxDistance < 1e8) {
                    expected = 0.0;
                    const int n = 200000;
                    for (int i = 0; i < n; ++i) {
                        const double t = (i + 0.5) * maxDistance / n;
                        const double rr = glm::length(o + d * t);
                        expected += (rr >= bottom && rr <= top) * maxDistance / n;
                    }
                    EXPECT_NEAR(total, expected, 2e-3 * maxDistance + 1e-9) << altitude << " km, mu " << mu;
                } else {
                    EXPECT_NEAR(total, expected, 1e-6 * std::max(1.0, expected)) << altitude << " km, mu " << mu;
                }
                if (count >= 1) {
                    EXPECT_GE(a.x, 0.0);
                    EXPECT_LE(a.y, maxDistance);
                    const double rm = glm::length(o + d * (0.5 * (a.x + a.y)));
                    EXPECT_TRUE(rm >= bottom - 1e-6 && rm <= top + 1e-6) << altitude << " " << mu;
                }
                if (count == 2) {
                    EXPECT_GE(b.x, a.y);
                    ++twice;
                }
                ++rays;
            }
        }
    }
    EXPECT_GT(twice, 50);  // rays that leave the layer below and come back were among them
    EXPECT_EQ(rays, 10 * 400 * 2);
}

TEST(CloudModel, EnergyConservingStepDoesNotDependOnTheStepSize) {
    // A constant source through a constant density: n steps of L / n give the exact
    // integral S src (1 - e^{-E rho L}) / (E rho) for any n; Michelic's Eq. 16 as written
    // approaches it as the step shrinks (first order).
    const double rho = 0.7, E = 30.0, S = 29.0, L = 0.2;
    const glm::dvec3 source(2.0, 1.0, 0.5);
    const double exact = S * rho * (1.0 - std::exp(-E * rho * L)) / (E * rho);  // sigma_s (1 - T) / sigma_t
    double previousError = 1e9;
    for (int n : {1, 2, 7, 64}) {
        glm::dvec3 t(1.0), i(0.0), t16(1.0), i16(0.0);
        for (int k = 0; k < n; ++k) {
            glsl::CloudMarchStep(rho, L / n, E, S, source, true, t, i);
            glsl::CloudMarchStep(rho, L / n, E, S, source, false, t16, i16);
        }
        EXPECT_NEAR(i.x, exact * source.x, 1e-12) << n;
        EXPECT_NEAR(t.x, std::exp(-E * rho * L), 1e-12) << n;   // Eq. 15
        EXPECT_NEAR(t16.x, std::exp(-E * rho * L), 1e-12) << n;
        const double error = std::abs(i16.x - exact * source.x);
        EXPECT_LT(error, previousError) << n;
        previousError = error;
    }
    EXPECT_LT(previousError, 0.05 * exact * source.x);
}

namespace {

class CloudGpu : public test::GLTest {
protected:
    static void SetUpTestSuite() {
        GLTest::SetUpTestSuite();
        // A vacuum: no air, so every attenuation and every bit of light in the probe is the clouds'.
        Scene vacuum;
        vacuum.atmosphere.rayleigh_scattering_per_m = vacuum.atmosphere.mie_scattering_per_m =
            vacuum.atmosphere.mie_extinction_per_m = vacuum.atmosphere.ozone_absorption_per_m = glm::dvec3(0.0);
        vacuumParameters = atmosphere::makeAtmosphereParameters(vacuum);
        atmosphere::GpuPrecompute precompute(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        vacuumTables = std::make_unique<atmosphere::GpuTables>(precompute.compute(vacuumParameters, 1));
    }
    static void TearDownTestSuite() {
        vacuumTables.reset();
        GLTest::TearDownTestSuite();
    }
    static CloudBlock constantLayer(double density, double extinction) {
        Scene s;
        s.clouds.enabled = true;
        s.clouds.constant_density = true;
        s.clouds.density_scale = density;
        s.clouds.extinction_per_km = extinction;
        s.clouds.single_scattering_albedo = 1.0;
        s.clouds.bottom_altitude_km = 1.5;
        s.clouds.top_altitude_km = 4.0;
        s.clouds.step_km = 0.02;
        s.clouds.max_steps = 4096;
        s.clouds.sun_samples = 16;
        s.clouds.sun_step_km = 0.5;  // 8 km: every sun ray's way through the layer here
        s.clouds.multiple_scattering_octaves = 1;  // Eq. 15-16 exactly
        s.clouds.powder = 0.0;
        return makeCloudBlock(s, Camera{}, 0.0);
    }
    static std::vector<CloudProbeResult> probe(const CloudBlock& block, const std::vector<CloudProbeRay>& rays) {
        const atmosphere::AtmosphereUniforms u = atmosphere::makeAtmosphereUniforms(vacuumParameters);
        return probeClouds(test::repoPaths().shaders(), *vacuumTables, u, block, nullptr, rays);
    }
    static inline atmosphere::AtmosphereParameters vacuumParameters;
    static inline std::unique_ptr<atmosphere::GpuTables> vacuumTables;
};

}  // namespace

TEST_F(CloudGpu, ConstantLayerTransmittanceIsBeerLambertOverTheChord) {
    // Michelic Eq. 15 over a uniform layer: T = exp(-E rho chord) from below, inside, above
    // and from space, at zenith angles from straight up to grazing, chords from 2.5 km to
    // hundreds of km (the limb), the chord computed independently (insideBall above).
    const double rho = 0.5, E = 0.8;  // optical depth 1 per 2.5 km: the limb chords stay measurable
    const CloudBlock block = constantLayer(rho, E);
    const double R = 6360.0;
    std::vector<CloudProbeRay> rays;
    std::vector<double> chords;
    for (double altitude : {0.5, 2.5, 6.0, 400.0}) {
        for (double zenithDeg : {0.0, 30.0, 60.0, 80.0, 89.0, 91.0, 95.0, 120.0, 150.0, 180.0}) {
            const double z = glm::radians(zenithDeg);
            CloudProbeRay ray;
            ray.origin = glm::dvec3(0.0, 0.0, R + altitude);
            ray.direction = glm::dvec3(std::sin(z), 0.0, std::cos(z));
            ray.sun = glm::dvec3(0.0, 0.0, 1.0);
            // The ground ends rays that hit it (the sky pass gives the surface's distance).
            const double groundHit = glm::length(ray.origin) > R ? insideBall(ray.origin, ray.direction, R) : 0.0;
            double toGround = 0.0;
            if (groundHit > 0.0) {
                const double b = glm::dot(ray.origin, ray.direction);
                toGround = -b - std::sqrt(b * b - (glm::dot(ray.origin, ray.origin) - R * R));
            }
            ray.distanceKm = toGround;  // 0: to space
            const double chord = shellChord(ray.origin, ray.direction, R + 1.5, R + 4.0, toGround > 0.0 ? toGround : 1e30);
            rays.push_back(ray);
            chords.push_back(chord);
        }
    }
    const std::vector<CloudProbeResult> got = probe(block, rays);
    int measured = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const double expected = std::exp(-E * rho * chords[i]);
        EXPECT_NEAR(got[i].transmittance.x, expected, 2e-4 + 1e-3 * expected)
            << "ray " << i << " chord " << chords[i] << " km, steps " << got[i].steps;
        measured += chords[i] > 0.0;
    }
    EXPECT_GE(measured, 22);  // the rays that cross the layer (the others must see T = 1)
}

TEST_F(CloudGpu, ThinConstantLayerSingleScatteringMatchesItsClosedForm) {
    // Camera below the layer looking straight up at the sun, no air, multiple scattering and
    // powder off: every point of the chord sees the sun through the rest of the layer above
    // it, so L = S rho P(1) E_sun integral_0^H e^{-E rho z} e^{-E rho (H - z)} dz
    //          = S rho P(1) E_sun H e^{-E rho H}.
    const double rho = 0.2, E = 0.1, H = 2.5;  // optical depth 0.05
    CloudBlock block = constantLayer(rho, E);
    const double g = block.phaseGForward;
    CloudProbeRay ray;
    ray.origin = glm::dvec3(0.0, 0.0, 6360.0 + 0.5);
    ray.direction = ray.sun = glm::dvec3(0.0, 0.0, 1.0);
    const CloudProbeResult got = probe(block, {ray})[0];
    const glm::dvec3 sun = vacuumParameters.solar_irradiance;
    const double phase = glsl::HenyeyGreenstein(g, 1.0);
    for (int c = 0; c < 3; ++c) {
        const double expected = E * rho * phase * sun[c] * H * std::exp(-E * rho * H);  // S = E (albedo 1)
        EXPECT_NEAR(got.inscatter[c], expected, 0.01 * expected) << c;
    }
    EXPECT_NEAR(got.transmittance.x, std::exp(-E * rho * H), 5e-5);  // 125 float steps
}
