// The height field near the camera (terrain/height.glsl TerrainNear, terrainHeightNearGrad,
// terrainRayHitNear; compiled as C++ by terrain/height.cpp): the same field as
// terrainHeight, without float's rounding of planet-sized directions, and the ray's meeting
// with it, which places the ground detail (terrain/ground_material.frag). A wrong split of the noise point,
// a wrong direction change or a wrong Newton derivative breaks the agreement with the float
// field, the smoothness, or the convergence below.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "noise/continents.h"
#include "terrain/height.h"

using namespace planet;

namespace {

constexpr double kRadiusM = 6360.0e3;

// The default mountains (8 octaves from 120 per radius: features down to 400 m) over a
// small continents map.
struct NearTerrain {
    NearTerrain() {
        TerrainParams p;
        p.continent_map_size = 256;  // texels of 25 km (the default 512: 12 km)
        shape = terrain::makeTerrainShape(p);
        continents = noise::bakeContinents(terrain::continentParams(p), p.continent_map_size);
    }
    float height(glm::dvec3 position) const {
        return terrain::terrainHeight(glm::vec3(glm::normalize(position)), shape, continents);
    }
    // An inland direction (well above the coast), where the mountains count.
    glm::dvec3 inland(unsigned seed) const {
        std::mt19937 rng(seed);
        std::normal_distribution<double> n(0.0, 1.0);
        for (;;) {
            const double x = n(rng), y = n(rng), z = n(rng);
            const glm::dvec3 d = glm::normalize(glm::dvec3(x, y, z));
            if (terrain::continentValue(glm::vec3(d), continents) > 0.3f) return d;
        }
    }
    terrain::TerrainShape shape;
    noise::CubeMap continents;
};

const NearTerrain& nearTerrain() {
    static const NearTerrain t;
    return t;
}

// A camera `altitudeM` above the ground at direction `up`.
glm::dvec3 cameraAbove(const NearTerrain& t, glm::dvec3 up, double altitudeM) {
    return up * (kRadiusM + t.height(up * kRadiusM) + altitudeM);
}

// Two unit tangents at `up`.
void tangents(glm::dvec3 up, glm::dvec3& east, glm::dvec3& north) {
    east = glm::normalize(glm::cross(glm::dvec3(0.0, 0.0, 1.0), up));
    north = glm::cross(up, east);
}

}  // namespace

// At points up to TERRAIN_NEAR_RANGE_M from the camera the near field is the float field:
// they differ by the float field's own rounding (centimetres, tens of them on steep slopes,
// where half a metre of direction is a lot of height) and the continents' first order:
// nowhere by more than 0.5 m, in the median by under 5 cm.
TEST(TerrainNear, IsTheHeightFieldNearTheCamera) {
    const NearTerrain& t = nearTerrain();
    std::vector<double> errors, farErrors;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (unsigned site = 0; site < 8; ++site) {
        const glm::dvec3 up = t.inland(100 + site);
        const glm::dvec3 camera = cameraAbove(t, up, 2.0);
        const terrain::TerrainNear near = terrain::makeTerrainNear(t.shape, t.continents, camera, kRadiusM);
        glm::dvec3 east, north;
        tangents(up, east, north);
        for (int i = 0; i < 64; ++i) {
            const double distance = 3000.0 * std::pow(unit(rng), 2.0), angle = 6.283 * unit(rng);
            const glm::dvec3 ground = up * kRadiusM + distance * (std::cos(angle) * east + std::sin(angle) * north);
            const glm::dvec3 point = glm::normalize(ground) * kRadiusM - camera;  // camera-relative
            glm::vec3 gradient;
            const float nearHeight = terrain::terrainHeightNearGrad(glm::vec3(point), near, t.shape, gradient);
            errors.push_back(std::abs(double(nearHeight) - t.height(camera + point)));
            if (distance > 1000.0) farErrors.push_back(errors.back());
        }
    }
    std::sort(errors.begin(), errors.end());
    const double median = errors[errors.size() / 2], worst = errors.back();
    std::sort(farErrors.begin(), farErrors.end());
    std::printf("near field - float field over %zu points within 3 km: median %.4f m, worst %.4f m (%.4f m beyond 1 km)\n",
                errors.size(), median, worst, farErrors.empty() ? 0.0 : farErrors.back());
    EXPECT_LT(median, 0.05);
    EXPECT_LT(worst, 0.5);  // a misplaced octave or continent would be metres to hundreds of metres off
}

// Along a metre of ground in millimetre steps the near field is smooth: its second
// differences stay at the rounding of the heights (millimetres), where the float field steps by centimetres every
// half metre (its directions round to 6e-8). And its gradient is the finite difference.
TEST(TerrainNear, IsSmoothAtTheMillimetreWhereTheFloatFieldSteps) {
    const NearTerrain& t = nearTerrain();
    double nearWorst = 0.0, floatWorst = 0.0, gradientWorst = 0.0;
    for (unsigned site = 0; site < 4; ++site) {
        const glm::dvec3 up = t.inland(200 + site);
        const glm::dvec3 camera = cameraAbove(t, up, 2.0);
        const terrain::TerrainNear near = terrain::makeTerrainNear(t.shape, t.continents, camera, kRadiusM);
        glm::dvec3 east, north;
        tangents(up, east, north);
        const glm::dvec3 start = up * kRadiusM + 10.0 * north - camera;
        std::vector<double> nearHeights, floatHeights;
        for (int i = 0; i <= 1000; ++i) {
            const glm::dvec3 point = start + 0.001 * i * east;
            glm::vec3 gradient;
            nearHeights.push_back(terrain::terrainHeightNearGrad(glm::vec3(point), near, t.shape, gradient));
            floatHeights.push_back(t.height(camera + point));
            if (i == 500) {  // the gradient (per radian) along east, against a 0.5 m central difference
                glm::vec3 unused;
                const double ahead = terrain::terrainHeightNearGrad(glm::vec3(point + 0.5 * east), near, t.shape, unused);
                const double behind = terrain::terrainHeightNearGrad(glm::vec3(point - 0.5 * east), near, t.shape, unused);
                const double slope = glm::dot(glm::dvec3(gradient), east) / kRadiusM;  // m per m
                gradientWorst = std::max(gradientWorst, std::abs(slope - (ahead - behind) / 1.0));
            }
        }
        for (std::size_t i = 1; i + 1 < nearHeights.size(); ++i) {
            nearWorst = std::max(nearWorst, std::abs(nearHeights[i + 1] - 2.0 * nearHeights[i] + nearHeights[i - 1]));
            floatWorst = std::max(floatWorst, std::abs(floatHeights[i + 1] - 2.0 * floatHeights[i] + floatHeights[i - 1]));
        }
    }
    std::printf("largest second difference over 1 mm steps: near field %.6f m, float field %.6f m; slope error %.2e\n",
                nearWorst, floatWorst, gradientWorst);
    EXPECT_LT(nearWorst, 0.01);  // the float rounding of heights of a few km (0.5 mm each)
    EXPECT_GT(floatWorst, 5.0e-3);  // what the near field is for: a float field that steps
    EXPECT_LT(gradientWorst, 1.0e-3);
}

// Where a ray from `camera` (world, m) meets the float field, independently of the near
// field: 5 cm steps to the first crossing, then bisection; the distance along the ray.
double rayAboveGround(const NearTerrain& t, glm::dvec3 camera, glm::dvec3 ray, double s) {
    const glm::dvec3 p = camera + s * ray;
    return glm::length(p) - kRadiusM - t.height(p);
}

double referenceHit(const NearTerrain& t, glm::dvec3 camera, glm::dvec3 ray) {
    auto above = [&](double s) { return rayAboveGround(t, camera, ray, s); };
    double s = 0.0;
    while (above(s + 0.05) > 0.0) s += 0.05;
    double lo = s, hi = s + 0.05;
    for (int i = 0; i < 40; ++i) (above(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
}

// A ray from 2 m above the ground at one of four inland sites, descending at 3 to 60 degrees,
// with its reference crossing (referenceHit, m along the ray) and the rate at which it closes
// on the ground there (d(height above the ground)/d(distance), negative).
struct NearRay {
    terrain::TerrainNear near;
    glm::dvec3 ray;
    double descentDeg, azimuth, reference, crossing;
};

// Calls `test` for each such ray that meets the ground within the near field's range at a
// degree or more; returns how many it left out. Rays that graze the ground (the ground falls
// away about as fast as the ray) have no well-placed crossing to find; rays that meet it
// beyond the near field's range are not asked to.
template <class Test> int forEachNearRay(const NearTerrain& t, Test test) {
    int leftOut = 0;
    for (unsigned site = 0; site < 4; ++site) {
        const glm::dvec3 up = t.inland(300 + site);
        const glm::dvec3 camera = cameraAbove(t, up, 2.0);
        const terrain::TerrainNear near = terrain::makeTerrainNear(t.shape, t.continents, camera, kRadiusM);
        glm::dvec3 east, north;
        tangents(up, east, north);
        for (double descentDeg : {3.0, 10.0, 30.0, 60.0}) {
            for (double azimuth = 0.0; azimuth < 6.28; azimuth += 0.785) {
                const double e = glm::radians(descentDeg);
                const glm::dvec3 ray =
                    std::cos(e) * (std::cos(azimuth) * east + std::sin(azimuth) * north) - std::sin(e) * up;
                const double reference = referenceHit(t, camera, ray);
                const double crossing = (rayAboveGround(t, camera, ray, reference + 1.0) -
                                         rayAboveGround(t, camera, ray, reference - 1.0)) / 2.0;
                if (crossing > -0.017 || reference > terrain::terrainNearRangeM()) {
                    ++leftOut;
                    continue;
                }
                test(NearRay{near, ray, descentDeg, azimuth, reference, crossing});
            }
        }
    }
    return leftOut;
}

// The ray's meeting with the ground does not depend on where the search starts (the mesh's
// point, which moves with the tessellation, but stays within centimetres of the ground, so
// within a small share of the distance along the ray): on rays from 2 m up descending at 3 to 60
// degrees, started 1 % before and after the reference crossing (referenceHit), the hits
// agree to 0.2 % of the distance (the float heights' rounding over a grazing ray's descent
// allows no better), and with the reference to what the float field's own error allows
// (converted to height by the rate at which the ray closes on the ground).
TEST(TerrainNear, TheRaysHitDoesNotDependOnTheStart) {
    const NearTerrain& t = nearTerrain();
    int rays = 0;
    double spread = 0.0, offReference = 0.0;
    const int grazing = forEachNearRay(t, [&](const NearRay& r) {
        glm::vec3 before, after;
        const bool a = terrain::terrainRayHitNear(glm::vec3(r.ray * (0.99 * r.reference)), r.near, t.shape, before);
        const bool b = terrain::terrainRayHitNear(glm::vec3(r.ray * (1.01 * r.reference)), r.near, t.shape, after);
        EXPECT_TRUE(a && b) << "descent " << r.descentDeg << " azimuth " << r.azimuth << " reference " << r.reference
                            << " hits " << glm::length(before) << " " << glm::length(after);
        spread = std::max(spread, double(glm::length(before - after)) / r.reference);
        // Along the ray times the rate the ray closes on the ground: metres of height.
        offReference =
            std::max(offReference, std::abs(glm::length(glm::dvec3(before)) - r.reference) * std::abs(r.crossing));
        ++rays;
    });
    EXPECT_LT(grazing, rays / 4);
    std::printf("%d rays (%d grazing left out): hits from the two starts %.2e of the distance apart at most; off the reference by %.4f m of "
                "height\n", rays, grazing, spread, offReference);
    EXPECT_LT(spread, 2.0e-3);
    EXPECT_LT(offReference, 0.35);  // the float field's own error (the first test: up to 0.3 m)
}

// The ground detail takes one Newton step from the mesh's point (terrain/ground_material.frag): from a start
// 3 cm of height off the ground (above or below it), that step lands where the search run to
// convergence lands, to 3 mm of height (the distance between the two along the ray times the
// rate the ray closes on the ground; measured 1.9 mm): a tenth of the start's error, and
// within the float field's own rounding (the hits from two starts, above, agree to 0.2 % of
// the distance along the ray, centimetres of height on a grazing ray).
TEST(TerrainNear, OneStepFromAPointNearTheGroundLandsOnTheCrossing) {
    const NearTerrain& t = nearTerrain();
    int starts = 0;
    double worst = 0.0;
    forEachNearRay(t, [&](const NearRay& r) {
        // The float field's own crossing (within its error of the reference, above).
        glm::vec3 crossingPoint, converged, stepped;
        EXPECT_TRUE(terrain::terrainRayHitNear(glm::vec3(r.ray * r.reference), r.near, t.shape, crossingPoint));
        for (double heightOff : {-0.03, 0.03}) {
            const glm::vec3 start(r.ray * (glm::length(glm::dvec3(crossingPoint)) - heightOff / r.crossing));
            EXPECT_TRUE(terrain::terrainRayHitNear(start, r.near, t.shape, converged));
            EXPECT_TRUE(terrain::terrainRayHitNearSteps(start, r.near, t.shape, 1, stepped));
            const double startOff = std::abs(glm::length(glm::dvec3(start)) - glm::length(glm::dvec3(converged)));
            const double off = std::abs(glm::length(glm::dvec3(stepped)) - glm::length(glm::dvec3(converged)));
            EXPECT_GT(startOff * std::abs(r.crossing), 0.02) << r.descentDeg << " " << r.azimuth;
            worst = std::max(worst, off * std::abs(r.crossing));
            ++starts;
        }
    });
    std::printf("%d starts 3 cm of height off the ground: one step lands within %.2e m of height of the converged "
                "hit\n", starts, worst);
    EXPECT_GT(starts, 100);
    EXPECT_LT(worst, 3.0e-3);
}

// The ground's material takes the step from the height and gradient it evaluated at the mesh's
// point for its normal (terrainRayHitNearStepFrom): the same step as terrainRayHitNearSteps's
// single one, which evaluates them itself, to float rounding (measured: within 7e-8 of the
// distance; 499 of 500 starts converge), where it converges and where it does not.
TEST(TerrainNear, AStepFromAKnownHeightIsTheSearchsFirstStep) {
    const NearTerrain& t = nearTerrain();
    int starts = 0, converged = 0;
    double worst = 0.0;
    forEachNearRay(t, [&](const NearRay& r) {
        for (double off : {-0.5, 0.02, 0.5, 3.0}) {
            const glm::vec3 start(r.ray * (r.reference * (1.0 + off * 1e-2)));
            glm::vec3 gradient, a, b;
            const float h = terrain::terrainHeightNearGrad(start, r.near, t.shape, gradient);
            const bool stepA = terrain::terrainRayHitNearStepFrom(start, r.near, h, gradient, a);
            const bool stepB = terrain::terrainRayHitNearSteps(start, r.near, t.shape, 1, b);
            EXPECT_EQ(stepA, stepB) << r.descentDeg << " " << r.azimuth << " " << off;
            worst = std::max(worst, double(glm::length(a - b)) / glm::length(glm::dvec3(start)));
            converged += stepA;
            ++starts;
        }
    });
    std::printf("%d starts (%d converged): the step from a known height is the search's within %.1e of the "
                "distance\n", starts, converged, worst);
    EXPECT_GT(converged, starts / 2);
    EXPECT_LT(worst, 1.0e-4);
}

// Where Newton's method does not converge (a ray that does not descend towards the ground:
// one grazing a crest, or here one rising), the ground detail still needs a place on the
// ground: `hit` is the start dropped along the vertical onto the height field (first order
// in the start's height above it), not the start.
TEST(TerrainNear, ARayThatMissesGivesThePointBelowItsStart) {
    const NearTerrain& t = nearTerrain();
    const glm::dvec3 up = t.inland(300);
    const glm::dvec3 camera = cameraAbove(t, up, 2.0);
    const terrain::TerrainNear near = terrain::makeTerrainNear(t.shape, t.continents, camera, kRadiusM);
    glm::dvec3 east, north;
    tangents(up, east, north);
    for (double riseDeg : {20.0, 40.0, 60.0}) {
        const double r = glm::radians(riseDeg);
        const glm::dvec3 ray = std::cos(r) * east + std::sin(r) * up;
        const double s = 40.0;  // the start: 40 m along the rising ray, metres above the ground
        const double startAbove = rayAboveGround(t, camera, ray, s);
        glm::vec3 hit;
        EXPECT_FALSE(terrain::terrainRayHitNear(glm::vec3(ray * s), near, t.shape, hit)) << riseDeg;
        const glm::dvec3 world = camera + glm::dvec3(hit);
        const double hitAbove = glm::length(world) - kRadiusM - t.height(world);
        std::printf("rising %.1f deg: the start %.2f m above the ground, the point given %.4f m\n", riseDeg,
                    startAbove, hitAbove);
        EXPECT_GT(startAbove, 1.0) << riseDeg;
        EXPECT_LT(std::abs(hitAbove), 0.35) << riseDeg;  // the float field's own error, as above
        EXPECT_LT(glm::length(glm::dvec3(hit) - ray * s), 1.01 * startAbove) << riseDeg;  // straight down
    }
}

TEST(TerrainNear, TheGroundsPatchesAreFixedToTheWorldWithUnitSpreadAndNoPeriod) {
    // The ground detail's coarse scale (terrain/height.glsl, terrainPatchesNear): a field of the
    // world position, the same seen from two cameras (formed from each one's noise point, in double);
    // of mean 0 and RMS 1 (as the detail texture's patch channel it replaced), its gradient the
    // field's (central differences) and its slope along the ground of the RMS the detail divides by;
    // and not periodic at the texture's 32 m (a lattice of blotches seen from 20 m up).
    const NearTerrain& t = nearTerrain();
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    double sum = 0.0, squares = 0.0, lagProducts = 0.0, worstMismatch = 0.0, slopeSquares = 0.0, worstSlopeError = 0.0;
    int n = 0;
    for (unsigned site = 0; site < 6; ++site) {
        const glm::dvec3 up = t.inland(200 + site);
        const glm::dvec3 camera = cameraAbove(t, up, 20.0);
        glm::dvec3 east, north;
        tangents(up, east, north);
        const terrain::TerrainNear near = terrain::makeTerrainNear(t.shape, t.continents, camera, kRadiusM);
        const glm::dvec3 other = camera + 700.0 * east - 300.0 * north;  // a second camera nearby
        const terrain::TerrainNear nearOther = terrain::makeTerrainNear(t.shape, t.continents, other, kRadiusM);
        for (int i = 0; i < 4000; ++i) {
            const glm::dvec3 point = camera + 1500.0 * (unit(rng) * east + unit(rng) * north) - 20.0 * up;
            glm::vec3 gradient, unused;
            const float p = terrain::terrainPatchesNear(glm::vec3(point - camera), near, gradient);
            worstMismatch = std::max(worstMismatch, double(std::abs(
                                                        p - terrain::terrainPatchesNear(glm::vec3(point - other),
                                                                                        nearOther, unused))));
            const float q = terrain::terrainPatchesNear(glm::vec3(point + 32.0 * east - camera), near, unused);
            // The slope along the ground against central differences 2 cm apart.
            const glm::dvec3 along = glm::dvec3(gradient) - glm::dot(glm::dvec3(gradient), up) * up;
            slopeSquares += glm::dot(along, along);
            const auto at = [&](glm::dvec3 d) {
                return double(terrain::terrainPatchesNear(glm::vec3(point + d - camera), near, unused));
            };
            const double dEast = (at(0.02 * east) - at(-0.02 * east)) / 0.04;
            worstSlopeError = std::max(worstSlopeError, std::abs(dEast - glm::dot(along, east)));
            sum += p;
            squares += double(p) * p;
            lagProducts += double(p) * q;
            ++n;
        }
    }
    const double mean = sum / n, rms = std::sqrt(squares / n), lagCorrelation = lagProducts / squares;
    const double slopeRms = std::sqrt(slopeSquares / n);
    std::printf("ground patches: mean %.4f, RMS %.4f, slope RMS %.4f per m (largest error against differences %.2g), "
                "correlation 32 m apart %.3f, two cameras differ by %.2g\n",
                mean, rms, slopeRms, worstSlopeError, lagCorrelation, worstMismatch);
    EXPECT_LT(std::abs(mean), 0.05);
    EXPECT_NEAR(rms, 1.0, 0.05);
    EXPECT_NEAR(slopeRms, terrain::terrainPatchSlopeRms(), 0.05 * slopeRms);  // the detail normalises by it
    EXPECT_LT(worstSlopeError, 0.02 * slopeRms);
    EXPECT_LT(lagCorrelation, 0.5);  // a 32 m period would give 1
    EXPECT_LT(worstMismatch, 2.0e-3);
}
