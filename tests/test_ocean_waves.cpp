// Spherical Gerstner waves (ocean/waves.h, Michelic §4 Eq. 7-11) and the wave-set generator
// (ocean/wave_spectrum.h), against analytic values and finite differences of the surface.
//
// Finite differences: at an undisplaced unit direction v with a tangent frame (e1, e2, v),
// the points v rotated by +-h / r along e1 and e2 give central-difference tangents of the
// displaced surface per metre of undisplaced arc. Their cross product is the true normal, and
// its component along v is the Jacobian determinant of (tangent-plane coordinates) -> surface:
// 1 for the flat sea, <= 0 where the surface folds over (a loop). On the Earth's radius the
// positions (~6.4e6 m) carry ~1e-9 m of rounding, so h = 1 mm gives tangents good to ~1e-6
// and a truncation error (k h)^2 / 6 < 3e-5 for the shortest (0.5 m) waves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "ocean/wave_spectrum.h"
#include "ocean/waves.h"
#include "scene/scene.h"

namespace planet::ocean {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEarthRadius = 6360.0e3;  // m

double degrees(double radians) { return radians * 180.0 / kPi; }

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// Deterministic test randomness: mt19937_64's output is fixed by the standard, its
// distributions are not, so the conversion to [0, 1) is ours.
class TestRandom {
public:
    explicit TestRandom(uint64_t seed) : engine_(seed) {}
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform over the sphere (equal area: z uniform, azimuth uniform).
    glm::dvec3 direction() {
        const double z = uniform(-1.0, 1.0);
        const double phi = uniform(0.0, 2.0 * kPi);
        const double s = std::sqrt(1.0 - z * z);
        return {s * std::cos(phi), s * std::sin(phi), z};
    }

private:
    std::mt19937_64 engine_;
};

// A right-handed orthonormal frame (e1, e2) of the tangent plane at unit v: e1 x e2 = v.
void tangentFrame(const glm::dvec3& v, glm::dvec3& e1, glm::dvec3& e2) {
    const glm::dvec3 helper = std::abs(v.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    e1 = glm::normalize(glm::cross(helper, v));
    e2 = glm::cross(v, e1);
}

// v moved by `distance` metres of arc along the unit tangent t, on a sphere of radius r.
glm::dvec3 moved(const glm::dvec3& v, const glm::dvec3& t, double distance, double r) {
    return std::cos(distance / r) * v + std::sin(distance / r) * t;
}

struct SurfaceTangents {
    glm::dvec3 t1, t2;  // dP/dx1, dP/dx2 per metre of undisplaced arc
    glm::dvec3 v;       // the undisplaced direction
    glm::dvec3 normal() const { return glm::normalize(glm::cross(t1, t2)); }
    double jacobian() const { return glm::dot(glm::cross(t1, t2), v); }
};

SurfaceTangents finiteDifferenceTangents(const std::vector<GerstnerWave>& waves, const glm::dvec3& v, double r,
                                         double t, const WaveFade& fade, double h) {
    glm::dvec3 e1, e2;
    tangentFrame(v, e1, e2);
    const auto P = [&](const glm::dvec3& dir) { return gerstnerPosition(waves, dir, r, t, fade); };
    SurfaceTangents s;
    s.v = v;
    s.t1 = (P(moved(v, e1, h, r)) - P(moved(v, e1, -h, r))) / (2.0 * h);
    s.t2 = (P(moved(v, e2, h, r)) - P(moved(v, e2, -h, r))) / (2.0 * h);
    return s;
}

// 1 - |v . o| for the nearest wave origin or antipode.
double nearestOriginGap(const std::vector<GerstnerWave>& waves, const glm::dvec3& v) {
    double gap = 1.0;
    for (const GerstnerWave& w : waves) gap = std::min(gap, 1.0 - std::abs(glm::dot(v, w.origin)));
    return gap;
}

// A random direction at least `minGap` (in 1 - |v . o|) from every origin and antipode.
glm::dvec3 directionAwayFromOrigins(TestRandom& random, const std::vector<GerstnerWave>& waves, double minGap) {
    for (;;) {
        const glm::dvec3 v = random.direction();
        if (nearestOriginGap(waves, v) > minGap) return v;
    }
}

double sumQAk(const std::vector<GerstnerWave>& waves) {
    double sum = 0.0;
    for (const GerstnerWave& w : waves) sum += w.steepness * w.amplitude_m * w.wavenumber();
    return sum;
}

double sumAk(const std::vector<GerstnerWave>& waves) {
    double sum = 0.0;
    for (const GerstnerWave& w : waves) sum += w.amplitude_m * w.wavenumber();
    return sum;
}

GerstnerWave makeWave(glm::dvec3 origin, double amplitude, double wavelength, double steepness, double phase) {
    GerstnerWave w;
    w.origin = glm::normalize(origin);
    w.amplitude_m = amplitude;
    w.wavelength_m = wavelength;
    w.steepness = steepness;
    w.speed_mps = deepWaterSpeed(wavelength);
    w.phase_rad = phase;
    return w;
}

// Local north and east at the wind point (derivatives of directionFromLatLon).
glm::dvec3 northAt(double latDeg, double lonDeg) {
    const double lat = glm::radians(latDeg), lon = glm::radians(lonDeg);
    return {-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat)};
}
glm::dvec3 eastAt(double lonDeg) {
    const double lon = glm::radians(lonDeg);
    return {-std::sin(lon), std::cos(lon), 0.0};
}

// Unit direction of travel of a wave at v (Eq. 7, normalised).
glm::dvec3 travelAt(const GerstnerWave& w, const glm::dvec3& v) {
    return glm::normalize(v * glm::dot(v, w.origin) - w.origin);
}

// ---------------------------------------------------------------------------------------
// Normals (Eq. 10)

// For one wave, Eq. 10 is the exact normal of Eq. 8 up to the sphere's curvature, terms
// of relative size A / r and Q A / (r sin(angle)) (~1e-6 here): tolerance 0.01 deg.
TEST(OceanNormal, SingleWaveMatchesFiniteDifferences) {
    TestRandom random(11);
    const WaveFade fade;
    double worst = 0.0;
    for (int trial = 0; trial < 40; ++trial) {
        const double wavelength = random.uniform(0.5, 200.0);
        const double k = 2.0 * kPi / wavelength;
        const double amplitude = random.uniform(0.05, 0.6) / k;  // slope A k up to 0.6
        const double steepness = random.uniform(0.0, 1.0);
        const std::vector<GerstnerWave> waves{
            makeWave(random.direction(), amplitude, wavelength, steepness, random.uniform(0.0, 2.0 * kPi))};
        const double time = random.uniform(0.0, 100.0);
        for (int i = 0; i < 50; ++i) {
            const glm::dvec3 v = directionAwayFromOrigins(random, waves, 2.0 * fade.e1);
            const SurfaceTangents fd = finiteDifferenceTangents(waves, v, kEarthRadius, time, fade, wavelength * 2e-4);
            const double angle = degrees(angleBetween(fd.normal(), gerstnerNormal(waves, v, kEarthRadius, time, fade)));
            worst = std::max(worst, angle);
            ASSERT_LT(angle, 0.01) << "trial " << trial << " point " << i;
        }
    }
    RecordProperty("worst_angle_deg", std::to_string(worst));
}

// For many waves Eq. 10 drops the products of different waves' slopes. In the tangent plane
// the exact slope is (I - M)^-1 g, Eq. 10's is g / (1 - tr M), with g = sum A k cos d the
// height gradient and M = sum Q' A k sin d d^T. In M's eigenbasis the difference is
// -lambda_other g_j / ((1 - lambda_j)(1 - tr M)), so the normals differ by at most
//   angle <= m G / (1 - m)^2,  m = sum Q' A k |sin|, G = |g|
// (a normal's direction is 1-Lipschitz in its slope). We assert that bound at each point,
// plus 1e-4 rad for curvature and finite differences, and a fixed ceiling of 3 deg (the
// default sea reaches ~1.4 deg at choppiness 0.9).
TEST(OceanNormal, GeneratedSeaWithinFirstOrderBound) {
    for (double choppiness : {0.3, 0.6, 0.9}) {
        OceanParams params;
        params.choppiness = choppiness;
        params.wave_count = 40;
        const std::vector<GerstnerWave> waves = generateWaves(params);
        const WaveFade fade{params.fade_start, params.fade_end};
        TestRandom random(23);
        double worst = 0.0, sum = 0.0;
        const int samples = 2000;
        for (int i = 0; i < samples; ++i) {
            const glm::dvec3 v = directionAwayFromOrigins(random, waves, 2.0 * fade.e1);
            const double time = random.uniform(0.0, 60.0);
            const SurfaceTangents fd = finiteDifferenceTangents(waves, v, kEarthRadius, time, fade, 1e-3);
            const double angle = angleBetween(fd.normal(), gerstnerNormal(waves, v, kEarthRadius, time, fade));
            double m = 0.0;
            glm::dvec3 g(0.0);
            for (const GerstnerWave& w : waves) {
                const double l = kEarthRadius * angleBetween(v, w.origin);
                const double theta = w.wavenumber() * l - w.angularFrequency() * time + w.phase_rad;
                const double ak = w.amplitude_m * w.wavenumber();
                m += w.steepness * ak * std::abs(std::sin(theta));  // Q' = Q away from the origins
                g += ak * std::cos(theta) * travelAt(w, v);
            }
            const double bound = m * glm::length(g) / ((1.0 - m) * (1.0 - m)) + 1e-4;
            ASSERT_LE(angle, bound) << "choppiness " << choppiness << " point " << i << " m " << m;
            ASSERT_LT(degrees(angle), 3.0);
            worst = std::max(worst, degrees(angle));
            sum += degrees(angle);
        }
        std::printf("[ choppiness %.1f: Eq. 10 vs true normal, mean %.3f deg, max %.3f deg ]\n", choppiness,
                    sum / samples, worst);
    }
}

// ---------------------------------------------------------------------------------------
// Fold-over (Michelic Fig. 8)

// Generated seas with sum Q A k = choppiness <= 0.9: the planar Jacobian is det(I - M) >=
// 1 - m >= 1 - choppiness, so it must stay above 0.1 (minus 1e-3 for finite differences)
// everywhere: at random points, and at and around each wave's origin and antipode, where
// Eq. 11's fade removes the loops of Fig. 8b.
TEST(OceanFoldOver, GeneratedSeaHasPositiveJacobianEverywhere) {
    for (double choppiness : {0.6, 0.9}) {
        OceanParams params;
        params.choppiness = choppiness;
        params.wave_count = 48;
        params.wind_speed_mps = 12.0;
        params.seed = 5;
        const std::vector<GerstnerWave> waves = generateWaves(params);
        const WaveFade fade{params.fade_start, params.fade_end};
        TestRandom random(31);
        std::vector<glm::dvec3> points;
        for (int i = 0; i < 3000; ++i) points.push_back(random.direction());
        // At, and at distances from 1 mm to 500 km of, every origin and antipode.
        for (const GerstnerWave& w : waves) {
            for (double sign : {1.0, -1.0}) {
                const glm::dvec3 centre = sign * w.origin;
                points.push_back(centre);
                glm::dvec3 e1, e2;
                tangentFrame(centre, e1, e2);
                for (double distance : {1e-3, 0.1, 0.5, 1.0, 3.0, 30.0, 1e3, 5e4, 9e4, 1.2e5, 2e5, 5e5}) {
                    const double azimuth = random.uniform(0.0, 2.0 * kPi);
                    const glm::dvec3 heading = std::cos(azimuth) * e1 + std::sin(azimuth) * e2;
                    points.push_back(moved(centre, heading, distance, kEarthRadius));
                }
            }
        }
        double lowest = 1e9;
        for (size_t i = 0; i < points.size(); ++i) {
            const double time = 7.0 * static_cast<double>(i % 11);
            const double jacobian =
                finiteDifferenceTangents(waves, points[i], kEarthRadius, time, fade, 5e-4).jacobian();
            lowest = std::min(lowest, jacobian);
            ASSERT_GT(jacobian, 1.0 - choppiness - 1e-3) << "choppiness " << choppiness << " point " << i;
        }
        std::printf("[ choppiness %.1f: lowest Jacobian %.4f over %zu points ]\n", choppiness, lowest, points.size());
    }
}

// Without the fade, a wave with Q = 1 loops at its origin (Fig. 8b): within Q A of o_i the
// horizontal displacement Q A cos(theta) d_i carries points across the origin when cos < 0,
// and the Jacobian's factor across the wave, 1 + Q A cos(theta) / l, turns negative. With
// the fade (Eq. 11) the same point is fine. Also loops at a crest when Q A k > 1 (Fig. 8d).
// These show the Jacobian test above can fail.
TEST(OceanFoldOver, LoopsAppearWithoutFade) {
    const double r = kEarthRadius;
    const WaveFade off{0.0, 0.0};
    const WaveFade on;  // e0 = 1e-4, e1 = 1e-3
    GerstnerWave w = makeWave({0.3, -0.2, 0.9}, 1.0, 20.0, 1.0, 0.0);
    glm::dvec3 e1, e2;
    tangentFrame(w.origin, e1, e2);
    for (double sign : {1.0, -1.0}) {
        // Near the origin points cross it when cos(theta) < 0 (factor 1 + Q A cos / l), near the
        // antipode when cos(theta) > 0 (factor 1 - Q A cos / l): set the phase to make it so at t = 0.
        w.phase_rad = sign > 0 ? kPi : -std::fmod(w.wavenumber() * r * kPi, 2.0 * kPi);
        const std::vector<GerstnerWave> waves{w};
        for (double distance : {0.2, 0.5}) {
            const glm::dvec3 v = moved(sign * w.origin, e1, distance, r);
            EXPECT_LT(finiteDifferenceTangents(waves, v, r, 0.0, off, 1e-3).jacobian(), 0.0)
                << (sign > 0 ? "origin" : "antipode") << ", distance " << distance;
            EXPECT_GT(finiteDifferenceTangents(waves, v, r, 0.0, on, 1e-3).jacobian(), 0.5)
                << (sign > 0 ? "origin" : "antipode") << ", distance " << distance;
        }
    }
    // Fig. 8d: Q A k = 1.5 > 1 folds at the crest (theta = pi / 2) even with the fade.
    const std::vector<GerstnerWave> steep{makeWave({0, 0, 1}, 1.5 * 20.0 / (2.0 * kPi), 20.0, 1.0, 0.0)};
    TestRandom random(3);
    double lowest = 1e9;
    for (int i = 0; i < 400; ++i) {
        const glm::dvec3 v = directionAwayFromOrigins(random, steep, 0.01);
        lowest = std::min(lowest, finiteDifferenceTangents(steep, v, r, 0.0, on, 1e-3).jacobian());
    }
    EXPECT_LT(lowest, -0.3);  // 1 - Q A k sin(theta) reaches -0.5 at crests
}

// ---------------------------------------------------------------------------------------
// Mean sea level

// The area-weighted mean of the height over the whole sphere is 0 for each wave up to
// O(A / (k r)^2) (the integral of sin(k r a + phi) sin(a) over [0, pi]), plus the lift
// (Q A cos)^2 / (2 r) of the horizontal displacement, Q^2 A^2 / (4 r) on average. On a
// sphere of 200 m with A = 0.25 m, Q = 1, 5 m waves (k r = 251) the lift is 3.1e-4 A and the
// rest under 2e-5 A: asserted |mean| < 1e-3 A, and mean = lift within 5e-5 A. The wave starts at the pole, so the height depends on z only: equal-area cells
// are slices of equal height in z (midpoint rule, 2e5 slices, 2 mm of arc at the equator),
// sampled at three azimuths.
TEST(OceanMeanLevel, SingleWaveOverWholeSphere) {
    const double r = 200.0;
    for (double phase : {0.0, 1.0, 2.5}) {
        for (double time : {0.0, 3.7}) {
            const std::vector<GerstnerWave> waves{makeWave({0, 0, 1}, 0.25, 5.0, 1.0, phase)};
            const int slices = 200000;
            double sum = 0.0;
            int n = 0;
            for (int i = 0; i < slices; ++i) {
                const double z = -1.0 + (i + 0.5) * 2.0 / slices;
                const double s = std::sqrt(1.0 - z * z);
                for (double azimuth : {0.3, 2.4, 4.4}) {
                    const glm::dvec3 v{s * std::cos(azimuth), s * std::sin(azimuth), z};
                    sum += gerstnerHeight(waves, v, r, time, WaveFade{});
                    ++n;
                }
            }
            const double mean = sum / n;
            std::printf("[ phase %.1f, time %.1f: mean height %.2e A ]\n", phase, time, mean / 0.25);
            EXPECT_LT(std::abs(mean), 1e-3 * 0.25) << "phase " << phase << " time " << time;
            EXPECT_NEAR(mean, 0.25 * 0.25 / (4.0 * r), 5e-5 * 0.25) << "phase " << phase << " time " << time;
        }
    }
}

// A generated sea on the Earth's radius, averaged over an equal-area Fibonacci lattice of
// 2e5 points. The lattice spacing (~25 km) is far beyond every wavelength, so the heights at
// its points are as good as independent: the mean has a standard error of sigma / 447
// (sigma = sqrt(sum A^2 / 2), the rms height). Tolerance 0.02 sigma, about 9 standard errors;
// a sea offset by even 2% of its rms height fails.
TEST(OceanMeanLevel, GeneratedSeaOverWholeSphere) {
    OceanParams params;
    params.wave_count = 40;
    const std::vector<GerstnerWave> waves = generateWaves(params);
    const double sigma = significantWaveHeight(waves) / 4.0;
    const int n = 200000;
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    for (double time : {0.0, 11.0}) {
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const double z = 1.0 - (i + 0.5) * 2.0 / n;
            const double s = std::sqrt(1.0 - z * z);
            const double phi = golden * i;
            sum += gerstnerHeight(waves, {s * std::cos(phi), s * std::sin(phi), z}, kEarthRadius, time,
                                  WaveFade{params.fade_start, params.fade_end});
        }
        std::printf("[ time %.0f: mean height %.2e sigma ]\n", time, sum / n / sigma);
        EXPECT_LT(std::abs(sum / n), 0.02 * sigma) << "time " << time << " sigma " << sigma;
    }
}

// ---------------------------------------------------------------------------------------
// No seams: the formulas never use latitude or longitude, so the surface is continuous
// across the date line and over the poles. Points a distance D apart must map to positions
// at most L D apart, with L = 1 + sum Q A k + sum A k the Lipschitz bound of Eq. 8 (plus
// 1e-6 m for rounding at the Earth's radius).

TEST(OceanSeam, ContinuousAcrossDateLineAndPoles) {
    // Wind near the date line and the pole puts origins and antipodes all around them,
    // and one wave starts exactly at the north pole.
    OceanParams params;
    params.wind_latitude_deg = 85.0;
    params.wind_longitude_deg = 179.0;
    params.wave_count = 32;
    std::vector<GerstnerWave> waves = generateWaves(params);
    waves.push_back(makeWave({0, 0, 1}, 0.3, 12.0, 0.5, 0.4));
    const WaveFade fade{params.fade_start, params.fade_end};
    const double lipschitz = 1.0 + sumQAk(waves) + sumAk(waves);
    const double r = kEarthRadius;
    TestRandom random(47);
    for (int i = 0; i < 500; ++i) {
        const double time = random.uniform(0.0, 100.0);
        const double gap = random.uniform(1e-3, 1.0);  // m
        // Date line: (lat, 180 - e) and (lat, -180 + e).
        const double lat = random.uniform(-89.0, 89.0);
        const double halfLonDeg = degrees(0.5 * gap / (r * std::cos(glm::radians(lat))));
        const glm::dvec3 a = directionFromLatLon(lat, 180.0 - halfLonDeg);
        const glm::dvec3 b = directionFromLatLon(lat, -180.0 + halfLonDeg);
        const double distance = r * angleBetween(a, b);
        EXPECT_LE(glm::length(gerstnerPosition(waves, a, r, time, fade) - gerstnerPosition(waves, b, r, time, fade)),
                  lipschitz * distance + 1e-6);
        // Over a pole: (+-(90 - e), lon) and (+-(90 - e), lon + 180).
        const double pole = i % 2 == 0 ? 1.0 : -1.0;
        const double lon = random.uniform(-180.0, 180.0);
        const double halfLatDeg = degrees(0.5 * gap / r);
        const glm::dvec3 c = directionFromLatLon(pole * (90.0 - halfLatDeg), lon);
        const glm::dvec3 d = directionFromLatLon(pole * (90.0 - halfLatDeg), lon + 180.0);
        EXPECT_LE(glm::length(gerstnerPosition(waves, c, r, time, fade) - gerstnerPosition(waves, d, r, time, fade)),
                  lipschitz * r * angleBetween(c, d) + 1e-6);
        // Exactly at the pole, whatever the longitude.
        const glm::dvec3 p1 = directionFromLatLon(pole * 90.0, lon);
        const glm::dvec3 p2 = directionFromLatLon(pole * 90.0, -lon + 37.0);
        EXPECT_LE(glm::length(gerstnerPosition(waves, p1, r, time, fade) - gerstnerPosition(waves, p2, r, time, fade)),
                  lipschitz * r * angleBetween(p1, p2) + 1e-6);
    }
}

// ---------------------------------------------------------------------------------------
// One wave

// Q = 0: a pure radial sine, height A sin(k l - w t + phase) exactly (1e-6 m: rounding of
// |P| ~ 6.4e6 m), displacement along v only.
TEST(OceanSingleWave, ZeroSteepnessIsRadialSine) {
    const double r = kEarthRadius;
    const GerstnerWave w = makeWave({0.2, 0.7, -0.4}, 0.8, 35.0, 0.0, 1.3);
    const std::vector<GerstnerWave> waves{w};
    TestRandom random(5);
    glm::dvec3 e1, e2;
    tangentFrame(w.origin, e1, e2);
    double highest = -1e9, lowest = 1e9;
    for (int i = 0; i < 20000; ++i) {
        const double arc = random.uniform(0.0, kPi * r);
        const double azimuth = random.uniform(0.0, 2.0 * kPi);
        const glm::dvec3 v = moved(w.origin, std::cos(azimuth) * e1 + std::sin(azimuth) * e2, arc, r);
        const double time = random.uniform(0.0, 50.0);
        const glm::dvec3 p = gerstnerPosition(waves, v, r, time, WaveFade{});
        const double theta = w.wavenumber() * arc - w.angularFrequency() * time + w.phase_rad;
        const double expected = w.amplitude_m * std::sin(theta);
        const double height = gerstnerHeight(waves, v, r, time, WaveFade{});
        ASSERT_NEAR(height, expected, 1e-6) << "arc " << arc;
        ASSERT_LT(glm::length(glm::cross(p, v)), 1e-6);  // radial: no horizontal displacement
        highest = std::max(highest, height);
        lowest = std::min(lowest, height);
    }
    EXPECT_NEAR(highest, w.amplitude_m, 1e-3 * w.amplitude_m);
    EXPECT_NEAR(lowest, -w.amplitude_m, 1e-3 * w.amplitude_m);
}

// Arc length from the origin of the crest (highest point) nearest `guess`, found on a grid
// of lambda / 1000 and refined with a parabola through the top three samples.
double crestArc(const std::vector<GerstnerWave>& waves, const glm::dvec3& along, double guess, double time) {
    const GerstnerWave& w = waves[0];
    const double r = kEarthRadius;
    const double step = w.wavelength_m / 1000.0;
    const auto height = [&](double arc) {
        return gerstnerHeight(waves, moved(w.origin, along, arc, r), r, time, WaveFade{});
    };
    double best = guess;
    double bestHeight = -1e9;
    for (int i = -500; i <= 500; ++i) {
        const double arc = guess + i * step;
        const double h = height(arc);
        if (h > bestHeight) {
            bestHeight = h;
            best = arc;
        }
    }
    const double hm = height(best - step), h0 = height(best), hp = height(best + step);
    return best + 0.5 * step * (hm - hp) / (hm - 2.0 * h0 + hp);
}

// The crest moves away from o towards -o at the wave's phase speed: over a quarter period
// it advances a quarter wavelength. Tolerance 1e-3 of a wavelength (the parabolic fit on a
// lambda / 1000 grid is good to ~1e-6 lambda; Q A cos^2 / (2 r) shifts nothing measurable).
TEST(OceanSingleWave, CrestTravelsFromOriginAtPhaseSpeed) {
    for (double steepness : {0.0, 0.7}) {
        const GerstnerWave w = makeWave({-0.5, 0.1, 0.6}, 0.5, 25.0, steepness, 0.9);
        const std::vector<GerstnerWave> waves{w};
        glm::dvec3 e1, e2;
        tangentFrame(w.origin, e1, e2);
        for (double startArc : {5.0e5, 1.0e7, 1.9e7}) {
            const double dt = 0.25 * w.wavelength_m / w.speed_mps;
            const double before = crestArc(waves, e1, startArc, 0.0);
            const double after = crestArc(waves, e1, before + w.speed_mps * dt, dt);
            EXPECT_NEAR(after - before, w.speed_mps * dt, 1e-3 * w.wavelength_m)
                << "steepness " << steepness << " at " << startArc << " m";
            EXPECT_GT(after, before);  // towards -o
        }
    }
}

// Wavelength measured along a great circle: 10 consecutive upward zero crossings of the
// height (bisected to the last bit, ~4e-9 m at 2e7 m) span 10 wavelengths, to 1e-6 relative, near the origin, at
// the equator of the wave and near the antipode.
TEST(OceanSingleWave, WavelengthAlongGreatCircle) {
    const double r = kEarthRadius;
    const GerstnerWave w = makeWave({0.1, -0.9, 0.3}, 0.4, 17.0, 0.0, 0.2);
    const std::vector<GerstnerWave> waves{w};
    glm::dvec3 e1, e2;
    tangentFrame(w.origin, e1, e2);
    const glm::dvec3 along = glm::normalize(e1 - 0.4 * e2);
    const auto height = [&](double arc) {
        return gerstnerHeight(waves, moved(w.origin, along, arc, r), r, 0.0, WaveFade{});
    };
    const auto upCrossing = [&](double from) {  // first upward zero crossing after `from`
        const double step = w.wavelength_m / 64.0;
        double a = from;
        while (!(height(a) < 0.0 && height(a + step) >= 0.0)) a += step;
        double b = a + step;
        for (int i = 0; i < 60; ++i) {  // to the last bit: the bracket is 0.3 m, 2^-60 of it is below an ulp
            const double mid = 0.5 * (a + b);
            (height(mid) < 0.0 ? a : b) = mid;
        }
        return 0.5 * (a + b);
    };
    for (double start : {2.0e3, 1.0e7, 1.99e7}) {
        const double first = upCrossing(start);
        double last = first;
        for (int i = 0; i < 10; ++i) last = upCrossing(last + 0.25 * w.wavelength_m);
        EXPECT_NEAR((last - first) / 10.0, w.wavelength_m, 1e-6 * w.wavelength_m) << "from " << start << " m";
    }
}

// ---------------------------------------------------------------------------------------
// validateWaves

TEST(OceanValidate, WavesFieldByField) {
    const GerstnerWave good = makeWave({0, 0, 1}, 0.5, 20.0, 0.5, 0.0);
    EXPECT_EQ(validateWaves({}), "");
    EXPECT_EQ(validateWaves({good, good}), "");
    const auto badSecond = [&](auto change) {
        GerstnerWave bad = good;
        change(bad);
        return validateWaves({good, bad});
    };
    const double nan = std::nan("");
    const double inf = INFINITY;
    struct Case {
        const char* field;
        std::string message;
    };
    const std::vector<Case> cases{
        {"origin", badSecond([](GerstnerWave& w) { w.origin = {0, 0, 1.001}; })},
        {"origin", badSecond([&](GerstnerWave& w) { w.origin = {nan, 0, 1}; })},
        {"amplitude_m", badSecond([](GerstnerWave& w) { w.amplitude_m = -0.1; })},
        {"amplitude_m", badSecond([&](GerstnerWave& w) { w.amplitude_m = inf; })},
        {"wavelength_m", badSecond([](GerstnerWave& w) { w.wavelength_m = 0.0; })},
        {"wavelength_m", badSecond([&](GerstnerWave& w) { w.wavelength_m = nan; })},
        {"steepness", badSecond([](GerstnerWave& w) { w.steepness = 1.01; })},
        {"steepness", badSecond([](GerstnerWave& w) { w.steepness = -0.01; })},
        {"speed_mps", badSecond([&](GerstnerWave& w) { w.speed_mps = inf; })},
        {"phase_rad", badSecond([&](GerstnerWave& w) { w.phase_rad = nan; })},
    };
    for (const Case& c : cases) {
        EXPECT_NE(c.message.find("wave 1"), std::string::npos) << c.message;
        EXPECT_NE(c.message.find(c.field), std::string::npos) << c.message;
    }
    // Within 1e-6 of unit is accepted; amplitude 0 and steepness 0 or 1 are valid.
    EXPECT_EQ(badSecond([](GerstnerWave& w) { w.origin = {0, 0, 1.0 + 5e-7}; }), "");
    EXPECT_EQ(badSecond([](GerstnerWave& w) { w.amplitude_m = 0.0, w.steepness = 1.0; }), "");
}

// ---------------------------------------------------------------------------------------
// The generator

bool identical(const GerstnerWave& a, const GerstnerWave& b) {
    return a.origin == b.origin && a.amplitude_m == b.amplitude_m && a.wavelength_m == b.wavelength_m &&
           a.steepness == b.steepness && a.speed_mps == b.speed_mps && a.phase_rad == b.phase_rad;
}

TEST(OceanGenerator, DeterministicFromSeed) {
    OceanParams params;
    const std::vector<GerstnerWave> a = generateWaves(params);
    const std::vector<GerstnerWave> b = generateWaves(params);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(identical(a[i], b[i])) << "wave " << i;
    params.seed = 2;
    const std::vector<GerstnerWave> c = generateWaves(params);
    ASSERT_EQ(a.size(), c.size());
    int same = 0;
    for (size_t i = 0; i < a.size(); ++i) same += identical(a[i], c[i]) ? 1 : 0;
    EXPECT_EQ(same, 0);
    // Seed 0 is a seed like any other.
    params.seed = 0;
    EXPECT_FALSE(identical(generateWaves(params)[0], a[0]));
}

TEST(OceanGenerator, CountValidityAndChoppiness) {
    OceanParams params;
    params.wave_count = 0;
    EXPECT_TRUE(generateWaves(params).empty());
    params.wave_count = -3;
    EXPECT_TRUE(generateWaves(params).empty());

    // Corners of the parameter ranges (ocean_params.h), each must give valid waves.
    std::vector<OceanParams> variants;
    for (int count : {1, 2, 7, 40, 4096}) {
        for (double choppiness : {0.0, 0.6, 1.0}) {
            OceanParams p;
            p.wave_count = count;
            p.choppiness = choppiness;
            variants.push_back(p);
        }
    }
    const auto variant = [&](auto change) {
        OceanParams p;
        change(p);
        variants.push_back(p);
    };
    variant([](OceanParams& p) { p.wind_speed_mps = 0.5; });
    variant([](OceanParams& p) { p.wind_speed_mps = 40.0, p.wave_count = 300; });
    variant([](OceanParams& p) { p.fetch_km = 0.001; });
    variant([](OceanParams& p) { p.fetch_km = 10000.0; });
    variant([](OceanParams& p) { p.directional_spread_deg = 0.0; });
    variant([](OceanParams& p) { p.directional_spread_deg = 180.0; });
    variant([](OceanParams& p) { p.min_wavelength_m = 0.01; });
    variant([](OceanParams& p) { p.min_wavelength_m = 10000.0; });
    variant([](OceanParams& p) { p.wind_latitude_deg = 90.0, p.wind_bearing_deg = -360.0; });
    variant([](OceanParams& p) { p.wind_latitude_deg = -90.0, p.wind_longitude_deg = 180.0; });
    variant([](OceanParams& p) { p.seed = 1000000; });
    // Out of range or not a number: clamped, still valid waves.
    variant([](OceanParams& p) {
        p.wind_latitude_deg = NAN, p.wind_bearing_deg = INFINITY, p.wind_speed_mps = -1.0, p.choppiness = 3.0;
    });
    for (size_t i = 0; i < variants.size(); ++i) {
        const OceanParams& p = variants[i];
        const std::vector<GerstnerWave> waves = generateWaves(p);
        ASSERT_EQ(waves.size(), static_cast<size_t>(p.wave_count)) << "variant " << i;
        EXPECT_EQ(validateWaves(waves), "") << "variant " << i;
        // Finch's rule keeps sum Q A k at most the choppiness (rounding: 1e-12).
        EXPECT_LE(sumQAk(waves), p.choppiness + 1e-12) << "variant " << i;
        for (const GerstnerWave& w : waves) {
            // Deep-water dispersion w^2 = g k, to rounding.
            const double k = w.wavenumber(), omega = w.angularFrequency();
            ASSERT_NEAR(omega * omega / (kGravity * k), 1.0, 1e-12) << "variant " << i;
            ASSERT_GT(w.wavelength_m, p.min_wavelength_m * (1.0 - 1e-12)) << "variant " << i;
        }
    }
}

// H_s = 4 sqrt(m0). Pierson-Moskowitz's m0 = alpha g^2 / (5 w_p^4) gives H_s = 0.2202 U^2 / g
// (the quoted 0.21 U^2 / g is a rounder fit). The generator carries each stratum's whole
// energy, so what it misses is only the truncation: below 0.5 w_p exp(-20) of the energy, above
// the 0.5 m waves a fraction 1.25 (w_p / w_max)^4, under 0.6% for U >= 3 m/s (H_s: half that),
// plus < 0.1% of quadrature. Asserted: within 1% of 0.2202 U^2 / g, and so within 6% of
// 0.21 U^2 / g; growing with the wind; the same for any wave count.
TEST(OceanGenerator, SignificantWaveHeightPiersonMoskowitz) {
    for (int seed : {1, 2, 3}) {
        double previous = 0.0;
        for (double wind : {3.0, 5.0, 8.0, 12.0, 16.0, 20.0, 40.0}) {
            OceanParams params;
            params.seed = seed;
            params.wind_speed_mps = wind;
            const double hs = significantWaveHeight(generateWaves(params));
            const double analytic = 4.0 * std::sqrt(8.1e-3 / (5.0 * std::pow(0.855, 4.0))) * wind * wind / kGravity;
            EXPECT_NEAR(hs / analytic, 1.0, 0.01) << "seed " << seed << " wind " << wind << " H_s " << hs;
            EXPECT_NEAR(hs / (0.21 * wind * wind / kGravity), 1.0, 0.06) << "seed " << seed << " wind " << wind;
            EXPECT_GT(hs, previous) << "seed " << seed << " wind " << wind;
            previous = hs;
        }
    }
    OceanParams params;
    const double reference = significantWaveHeight(generateWaves(params));
    for (int count : {1, 2, 5, 4096}) {
        params.wave_count = count;
        EXPECT_NEAR(significantWaveHeight(generateWaves(params)) / reference, 1.0, 0.005) << count << " waves";
    }
}

// JONSWAP: a limited fetch gives a smaller, growing sea. Hasselmann et al. 1973 fit
// g H_s / U^2 = 1.6e-3 (g F / U^2)^(1/2); the spectrum's parameters are fits of their own,
// so the two agree only roughly: within a factor 1.5. A fetch past full development
// (g F / U^2 ~ 17000) changes nothing.
TEST(OceanGenerator, SignificantWaveHeightJonswap) {
    const double wind = 10.0;
    double previous = 0.0;
    for (double fetchKm : {5.0, 20.0, 50.0, 100.0}) {
        OceanParams params;
        params.wind_speed_mps = wind;
        params.fetch_km = fetchKm;
        params.wave_count = 256;
        const double hs = significantWaveHeight(generateWaves(params));
        const double fit = 1.6e-3 * std::sqrt(kGravity * fetchKm * 1e3 / (wind * wind)) * wind * wind / kGravity;
        EXPECT_GT(hs / fit, 1.0 / 1.5) << "fetch " << fetchKm << " km, H_s " << hs << ", fit " << fit;
        EXPECT_LT(hs / fit, 1.5) << "fetch " << fetchKm << " km, H_s " << hs << ", fit " << fit;
        EXPECT_GT(hs, previous);
        previous = hs;
    }
    OceanParams long1, long2;
    long1.fetch_km = 5000.0;
    long2.fetch_km = 9000.0;
    EXPECT_EQ(significantWaveHeight(generateWaves(long1)), significantWaveHeight(generateWaves(long2)));
    // The peak frequency of a limited fetch is above Pierson-Moskowitz's.
    OceanParams pm, jonswap;
    jonswap.fetch_km = 20.0;
    EXPECT_GT(spectrumPeakFrequency(jonswap), spectrumPeakFrequency(pm));
}

// At the wind point the amplitude-weighted mean direction of travel is the wind bearing:
// within 3 deg for 40 waves (antithetic pairs cancel all but the amplitude difference of
// neighbouring frequencies) and within 1 deg for 1024; every wave within 90 deg of it.
// 200 km away it is still within 5 deg; at the wind point's antipode the waves have
// converged from their origins and their directions spread much more widely.
TEST(OceanGenerator, MeanDirectionFollowsWind) {
    for (int seed : {1, 2, 3, 4, 5}) {
        for (int count : {40, 1024}) {
            for (double bearing : {60.0, -135.0, 0.0}) {
                OceanParams params;
                params.seed = seed;
                params.wave_count = count;
                params.wind_bearing_deg = bearing;
                params.wind_latitude_deg = seed == 5 ? 89.9 : 43.0;
                const std::vector<GerstnerWave> waves = generateWaves(params);
                const glm::dvec3 wind = directionFromLatLon(params.wind_latitude_deg, params.wind_longitude_deg);
                const glm::dvec3 north = northAt(params.wind_latitude_deg, params.wind_longitude_deg);
                const glm::dvec3 east = eastAt(params.wind_longitude_deg);
                const glm::dvec3 downwind =
                    std::cos(glm::radians(bearing)) * north + std::sin(glm::radians(bearing)) * east;
                const auto meanDirectionError = [&](const glm::dvec3& v, const glm::dvec3& expected) {
                    glm::dvec3 mean(0.0);
                    for (const GerstnerWave& w : waves) mean += w.amplitude_m * travelAt(w, v);
                    return degrees(angleBetween(mean, expected));
                };
                const double tolerance = count == 40 ? 3.0 : 1.0;
                EXPECT_LT(meanDirectionError(wind, downwind), tolerance)
                    << "seed " << seed << " count " << count << " bearing " << bearing;
                for (const GerstnerWave& w : waves) ASSERT_GE(glm::dot(travelAt(w, wind), downwind), -1e-12);
                // 200 km downwind: the great circle along the wind, carried along.
                const glm::dvec3 there = moved(wind, downwind, 2e5, kEarthRadius);
                const glm::dvec3 downwindThere = glm::normalize(glm::cross(glm::cross(wind, downwind), there));
                EXPECT_LT(meanDirectionError(there, downwindThere), 5.0) << "seed " << seed << " count " << count;
            }
        }
    }
    // Far away the directions differ: the amplitude-weighted coherence |sum A d| / sum A
    // (1: all parallel) drops 140 deg downwind, among the waves' antipodes (120 to 160 deg
    // downwind), where some still run downwind and those past their antipode converge back
    // onto it. (Not at the wind point's antipode: every great circle through the wind point
    // passes there, and the directions repeat; nor 90 deg crosswind, where waves from the
    // compact source region all arrive from it, as swell from a distant storm does.)
    OceanParams params;
    const std::vector<GerstnerWave> waves = generateWaves(params);
    const glm::dvec3 wind = directionFromLatLon(params.wind_latitude_deg, params.wind_longitude_deg);
    const double bearing = glm::radians(params.wind_bearing_deg);
    const glm::dvec3 downwind = std::cos(bearing) * northAt(params.wind_latitude_deg, params.wind_longitude_deg) +
                                std::sin(bearing) * eastAt(params.wind_longitude_deg);
    const auto coherence = [&](const glm::dvec3& v) {
        glm::dvec3 mean(0.0);
        double total = 0.0;
        for (const GerstnerWave& w : waves) {
            mean += w.amplitude_m * travelAt(w, v);
            total += w.amplitude_m;
        }
        return glm::length(mean) / total;
    };
    const glm::dvec3 farDownwind = moved(wind, downwind, glm::radians(140.0) * kEarthRadius, kEarthRadius);
    std::printf("[ coherence: wind point %.3f, 140 deg downwind %.3f ]\n", coherence(wind), coherence(farDownwind));
    EXPECT_LT(coherence(farDownwind), coherence(wind) - 0.2);
}

TEST(OceanGenerator, ValidateOceanParams) {
    OceanParams params;
    EXPECT_EQ(validateOceanParams(params), "");
    params.fade_start = 1e-3;
    params.fade_end = 1e-3;
    EXPECT_NE(validateOceanParams(params).find("fade_end"), std::string::npos);
    params.fade_end = 1e-4;
    EXPECT_NE(validateOceanParams(params).find("fade_start"), std::string::npos);
    params.fade_start = 0.0;
    EXPECT_EQ(validateOceanParams(params), "");
}

}  // namespace
}  // namespace planet::ocean

// The foam at the shore (waves.h, foamCover; the GPU's copy in ocean_waves.glsl): one wave
// of amplitude A breaks shoreward of d_b = A / 0.39 and keeps (0.39 d)^2 of its energy, so the
// cover is 0.39 d / A x 35/128 there: none in deeper water, none at the waterline, the crest
// mean just inside the breaking line; two waves weigh by their energies.
TEST(OceanFoam, CoverPeaksAtTheBreakingLineAndVanishesAtTheWaterline) {
    using planet::ocean::foamCover;
    using planet::ocean::kFoamCrestMean;
    planet::ocean::GerstnerWave big;
    big.amplitude_m = 1.0;
    const std::vector<planet::ocean::GerstnerWave> one{big};
    const double breaking = 1.0 / 0.39;
    EXPECT_EQ(foamCover(one, breaking + 0.01), 0.0);
    EXPECT_EQ(foamCover(one, 50.0), 0.0);
    EXPECT_EQ(foamCover(one, 0.0), 0.0);
    EXPECT_NEAR(foamCover(one, 0.5 * breaking), 0.5 * kFoamCrestMean, 1e-12);
    EXPECT_NEAR(foamCover(one, 0.999 * breaking), 0.999 * kFoamCrestMean, 1e-12);
    EXPECT_NEAR(kFoamCrestMean, 35.0 / 128.0, 0.0);
    // The crest pattern's mean, ((1 + sin x) / 2)^4 over a period, by quadrature.
    double mean = 0.0;
    const int n = 4096;
    for (int i = 0; i < n; ++i) mean += std::pow(0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * (i + 0.5) / n), 4.0);
    EXPECT_NEAR(mean / n, kFoamCrestMean, 1e-9);
    // Two waves: A = 1 keeps 0.39, A = 0.5 keeps 0.78 at 1 m; energies 1 and 0.25.
    planet::ocean::GerstnerWave small;
    small.amplitude_m = 0.5;
    const std::vector<planet::ocean::GerstnerWave> two{big, small};
    EXPECT_NEAR(foamCover(two, 1.0), (1.0 * 0.39 + 0.25 * 0.78) / 1.25 * kFoamCrestMean, 1e-12);
    // At 1.5 m only the big one breaks: (1 x 0.585) / 1.25.
    EXPECT_NEAR(foamCover(two, 1.5), 0.585 / 1.25 * kFoamCrestMean, 1e-12);
    EXPECT_EQ(foamCover({}, 1.0), 0.0);
}
