// The atmosphere model (shaders/atmosphere/*.glsl compiled as C++, double
// precision) against closed forms, limits and symmetries.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "atmosphere/parameters.h"
#include "atmosphere/reference_tables.h"

using namespace planet;
using namespace planet::atmosphere;

namespace {

constexpr double kPi = 3.14159265358979323846;

AtmosphereParameters earth() { return makeAtmosphereParameters(Scene{}); }

AtmosphereParameters rayleighOnly() {
    AtmosphereParameters a = earth();
    a.mie_scattering = a.mie_extinction = glm::dvec3(0.0);
    a.absorption_extinction = glm::dvec3(0.0);
    return a;
}

AtmosphereParameters vacuum() {
    AtmosphereParameters a = earth();
    a.rayleigh_scattering = a.mie_scattering = a.mie_extinction = a.absorption_extinction = glm::dvec3(0.0);
    return a;
}

// Tables are costly; compute each atmosphere once for the whole suite.
const ReferenceResult& tablesFor(const std::string& name) {
    static std::map<std::string, ReferenceResult> cache;
    auto it = cache.find(name);
    if (it != cache.end()) return it->second;
    const AtmosphereParameters a = name == "earth" ? earth() : name == "rayleigh" ? rayleighOnly() : vacuum();
    return cache.emplace(name, computeReferenceTables(a, TableSizes::reduced(), 4)).first->second;
}

// Sky radiance for a camera at altitude h (km), sun at zenith angle sunZenith,
// view at zenith angle viewZenith and azimuth from the sun (radians).
glm::dvec3 skyRadiance(const std::string& name, const AtmosphereParameters& a, double h, double sunZenith,
                       double viewZenith, double viewAzimuth, glm::dvec3* transmittance = nullptr) {
    const ReferenceResult& r = tablesFor(name);
    Model model(r.tables.sizes);
    const glm::dvec3 camera(0.0, 0.0, a.bottom_radius + h);
    const glm::dvec3 sun(std::sin(sunZenith), 0.0, std::cos(sunZenith));
    const glm::dvec3 view(std::sin(viewZenith) * std::cos(viewAzimuth), std::sin(viewZenith) * std::sin(viewAzimuth),
                          std::cos(viewZenith));
    glm::dvec3 t;
    const glm::dvec3 L = model.GetSkyRadiance(a, r.tables.transmittance, r.tables.scattering, r.tables.singleMie,
                                              camera, view, sun, t);
    if (transmittance) *transmittance = t;
    return L;
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

TEST(AtmosphereModel, VerticalTransmittanceMatchesClosedForm) {
    // Straight up from the ground the optical depth of an exponential profile
    // is beta H (1 - exp(-(top - bottom) / H)); a tent of width w lying inside
    // the atmosphere contributes beta w / 2.
    const AtmosphereParameters a = earth();
    const Scene s;
    const double thickness = a.top_radius - a.bottom_radius;
    auto expDepth = [&](double H) { return H * (1.0 - std::exp(-thickness / H)); };
    const glm::dvec3 depth = a.rayleigh_scattering * expDepth(s.atmosphere.rayleigh_scale_height_km) +
                             a.mie_extinction * expDepth(s.atmosphere.mie_scale_height_km) +
                             a.absorption_extinction * (s.atmosphere.ozone_width_km / 2.0);
    const glm::dvec3 expected = glm::exp(-depth);
    Model model(TableSizes::reduced());
    const glm::dvec3 computed = model.ComputeTransmittanceToTopAtmosphereBoundary(a, a.bottom_radius, 1.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(computed[c], expected[c], expected[c] * 1e-5) << c;
    // Through the table (interpolated), still within 0.1 %.
    const glm::dvec3 table =
        model.GetTransmittanceToTopAtmosphereBoundary(a, tablesFor("earth").tables.transmittance, a.bottom_radius, 1.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(table[c], expected[c], expected[c] * 1e-3) << c;
}

TEST(AtmosphereModel, TentProfileIsOneAtPeakAndZeroOutside) {
    const DensityProfile p = tentProfile(25.0, 30.0);
    Model model(TableSizes::reduced());
    EXPECT_NEAR(model.GetProfileDensity(p, 25.0), 1.0, 1e-12);
    EXPECT_NEAR(model.GetProfileDensity(p, 17.5), 0.5, 1e-12);
    EXPECT_NEAR(model.GetProfileDensity(p, 32.5), 0.5, 1e-12);
    EXPECT_EQ(model.GetProfileDensity(p, 5.0), 0.0);
    EXPECT_EQ(model.GetProfileDensity(p, 45.0), 0.0);
    EXPECT_NEAR(model.GetProfileDensity(exponentialProfile(8.0), 8.0), std::exp(-1.0), 1e-12);
}

TEST(AtmosphereModel, PhaseFunctionsIntegrateToOne) {
    Model model(TableSizes::reduced());
    const int n = 20000;
    double rayleigh = 0.0, mie = 0.0;
    for (int i = 0; i < n; ++i) {  // integrate over nu in [-1, 1] times 2 pi (midpoint rule)
        const double nu = -1.0 + (i + 0.5) * 2.0 / n;
        rayleigh += model.RayleighPhaseFunction(nu) * 2.0 * kPi * 2.0 / n;
        mie += model.MiePhaseFunction(0.8, nu) * 2.0 * kPi * 2.0 / n;
    }
    EXPECT_NEAR(rayleigh, 1.0, 1e-6);
    EXPECT_NEAR(mie, 1.0, 1e-3);
    // Cornette-Shanks with g = 0 is the Rayleigh phase function (Elek Eq. 2 vs Eq. 3).
    EXPECT_NEAR(model.MiePhaseFunction(0.0, 0.3), model.RayleighPhaseFunction(0.3), 1e-12);
}

TEST(AtmosphereModel, TableCoordinatesRoundTrip) {
    const AtmosphereParameters a = earth();
    Model model(TableSizes::reduced());
    for (double r : {a.bottom_radius, a.bottom_radius + 1.0, a.bottom_radius + 30.0, a.top_radius}) {
        for (double mu : {-1.0, -0.5, -0.01, 0.0, 0.2, 1.0}) {
            double r2 = 0.0, mu2 = 0.0;
            model.GetRMuFromTransmittanceTextureUv(a, model.GetTransmittanceTextureUvFromRMu(a, r, mu), r2, mu2);
            EXPECT_NEAR(r2, r, 1e-6) << r << " " << mu;
            // At the top boundary every upward ray has length 0, so mu is not recoverable there.
            if (!model.RayIntersectsGround(a, r, mu) && r < a.top_radius) {
                EXPECT_NEAR(mu2, mu, 1e-6) << r << " " << mu;
            }
        }
    }
    for (double mu_s : {-0.2, 0.0, 0.5, 1.0}) {
        const double r = a.bottom_radius + 5.0, mu = 0.3, nu = 0.2;
        double r2, mu2, mu_s2, nu2;
        bool ground;
        model.GetRMuMuSNuFromScatteringTextureUvwz(
            a, model.GetScatteringTextureUvwzFromRMuMuSNu(a, r, mu, mu_s, nu, false), r2, mu2, mu_s2, nu2, ground);
        EXPECT_NEAR(r2, r, 1e-6);
        EXPECT_NEAR(mu2, mu, 1e-6);
        EXPECT_NEAR(mu_s2, mu_s, 1e-6);
        EXPECT_NEAR(nu2, nu, 1e-9);
        EXPECT_FALSE(ground);
    }
}

TEST(AtmosphereModel, NoParticlesMeansFullTransmittanceAndBlackSky) {
    const ReferenceResult& r = tablesFor("vacuum");
    for (const glm::dvec4& t : r.tables.transmittance.texels) EXPECT_NEAR(t.r, 1.0, 1e-12);
    for (const glm::dvec4& s : r.tables.scattering.texels) EXPECT_EQ(s.r + s.g + s.b, 0.0);
    for (const glm::dvec4& e : r.tables.irradiance.texels) EXPECT_EQ(e.r + e.g + e.b, 0.0);
    const glm::dvec3 L = skyRadiance("vacuum", vacuum(), 0.001, 0.3, 0.5, 0.0);
    EXPECT_EQ(L, glm::dvec3(0.0));
}

TEST(AtmosphereModel, EachOrderAddsLessThanTheOneBefore) {
    const ReferenceResult& r = tablesFor("earth");
    ASSERT_EQ(r.orderMeans.size(), 4u);
    for (std::size_t i = 1; i < r.orderMeans.size(); ++i) {
        EXPECT_GT(r.orderMeans[i], 0.0) << "order " << i + 1;
        EXPECT_LT(r.orderMeans[i], r.orderMeans[i - 1]) << "order " << i + 1;
    }
}

TEST(AtmosphereModel, RayleighNoonSkyIsBluerAtZenithThanAtHorizon) {
    const glm::dvec3 zenith = skyRadiance("rayleigh", rayleighOnly(), 0.001, 0.0, 0.0, 0.0);
    const glm::dvec3 horizon = skyRadiance("rayleigh", rayleighOnly(), 0.001, 0.0, glm::radians(89.0), 0.0);
    EXPECT_GT(zenith.b / zenith.r, horizon.b / horizon.r);
    EXPECT_GT(zenith.b, zenith.r);  // and blue at all
}

TEST(AtmosphereModel, SunsetSkyNearTheSunIsRedderThanAtNoon) {
    const glm::dvec3 noon = skyRadiance("earth", earth(), 0.001, glm::radians(30.0), glm::radians(35.0), 0.0);
    const glm::dvec3 sunset = skyRadiance("earth", earth(), 0.001, glm::radians(89.0), glm::radians(87.0), 0.0);
    EXPECT_GT(sunset.r / sunset.b, noon.r / noon.b);
}

TEST(AtmosphereModel, SkyIsMirrorSymmetricInAzimuth) {
    for (double az : {0.3, 1.2, 2.5}) {
        const glm::dvec3 a = skyRadiance("earth", earth(), 1.0, glm::radians(60.0), glm::radians(70.0), az);
        const glm::dvec3 b = skyRadiance("earth", earth(), 1.0, glm::radians(60.0), glm::radians(70.0), -az);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-9 * std::max(1.0, a[c])) << az;
    }
}

TEST(AtmosphereModel, NoNanOrInfForAnyCameraOrSun) {
    const AtmosphereParameters a = earth();
    for (const auto& t : tablesFor("earth").tables.scattering.texels)
        ASSERT_TRUE(std::isfinite(t.r) && std::isfinite(t.g) && std::isfinite(t.b) && std::isfinite(t.a));
    for (double h : {0.0, 0.001, 10.0, 59.9, 60.0, 100.0, 36000.0}) {       // km: ground to far outside
        for (double sunZenith : {0.0, glm::radians(60.0), glm::radians(100.0)}) {  // 100 deg: 10 deg below horizon
            for (double viewZenith : {0.0, glm::radians(89.9), glm::radians(90.0), glm::radians(120.0), kPi}) {
                glm::dvec3 t;
                const glm::dvec3 L = skyRadiance("earth", a, h, sunZenith, viewZenith, 0.7, &t);
                EXPECT_TRUE(finite(L) && finite(t)) << h << " " << sunZenith << " " << viewZenith;
                EXPECT_GE(glm::min(L.r, glm::min(L.g, L.b)), 0.0);
            }
        }
    }
}

TEST(AtmosphereModel, SpaceViewMissingTheAtmosphereIsBlackAndClear) {
    glm::dvec3 t;
    const glm::dvec3 L = skyRadiance("earth", earth(), 36000.0, 0.0, 0.0, 0.0, &t);  // looking away from the planet
    EXPECT_EQ(L, glm::dvec3(0.0));
    EXPECT_EQ(t, glm::dvec3(1.0));
}

TEST(AtmosphereModel, ShadowLengthRemovesTheFarInScatteringButNotTheTransmittance) {
    // Bruneton's shadow_length (the interface's SunShadowLength hook): none gives the plain
    // aerial perspective; the whole segment in shadow gives no in-scattering and the same
    // transmittance; more shadow, less light (a 20 km horizontal segment from 1 km up).
    const AtmosphereParameters a = earth();
    const ReferenceResult& r = tablesFor("earth");
    Model model(r.tables.sizes);
    const glm::dvec3 camera(0.0, 0.0, a.bottom_radius + 1.0);
    const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 0.0, 1.0));
    const glm::dvec3 view = glm::normalize(glm::dvec3(1.0, 0.2, -0.02));
    const double d = 20.0;
    glm::dvec3 t0, t1, tAll, tHalf;
    const glm::dvec3 plain = model.GetSkyRadianceToPointAlongRay(a, r.tables.transmittance, r.tables.scattering,
                                                                 r.tables.singleMie, camera, view, d, sun, t0);
    auto shadowed = [&](double length, glm::dvec3& t) {
        return model.GetSkyRadianceToPointAlongRayFrom(a, false, r.tables.transmittance, r.tables.scattering,
                                                       r.tables.singleMie, camera, view, d, sun, length, t);
    };
    EXPECT_EQ(shadowed(0.0, t1), plain);
    EXPECT_EQ(t1, t0);
    const glm::dvec3 half = shadowed(d / 2, tHalf);
    const glm::dvec3 all = shadowed(d, tAll);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(tHalf[c], t0[c], 1e-12);
        EXPECT_NEAR(tAll[c], t0[c], 1e-12);
        EXPECT_NEAR(all[c], 0.0, 1e-12 + 1e-9 * plain[c]);
        EXPECT_GT(half[c], 0.2 * plain[c]);
        EXPECT_LT(half[c], 0.8 * plain[c]);
    }
}
