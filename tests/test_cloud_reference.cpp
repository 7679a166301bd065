// The CPU reference of the cloud march (src/clouds/cloud_reference.h: cloud_density.glsl and
// cloud_march.glsl compiled as C++ in double) against the GPU's (clouds/cloud_probe.comp) on a
// baked volume and weather map, its convergence in the step size, and `planet sky-probe`
// through the clouds on the GPU against --reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "atmosphere/parameters.h"
#include "atmosphere/precompute_gpu.h"
#include "atmosphere/reference_tables.h"
#include "atmosphere/uniforms.h"
#include "clouds/clear_sky.h"
#include "clouds/cloud_block.h"
#include "clouds/cloud_probe.h"
#include "clouds/cloud_reference.h"
#include "clouds/cloud_resources.h"
#include "gl_test_support.h"
#include "noise/cloud_volume.h"
#include "noise/weather_map.h"
#include "process.h"
#include "test_util.h"

using namespace planet;
using namespace planet::clouds;
namespace fs = std::filesystem;

namespace {

// Earth with a cloud layer small enough to bake in a moment: a 64^3 volume (0.25 km voxels
// over the 16 km tile) and 16^2 weather faces, coverage 0.8 so that most rays meet cloud; a
// quarter of the voxels cloud and a border of 3 voxels leave 12 % of the volume empty, so
// that the march takes its large steps (0.5 km) too. The march's parameters are pinned here
// (the preset defaults of the day), so that a change of a default does not move the figures.
Scene cloudyScene() {
    Scene s;
    CloudParams& c = s.clouds;
    c.enabled = true;
    c.coverage = 0.8;
    c.volume_size = 64;
    c.cloud_fraction = 0.25;
    c.border_voxels = 3;
    c.weather_map_size = 16;
    c.extinction_per_km = 40.0;
    c.step_km = 0.05;
    c.max_steps = 256;
    c.sun_samples = 6;
    c.sun_step_km = 0.2;
    c.multiple_scattering_octaves = 4;
    c.type_profiles = true;
    return s;
}

// Where the rays start: a place whose weather map is cloudy at coverage 0.8 (most of the
// rays below meet cloud), away from the cube map's face centres and edges.
const glm::dvec3 kPlace = directionFromLatLon(20.0, 30.0);

struct Geometry {
    double altitudeKm, zenithDeg, azimuthDeg;
};

// Rays from below the layer (1.5-4 km), inside it, above it, from orbit (nadir, and grazing the
// layer at the limb: tangent 1 km, under the layer, and 3 km, in it), near the horizon.
std::vector<Geometry> geometries() {
    const double R = 6360.0;
    auto limb = [R](double orbitKm, double tangentKm) {  // zenith angle of the ray tangent at R + tangentKm
        return 180.0 - glm::degrees(std::asin((R + tangentKm) / (R + orbitKm)));
    };
    return {{0.5, 0.0, 0.0},    {0.5, 40.0, 60.0},   {0.5, 75.0, 200.0},  {0.5, 88.0, 300.0},
            {2.5, 0.0, 0.0},    {2.5, 60.0, 120.0},  {2.5, 90.0, 30.0},   {2.5, 120.0, 250.0},
            {2.5, 180.0, 0.0},  {6.0, 93.0, 90.0},   {6.0, 120.0, 0.0},   {6.0, 150.0, 180.0},
            {6.0, 180.0, 0.0},  {400.0, 180.0, 0.0}, {400.0, 160.0, 45.0}, {400.0, limb(400.0, 1.0), 10.0},
            {400.0, limb(400.0, 3.0), 100.0},        {400.0, limb(400.0, 3.0), 280.0}};
}

// The ray of a geometry at kPlace, the sun at a zenith angle and an azimuth (deg, from north);
// it ends at the ground where it hits it, as the sky pass's and sky-probe's rays do.
CloudProbeRay makeRay(const Geometry& g, double sunZenithDeg, double sunAzimuthDeg, double planetRadiusKm,
                      glm::dvec3 place = kPlace) {
    const LocalFrame f = localFrameAt(place);
    auto towards = [&f](double zenithDeg, double azimuthDeg) {
        const double z = glm::radians(zenithDeg), a = glm::radians(azimuthDeg);
        return glm::normalize(std::sin(z) * (std::cos(a) * f.north + std::sin(a) * f.east) + std::cos(z) * f.up);
    };
    CloudProbeRay ray;
    ray.origin = f.up * (planetRadiusKm + g.altitudeKm);
    ray.direction = towards(g.zenithDeg, g.azimuthDeg);
    ray.sun = towards(sunZenithDeg, sunAzimuthDeg);
    const double r = glm::length(ray.origin), rmu = glm::dot(ray.origin, ray.direction);
    const double discriminant = rmu * rmu - (r - planetRadiusKm) * (r + planetRadiusKm);
    if (rmu < 0.0 && discriminant >= 0.0) ray.distanceKm = -rmu - std::sqrt(discriminant);
    return ray;
}

CloudBlock blockFor(const Scene& scene, const CloudProbeRay& ray, double largeStepKm) {
    Camera camera;
    camera.position = ray.origin * 1000.0;  // the tile offset formed in double (Eq. 12)
    return makeCloudBlock(scene, camera, largeStepKm, scene.clouds.volume_size, 0.0);
}

// The in-scattering's error relative to the reference, per channel, with a floor of 1e-4
// of the solar irradiance per sr (rays that see almost nothing compare in absolute terms).
double radianceError(const glm::dvec3& got, const glm::dvec3& reference, const glm::dvec3& solar) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(got[c] - reference[c]) / std::max(std::abs(reference[c]), 1e-4 * solar[c]));
    return worst;
}
double transmittanceError(const glm::dvec3& got, const glm::dvec3& reference) {
    const glm::dvec3 d = glm::abs(got - reference);
    return std::max(d.x, std::max(d.y, d.z));
}

// The scene's CPU tables (reduced, computed once for every test here), the baked volume
// and weather map from the cloud cache (the entries CloudResources bakes and the GPU samples).
struct CpuData {
    Scene scene = cloudyScene();
    atmosphere::AtmosphereParameters atmosphere = atmosphere::makeAtmosphereParameters(scene);
    atmosphere::AtmosphereTables tables = atmosphere::computeReferenceTables(
                                              atmosphere, atmosphere::TableSizes::reduced(),
                                              scene.atmosphere.scattering_orders)
                                              .tables;
    noise::CloudVolume volume =
        noise::loadOrBakeCloudVolume(volumeParamsOf(scene.clouds), noise::defaultCloudCacheRoot());
    noise::WeatherMap weather = noise::loadOrBakeWeatherMap(weatherParamsOf(scene.clouds), scene.clouds.weather_map_size,
                                                         noise::defaultCloudCacheRoot());
};
const CpuData& cpuData() {
    static const CpuData data;
    return data;
}

class CloudReferenceGpu : public test::GLTest {
protected:
    static void SetUpTestSuite() {
        GLTest::SetUpTestSuite();
        const CpuData& d = cpuData();
        tables = std::make_unique<atmosphere::GpuTables>(atmosphere::upload(d.tables));
        resources = std::make_unique<CloudResources>();
        resources->update(d.scene, Camera{}, 1);  // loads what cpuData() baked into the cache
        probe = std::make_unique<CloudProbe>(test::repoPaths().shaders(), d.tables.sizes);
    }
    static void TearDownTestSuite() {
        probe.reset();
        resources.reset();
        tables.reset();
        GLTest::TearDownTestSuite();
    }
    static inline std::unique_ptr<atmosphere::GpuTables> tables;
    static inline std::unique_ptr<CloudResources> resources;
    static inline std::unique_ptr<CloudProbe> probe;
};

}  // namespace

// The GPU probe and the CPU reference over the geometries' rays, under a high and a low sun,
// with blocks for a pixel spanning `pixelAngle` rad (0: no footprint, the volume's level 0).
struct MarchComparison {
    double worstRadiance = 0.0, meanRadiance = 0.0, worstTransmittance = 0.0;
    int cloudy = 0, skipping = 0, count = 0;
    int changedByMips = 0;  // rays whose reference moves by over 0.2 % when read from level 0 alone
};

MarchComparison compareMarches(CloudProbe& probe, const atmosphere::GpuTables& tables, CloudResources& resources,
                               double pixelAngle) {
    const CpuData& d = cpuData();
    const double largeStepKm = resources.largeStepKm(d.scene.clouds.tile_width_km);
    const CloudReference reference(d.atmosphere, d.tables, &d.volume, &d.weather);
    const CloudReference levelZero(d.atmosphere, d.tables, &d.volume, &d.weather, 1);
    const atmosphere::AtmosphereUniforms uniforms = atmosphere::makeAtmosphereUniforms(d.atmosphere);
    MarchComparison c;
    for (const double sunZenith : {30.0, 86.0}) {  // sun high, sun low (reddened, long ways through the layer)
        for (const Geometry& g : geometries()) {
            // Both get the ray as the GPU receives it (float): what is compared is the march.
            CloudProbeRay ray = makeRay(g, sunZenith, 40.0, d.atmosphere.bottom_radius);
            ray.origin = glm::dvec3(glm::vec3(ray.origin));
            ray.direction = glm::dvec3(glm::vec3(ray.direction));
            ray.sun = glm::dvec3(glm::vec3(ray.sun));
            ray.distanceKm = double(float(ray.distanceKm));
            CloudBlock block = blockFor(d.scene, ray, largeStepKm);
            block.pixelAngle = static_cast<float>(pixelAngle);
            const CloudProbeResult gpu = probe.run(tables, uniforms, block, &resources, {ray})[0];
            const CloudProbeResult cpu = reference.march(block, ray);
            const double er = radianceError(gpu.inscatter, cpu.inscatter, d.atmosphere.solar_irradiance);
            const double et = transmittanceError(gpu.transmittance, cpu.transmittance);
            std::printf("  sun %2.0f alt %5.1f km zen %6.2f az %3.0f: steps %4d/%4d skipped %2d/%2d T %.4f/%.4f "
                        "L %.5f/%.5f: L %.3f%% T %.1e\n",
                        sunZenith, g.altitudeKm, g.zenithDeg, g.azimuthDeg, gpu.steps, cpu.steps, gpu.skipped,
                        cpu.skipped, gpu.transmittance.y, cpu.transmittance.y, gpu.inscatter.y, cpu.inscatter.y,
                        100.0 * er, et);
            c.worstRadiance = std::max(c.worstRadiance, er);
            c.meanRadiance += er;
            c.worstTransmittance = std::max(c.worstTransmittance, et);
            c.cloudy += cpu.steps > 0 && cpu.transmittance.y < 0.5;
            c.skipping += cpu.skipped > 0;
            const CloudProbeResult flat = levelZero.march(block, ray);
            c.changedByMips += radianceError(flat.inscatter, cpu.inscatter, d.atmosphere.solar_irradiance) > 0.002;
            ++c.count;
        }
    }
    c.meanRadiance /= c.count;
    std::printf("%d rays (%d through thick cloud, %d with large steps, %d changed by the mips): in-scattering %.3f%% "
                "at most, %.3f%% on average; transmittance %.1e at most\n",
                c.count, c.cloudy, c.skipping, c.changedByMips, 100.0 * c.worstRadiance, 100.0 * c.meanRadiance,
                c.worstTransmittance);
    return c;
}

TEST_F(CloudReferenceGpu, GpuMarchMatchesTheCpuReferenceOnTheBakedVolume) {
    const CpuData& d = cpuData();
    EXPECT_DOUBLE_EQ(largeStepKmOf(d.scene.clouds), resources->largeStepKm(d.scene.clouds.tile_width_km));  // the reference's copy of the rule
    const MarchComparison c = compareMarches(*probe, *tables, *resources, 0.0);
    // Measured on Mesa llvmpipe: in-scattering 0.71 % at most, 0.11 % on average; transmittance
    // 3.5e-4. The worst rays see the sun through optically thick cloud (E = 40 / km), whose light
    // moves by percents when the samples move by the float rounding of a position at planet
    // scale (moving one ray of this set by 0.5 m moved its light by 2.7 %, in vacuum). A reference with GL's 8-bit filtering weights (most
    // hardware GPUs) differs from this one by 3.6 % at most, 0.33 % on average, 1.1e-3; hence
    // 5 %, 0.5 % and 2e-3. A GPU march with phase asymmetry 0.59 instead of 0.6 fails the
    // average (0.63 %), 0.55 both (8.8 % / 3 %); one with the phase's cosine reversed, without
    // the clouds' transmittance towards the sun, or with 3 octaves instead of 4 fails by 25 % to
    // 17x; so do extinction 2 % high (6 % / 1.8 % / 7e-3), a reference sampling the volume half
    // a voxel off or the weather map mirrored (all three limits each).
    EXPECT_LT(c.worstRadiance, 0.05);
    EXPECT_LT(c.meanRadiance, 0.005);
    EXPECT_LT(c.worstTransmittance, 2e-3);
    EXPECT_GE(c.cloudy, 12);   // the comparison is about clouds, not clear air
    EXPECT_GE(c.skipping, 8);  // and the large steps through empty space
    // No pixel footprint, but a sample stands for its whole step (clouds/cloud_march.glsl): the rays
    // whose steps grow past a voxel (the large steps' budget over a long way through the layer)
    // read the levels that span them, the rest level 0 (measured: 6 of the 36 rays move by over 0.2 %).
    EXPECT_GE(c.changedByMips, 1);
    EXPECT_LT(c.changedByMips, c.count / 2);
}

TEST_F(CloudReferenceGpu, WhereAPixelSpansVoxelsTheGpuReadsTheMipsAsTheReferenceDoes) {
    // Blocks for a pixel of 12 mrad (60 degrees over 90 px, the tests' frames): a voxel (62.5 m)
    // spans a pixel 5 km away, 8 voxels 42 km away, so the rays between read the volume's levels
    // 0 to 3 (CloudVolumeLod), trilinear between levels. The GPU's mips (glGenerateTextureMipmap)
    // against the CPU's (noise::cloudVolumeMips, a 2x2x2 box), within the bounds of the test
    // above (measured: 0.71 % at most, 0.09 % on average, 3.5e-4); and the mips are read: a
    // reference that reads level 0 alone moves by over 0.2 % on 5 of the 36 rays (measured).
    const MarchComparison c = compareMarches(*probe, *tables, *resources, 1.2e-2);
    EXPECT_LT(c.worstRadiance, 0.05);
    EXPECT_LT(c.meanRadiance, 0.005);
    EXPECT_LT(c.worstTransmittance, 2e-3);
    EXPECT_GE(c.changedByMips, 3);
}

TEST(CloudVolumeMips, EachLevelIsTheMeanOfTheEightVoxelsAbove) {
    // A 4^3 volume whose voxel (x, y, z) holds x + 10 y + 100 z (exact in half): level 1's
    // voxel (i, j, k) is the mean of its 2x2x2 block, 2 i + 0.5 + 10 (2 j + 0.5) + 100 (2 k +
    // 0.5); level 2 the mean of all, 1.5 + 15 + 150; and no level below one voxel.
    noise::CloudVolume v;
    v.size = 4;
    v.voxels.resize(64);
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) v.voxels[v.index(x, y, z)] = float(x + 10 * y + 100 * z);
    const std::vector<noise::CloudVolume> mips = noise::cloudVolumeMips(v, noise::kCloudVolumeMipLevels);
    ASSERT_EQ(mips.size(), 2u);
    ASSERT_EQ(mips[0].size, 2);
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                EXPECT_FLOAT_EQ(mips[0].at(i, j, k), float((2 * i + 0.5) + 10 * (2 * j + 0.5) + 100 * (2 * k + 0.5)));
    ASSERT_EQ(mips[1].size, 1);
    EXPECT_FLOAT_EQ(mips[1].at(0, 0, 0), 166.5f);
}

TEST(CloudReference, HalvingTheStepConvergesOnRaysThroughClouds) {
    // The CPU reference with clouds.step_km 0.1, 0.05 (cloudyScene's) and 0.025 km, budgets
    // large enough never to stretch the step, on the rays above that meet cloud.
    const CpuData& d = cpuData();
    const CloudReference reference(d.atmosphere, d.tables, &d.volume, &d.weather);
    auto marchAll = [&](double stepKm) {
        Scene scene = d.scene;
        scene.clouds.step_km = stepKm;
        scene.clouds.max_steps = 8192;
        std::vector<CloudProbeRay> rays;
        std::vector<CloudBlock> blocks;
        for (const double sunZenith : {30.0, 86.0})
            for (const Geometry& g : geometries()) {
                rays.push_back(makeRay(g, sunZenith, 40.0, d.atmosphere.bottom_radius));
                blocks.push_back(blockFor(scene, rays.back(), largeStepKmOf(scene.clouds)));
            }
        return reference.march(blocks, rays);
    };
    const auto start = std::chrono::steady_clock::now();
    const std::vector<CloudProbeResult> coarse = marchAll(0.1), middle = marchAll(0.05), fine = marchAll(0.025);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    long long steps = 0;
    for (const auto* results : {&coarse, &middle, &fine})
        for (const CloudProbeResult& r : *results) steps += r.steps + r.skipped;
    std::printf("CPU reference: %zu rays, %lld cloud steps in %.3f s on all cores\n", 3 * fine.size(), steps, seconds);
    struct Change {
        double worst = 0.0, mean = 0.0, transmittance = 0.0;
    };
    auto change = [&](const std::vector<CloudProbeResult>& a, const std::vector<CloudProbeResult>& b, int& rays) {
        Change c;
        rays = 0;
        for (std::size_t i = 0; i < b.size(); ++i) {
            if (b[i].steps == 0 || b[i].transmittance.y > 0.95) continue;  // no cloud on the way
            const double e = radianceError(a[i].inscatter, b[i].inscatter, d.atmosphere.solar_irradiance);
            c.worst = std::max(c.worst, e);
            c.mean += e;
            c.transmittance = std::max(c.transmittance, transmittanceError(a[i].transmittance, b[i].transmittance));
            ++rays;
        }
        c.mean /= std::max(rays, 1);
        return c;
    };
    int rays = 0;
    const Change first = change(coarse, middle, rays), second = change(middle, fine, rays);
    std::printf("on %d rays through clouds, in-scattering changes by at most / on average, transmittance at most:\n"
                "  step 0.1 -> 0.05 km:  %.2f%% / %.2f%%, %.1e\n  step 0.05 -> 0.025 km: %.2f%% / %.2f%%, %.1e\n",
                rays, 100.0 * first.worst, 100.0 * first.mean, first.transmittance, 100.0 * second.worst,
                100.0 * second.mean, second.transmittance);
    // Measured: 0.1 -> 0.05: 16.4 % / 2.2 % (the worst: a thin, sunlit cloud edge whose light
    // comes from a few samples), 5.1e-3; 0.05 -> 0.025: 3.4 % / 0.46 %, 6.1e-3. The bounds: the
    // step cloudyScene pins (0.05 km) is within 5 % of the next halving on every ray, and on
    // average the change at least halves with the step.
    EXPECT_GE(rays, 24);
    EXPECT_LT(second.worst, 0.05);
    EXPECT_LT(second.mean, 0.01);
    EXPECT_LT(second.transmittance, 0.02);
    EXPECT_LT(second.mean, 0.5 * first.mean);
}

namespace {

// The suite's layer at coverage 0.5 (the clear sky map then holds: CloudLocalCoverage keeps a 0 at
// 0) over a weather map of 128 a face (78 km a texel: on the suite's 16, 625 km, whose clear sky
// must span several texels to be known for sure, the map holds no clear angle), with its map.
struct ClearSkyCase {
    const CpuData& d = cpuData();
    noise::WeatherMap weather = noise::bakeWeatherMap(weatherParamsOf(d.scene.clouds), 128);
    clouds::ClearSkyMap clear = clouds::buildClearSkyMap(weather);
    std::vector<noise::CloudVolume> mips = noise::cloudVolumeMips(d.volume, noise::kCloudVolumeMipLevels);
    Scene scene = [this] {
        Scene s = d.scene;
        s.clouds.coverage = 0.5;
        return s;
    }();
};

}  // namespace

TEST(CloudReference, TheClearSkysLongStepsChangeTheCostNotTheSky) {
    // The march with the clear sky map (src/clouds/clear_sky.h) and without it (the model given
    // none: CloudClearDistance 0) on ClearSkyCase's layer, on the geometries' rays from 40 places
    // over the sphere, every other one under a clear sky near clouds. Where no cloud is met the
    // two are the same sky to the last bit (the air's slices do not depend on the cloud steps);
    // where one is, the samples past a long step within the same slice of the layer lie
    // elsewhere, which may move the light by about what halving the step does (the test above;
    // measured: 0.00 %, the long steps of the 4 such rays lie in other slices than their cloud).
    const ClearSkyCase c;
    const CpuData& d = c.d;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int clearRays = 0, cloudyRays = 0, shortened = 0, shortenedCloudy = 0, differ = 0;
    long long stepsWith = 0, stepsWithout = 0;
    double worst = 0.0, mean = 0.0;
    for (int place = 0; place < 40; ++place) {
        glm::dvec3 at = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        // Every other place under a clear sky with cloud in sight: its texel of the map holds an
        // angle, and within 150 km the coverage is over 1/2 (the edges of a cloud field, thinly
        // covered, seldom hold a cloud).
        auto cloudNear = [&](glm::dvec3 p) {
            const LocalFrame f = localFrameAt(p);
            for (int k = 0; k < 16; ++k) {
                const double a = 2.0 * M_PI * k / 16.0, r = 150.0 / 6360.0;
                const glm::dvec3 q = std::cos(r) * p + std::sin(r) * (std::cos(a) * f.north + std::sin(a) * f.east);
                if (noise::sampleWeather(c.weather, q).x > 0.5f) return true;
            }
            return false;
        };
        while (place % 2 == 0 && (clouds::clearSkyAngleAt(c.clear, at) <= 0.0 || !cloudNear(at)))
            at = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        std::vector<Geometry> rays = geometries();
        for (int k = 0; k < 8; ++k) {  // and rays that go far through the layer, every way round
            rays.push_back({2.5, 90.0, 45.0 * k});
            rays.push_back({0.5, 87.0, 45.0 * k + 20.0});
        }
        for (const Geometry& g : rays) {
            const CloudProbeRay ray = makeRay(g, 30.0, 40.0, d.atmosphere.bottom_radius, at);
            const CloudBlock block = blockFor(c.scene, ray, largeStepKmOf(c.scene.clouds));
            glsl::CloudMarchModel with(d.atmosphere, d.tables, block, &d.volume, &c.mips, &c.weather, &c.clear);
            glsl::CloudMarchModel without(d.atmosphere, d.tables, block, &d.volume, &c.mips, &c.weather, nullptr);
            const auto a = with.MarchView(ray.origin, ray.direction, ray.distanceKm, ray.sun, with.MarchQualityOf(0.5));
            const auto b =
                without.MarchView(ray.origin, ray.direction, ray.distanceKm, ray.sun, without.MarchQualityOf(0.5));
            stepsWith += a.steps + a.skipped;
            stepsWithout += b.steps + b.skipped;
            shortened += a.steps + a.skipped < b.steps + b.skipped;
            if (b.cloudOpacity == 0.0) {
                ++clearRays;
                differ += a.inscatter != b.inscatter || a.transmittance != b.transmittance || a.cloudOpacity != 0.0;
            } else {
                ++cloudyRays;
                shortenedCloudy += a.steps + a.skipped < b.steps + b.skipped;
                const double e = radianceError(a.inscatter, b.inscatter, d.atmosphere.solar_irradiance);
                worst = std::max(worst, e);
                mean += e;
            }
        }
    }
    mean /= std::max(cloudyRays, 1);
    std::printf("%d rays without cloud (%d differ), %d with: in-scattering moved by %.2f%% at most, %.3f%% on average; "
                "%d rays marched in fewer steps (%d of them with cloud), %lld steps against %lld\n",
                clearRays, differ, cloudyRays, 100.0 * worst, 100.0 * mean, shortened, shortenedCloudy, stepsWith,
                stepsWithout);
    EXPECT_EQ(differ, 0);
    EXPECT_GE(clearRays, 100);
    EXPECT_GE(cloudyRays, 100);
    EXPECT_LT(worst, 0.05);
    EXPECT_LT(mean, 0.01);
    EXPECT_GE(shortened, 100);
    EXPECT_GE(shortenedCloudy, 2);
    EXPECT_LT(double(stepsWith), 0.8 * double(stepsWithout));
}

TEST(CloudReference, TheSunsWayThroughAClearSkyIsNotSampledAndTheShadowIsTheSame) {
    // The clouds' transmittance towards the sun from the ground (the surfaces' shadows), with the
    // clear sky map and without, on ClearSkyCase's layer at 2000 places and suns (every other one
    // low): where the map says the whole way is clear its samples are not taken, and the
    // transmittance must be what they would have given, 1.
    // Measured: 550 ways through cloud, 51 not sampled, none differs. (The map's clear caps lie
    // far from cloud beside these ways: a shortcut taken where the cap reached a tenth of the way
    // went unnoticed; one at the wrong place, or without the map's gate, would not.)
    const ClearSkyCase c;
    const CpuData& d = c.d;
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int differ = 0, shaded = 0, clearWays = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 up = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        glm::dvec3 sun = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        if (glm::dot(sun, up) < 0.0) sun = -sun;  // a sun above the horizon; every other one low (1-5 deg),
        if (i % 2 == 0) {                        // whose way through the layer is long (30-100 km)
            const glm::dvec3 level = glm::normalize(sun - glm::dot(sun, up) * up);
            const double elevation = glm::radians(1.0 + 2.0 * (1.0 + unit(rng)));
            sun = std::cos(elevation) * level + std::sin(elevation) * up;
        }
        const glm::dvec3 point = up * (d.atmosphere.bottom_radius + 0.5);
        CloudProbeRay ray;
        ray.origin = point;
        const CloudBlock block = blockFor(c.scene, ray, largeStepKmOf(c.scene.clouds));
        glsl::CloudMarchModel with(d.atmosphere, d.tables, block, &d.volume, &c.mips, &c.weather, &c.clear);
        glsl::CloudMarchModel without(d.atmosphere, d.tables, block, &d.volume, &c.mips, &c.weather, nullptr);
        const double a = with.CloudSunTransmittance(point, sun, 100.0);
        const double b = without.CloudSunTransmittance(point, sun, 100.0);
        differ += a != b;
        shaded += b < 1.0;
        // Whether the shortcut was taken: the clear sky at the way's start reaches past its end.
        glm::dvec2 first, second;
        const double r = glm::length(point);
        glsl::CloudLayerIntervals(r, glm::dot(point, sun) / r, 1.0e9, with.clouds.bottomRadius, with.clouds.topRadius,
                                 first, second);
        const glm::dvec3 entry = glm::normalize(point + sun * first.x);
        const double way = std::min(first.y - first.x, 100.0);
        const bool notSampled = with.CloudClearAlong(point + sun * first.x, way);
        // The map's own angle at the way's start, where its weather has no coverage, reaches as far.
        EXPECT_EQ(notSampled, noise::sampleWeather(c.weather, entry).x <= 0.0f &&
                                  clouds::clearSkyChord(clouds::clearSkyAngleAt(c.clear, entry)) *
                                          with.clouds.bottomRadius >= way);
        clearWays += notSampled;
    }
    std::printf("2000 ways to the sun: %d through cloud, %d not sampled (a clear sky); %d differ\n", shaded,
                clearWays, differ);
    EXPECT_EQ(differ, 0);
    EXPECT_GE(shaded, 300);
    EXPECT_GE(clearWays, 40);
}

TEST_F(CloudReferenceGpu, TheGpuTakesTheClearSkysLongStepsWhereTheReferenceDoes) {
    // The suite's layer with a weather map of 128 a face (the test above says why) at coverage
    // 0.5, rays from places under a clear sky: the GPU's clear sky texture (its faces, its texels)
    // against the CPU's map, by the steps each takes and the light, within the bounds of the
    // first test.
    const CpuData& d = cpuData();
    Scene scene = d.scene;
    scene.clouds.coverage = 0.5;
    scene.clouds.weather_map_size = 128;
    const noise::WeatherMap weather =
        noise::loadOrBakeWeatherMap(weatherParamsOf(scene.clouds), 128, noise::defaultCloudCacheRoot());
    CloudResources clearResources;
    clearResources.update(scene, Camera{}, 1);  // the same cache entry
    const CloudReference reference(d.atmosphere, d.tables, &d.volume, &weather);
    const clouds::ClearSkyMap clear = clouds::buildClearSkyMap(weather);
    const atmosphere::AtmosphereUniforms uniforms = atmosphere::makeAtmosphereUniforms(d.atmosphere);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int rays = 0, sameSteps = 0, clearSkips = 0, worstStepDifference = 0;
    double worst = 0.0, worstT = 0.0;
    for (int place = 0; place < 12; ++place) {
        glm::dvec3 at;
        do at = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        while (clouds::clearSkyAngleAt(clear, at) <= 0.0);
        for (int k = 0; k < 4; ++k)
            for (const Geometry& g : {Geometry{2.5, 90.0, 90.0 * k}, Geometry{0.5, 87.0, 90.0 * k + 45.0}}) {
                CloudProbeRay ray = makeRay(g, 30.0, 40.0, d.atmosphere.bottom_radius, at);
                ray.origin = glm::dvec3(glm::vec3(ray.origin));
                ray.direction = glm::dvec3(glm::vec3(ray.direction));
                ray.sun = glm::dvec3(glm::vec3(ray.sun));
                const CloudBlock block = blockFor(scene, ray, clearResources.largeStepKm(scene.clouds.tile_width_km));
                const CloudProbeResult gpu = probe->run(*tables, uniforms, block, &clearResources, {ray})[0];
                const CloudProbeResult cpu = reference.march(block, ray);
                ++rays;
                sameSteps += gpu.steps == cpu.steps && gpu.skipped == cpu.skipped;
                worstStepDifference = std::max(worstStepDifference, std::abs(gpu.steps + gpu.skipped - cpu.steps - cpu.skipped));
                clearSkips += cpu.steps < 50;  // the layer's 180 km would take 200 and more without
                worst = std::max(worst, radianceError(gpu.inscatter, cpu.inscatter, d.atmosphere.solar_irradiance));
                worstT = std::max(worstT, transmittanceError(gpu.transmittance, cpu.transmittance));
            }
    }
    std::printf("%d rays from under a clear sky: %d with the same steps on both (the others %d apart at most), %d "
                "crossed in under 50 small steps; in-scattering %.3f%% at most, transmittance %.1e\n",
                rays, sameSteps, worstStepDifference, clearSkips, 100.0 * worst, worstT);
    // Measured on llvmpipe: 91 of 96 the same, the others 1 to 3 steps apart (float positions at
    // planet scale against double, as on the suite's other rays); 0.002 %, 1.6e-5. A texture
    // whose faces or texels the GPU read otherwise than the CPU's map would step elsewhere.
    EXPECT_GE(sameSteps, 3 * rays / 4);
    EXPECT_LE(worstStepDifference, 4);
    EXPECT_GE(clearSkips, rays / 4);
    EXPECT_LT(worst, 0.05);
    EXPECT_LT(worstT, 2e-3);
}

namespace {

class CloudReferenceCli : public test::CliFixture {};

struct ProbeRow {
    double radiance[3], transmittance[3];
};

std::vector<ProbeRow> readProbe(const fs::path& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);  // header
    std::vector<ProbeRow> rows;
    while (std::getline(in, line)) {
        std::vector<double> v;
        std::istringstream fields(line);
        for (std::string f; std::getline(fields, f, ',');) v.push_back(std::stod(f));
        if (v.size() != 10) {
            ADD_FAILURE() << line;
            continue;
        }
        rows.push_back({{v[4], v[5], v[6]}, {v[7], v[8], v[9]}});
    }
    return rows;
}

}  // namespace

TEST_F(CloudReferenceCli, SkyProbeThroughCloudsGpuMatchesReference) {
    // A small baked layer (cloudyScene's) above the north pole, where sky-probe's frame sits.
    shareCloudCache();
    std::ofstream(dir / "cloudy.toml") << "[clouds]\nenabled = true\ncoverage = 0.8\nvolume_size = 64\n"
                                          "cloud_fraction = 0.25\nborder_voxels = 3\nweather_map_size = 16\n";
    std::ofstream(dir / "cases.csv") << "altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg\n"
                                        "500,30,60,90\n"         // below the layer, into it
                                        "2500,60,90,30\n"        // inside, horizontal
                                        "6000,30,120,0\n"        // above, down to the ground
                                        "400000,30,162,0\n"      // orbit, towards the limb
                                        "400000,30,0,0\n";       // orbit, looking up: nothing at all
    const std::string args = "sky-probe --preset cloudy.toml --tables reduced --in cases.csv";
    const auto gpu = test::runCommand(planet(args + " --out gpu.csv"));
    ASSERT_EQ(gpu.exitCode, 0) << gpu.output;
    EXPECT_TRUE(test::contains(gpu.output, "through the clouds")) << gpu.output;
    const auto ref = test::runCommand(planet(args + " --out ref.csv --reference"));
    ASSERT_EQ(ref.exitCode, 0) << ref.output;
    const std::vector<ProbeRow> g = readProbe(dir / "gpu.csv"), c = readProbe(dir / "ref.csv");
    ASSERT_EQ(g.size(), 5u);
    ASSERT_EQ(c.size(), 5u);
    // 2 % as for the clear sky (AtmosphereCli.SkyProbeGpuMatchesCpuReference): here the GPU's
    // tables are its own, not the reference's (measured: 0.3 % at most; floors 1e-4); the rays
    // start from the exact double origin on the CPU, the float one on the GPU.
    for (std::size_t i = 0; i < g.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
            const double dr = std::abs(g[i].radiance[ch] - c[i].radiance[ch]) / std::max(c[i].radiance[ch], 1e-4);
            const double dt =
                std::abs(g[i].transmittance[ch] - c[i].transmittance[ch]) / std::max(c[i].transmittance[ch], 1e-4);
            std::printf("  row %zu channel %d: radiance %.5e / %.5e (%.2f%%), transmittance %.3e / %.3e\n", i, ch,
                        g[i].radiance[ch], c[i].radiance[ch], 100.0 * dr, g[i].transmittance[ch],
                        c[i].transmittance[ch]);
            EXPECT_LT(dr, 0.02) << "row " << i << " channel " << ch;
            EXPECT_LT(dt, 0.02) << "row " << i << " channel " << ch;
        }
    // The clouds are in it: the horizontal ray inside the layer is opaque; above the atmosphere
    // looking up, nothing.
    EXPECT_LT(c[1].transmittance[1], 1e-3);
    for (int ch = 0; ch < 3; ++ch) {
        EXPECT_EQ(g[4].radiance[ch], 0.0);
        EXPECT_EQ(g[4].transmittance[ch], 1.0);
    }
}

