#include "clouds/cloud_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace planet::clouds {

namespace glsl {

CloudBlockDouble widen(const CloudBlock& b) {
    CloudBlockDouble d;
    d.cameraTileOffset = vec3(b.cameraTileOffset);
    d.tileWidth = b.tileWidth;
    d.cameraFromCentre = vec3(b.cameraFromCentre);
    d.bottomRadius = b.bottomRadius;
    d.topRadius = b.topRadius;
    d.coverage = b.coverage;
    d.densityScale = b.densityScale;
    d.extinction = b.extinction;
    d.scattering = b.scattering;
    d.phaseGForward = b.phaseGForward;
    d.phaseGBack = b.phaseGBack;
    d.phaseBackWeight = b.phaseBackWeight;
    d.sunStep = b.sunStep;
    d.stepKm = b.stepKm;
    d.largeStepKm = b.largeStepKm;
    d.powder = b.powder;
    d.sunSamples = b.sunSamples;
    d.maxSteps = b.maxSteps;
    d.atmosphereSlices = b.atmosphereSlices;
    d.multipleScatteringOctaves = b.multipleScatteringOctaves;
    d.energyConservingStep = b.energyConservingStep;
    d.constantDensity = b.constantDensity;
    d.enabled = b.enabled;
    d.typeProfiles = b.typeProfiles;
    d.pixelAngle = b.pixelAngle;
    d.voxelKm = b.voxelKm;
    return d;
}

CloudMarchModel::CloudMarchModel(const AtmosphereParameters& atmosphere, const atmosphere::AtmosphereTables& tables,
                                 const CloudBlock& block, const noise::CloudVolume* volume,
                                 const std::vector<noise::CloudVolume>* volumeMips, const noise::WeatherMap* weather,
                                 const ClearSkyMap* clearSkyMap)
    : Model(tables.sizes),
      clouds(widen(block)),
      cloudVolume{volume, volumeMips},
      weatherMap{weather},
      clearSky{clearSkyMap},
      transmittance_texture(tables.transmittance),
      scattering_texture(tables.scattering),
      single_mie_scattering_texture(tables.singleMie),
      irradiance_texture(tables.irradiance),
      atmosphere_(atmosphere) {}

namespace {

// GL_REPEAT on a texel index (any integer).
std::size_t wrap(std::int64_t i, int size) {
    const std::int64_t n = size;
    return static_cast<std::size_t>(((i % n) + n) % n);
}

// GL 4.5 §8.14.2 for GL_LINEAR: u' = size u - 1/2, i0 = floor(u'), weight frac(u') on i0 + 1,
// each index wrapped (GL_REPEAT); R16F reads as (r, 0, 0, 1).
double trilinear(const noise::CloudVolume& v, vec3 uvw) {
    const vec3 texel = uvw * double(v.size) - 0.5;
    const vec3 base = glm::floor(texel);
    const vec3 f = texel - base;
    std::size_t i[3][2];
    for (int axis = 0; axis < 3; ++axis) {
        const auto b = static_cast<std::int64_t>(base[axis]);
        i[axis][0] = wrap(b, v.size);
        i[axis][1] = wrap(b + 1, v.size);
    }
    const auto n = static_cast<std::size_t>(v.size);
    double value = 0.0;
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const double w = (dx ? f.x : 1.0 - f.x) * (dy ? f.y : 1.0 - f.y) * (dz ? f.z : 1.0 - f.z);
                value += w * v.voxels[(i[2][dz] * n + i[1][dy]) * n + i[0][dx]];
            }
    return value;
}

}  // namespace

// GL_LINEAR_MIPMAP_LINEAR (§8.14.3): the levels floor(lod) and the next, mixed by frac(lod),
// lod clamped to the levels there are.
vec4 CloudMarchModel::textureLod(const VolumeSampler& sampler, vec3 uvw, Number lod) const {
    if (!sampler.volume) return vec4(noise::kCloudEmpty, 0.0, 0.0, 1.0);
    const int top = sampler.mips ? static_cast<int>(sampler.mips->size()) : 0;
    lod = glm::clamp(lod, 0.0, double(top));
    const int level = std::min(static_cast<int>(lod), top);
    auto at = [&](int l) { return trilinear(l == 0 ? *sampler.volume : (*sampler.mips)[l - 1], uvw); };
    const double f = lod - level;
    const double value = f > 0.0 && level < top ? glm::mix(at(level), at(level + 1), f) : at(level);
    return vec4(value, 0.0, 0.0, 1.0);
}

// A seamless samplerCube, GL_LINEAR (noise::sampleWeather); RG16F reads as (r, g, 0, 1).
vec4 CloudMarchModel::textureLod(const WeatherSampler& sampler, vec3 direction, Number) const {
    if (!sampler.map) return vec4(0.0, 0.5, 0.0, 1.0);
    const glm::vec2 w = noise::sampleWeather(*sampler.map, direction);
    return vec4(w.x, w.y, 0.0, 1.0);
}

// An R32F samplerCube of the angles' chords (makeClearSkyTexture), GL_NEAREST: reads as (r, 0, 0, 1).
vec4 CloudMarchModel::textureLod(const ClearSkySampler& sampler, vec3 direction, Number) const {
    return vec4(sampler.map ? clearSkyChord(clearSkyAngleAt(*sampler.map, direction)) : 0.0, 0.0, 0.0, 1.0);
}

// interface.glsl with ELEK_TABLE 0: Bruneton's 4D table, without light shafts
// (terrain.light_shafts: the CPU reference has none, its SunShadowLength is 0).
CloudMarchModel::ViewRay CloudMarchModel::AirRay(vec3 up, Length altitudeKm, bool byAltitude, vec3 position,
                                                 vec3 viewRay, vec3 sun) {
    return byAltitude ? ViewRayInAtmosphereAt(atmosphere_, up, altitudeKm, viewRay, sun)
                      : ViewRayInAtmosphere(atmosphere_, position, viewRay, sun);
}
vec3 CloudMarchModel::SkyRadianceOfRay(const ViewRay& ray, vec3, vec3, vec3, vec3& transmittance) {
    return GetSkyRadianceOfRay(atmosphere_, false, transmittance_texture, scattering_texture,
                               single_mie_scattering_texture, ray, transmittance);
}
vec3 CloudMarchModel::SkyRadianceToPointOfRay(const ViewRay& ray, vec3, vec3, Length distance, vec3,
                                              vec3& transmittance) {
    return GetSkyRadianceToPointOfRay(atmosphere_, false, transmittance_texture, scattering_texture,
                                      single_mie_scattering_texture, ray, distance, Length(0.0), transmittance);
}

}  // namespace glsl

double largeStepKmOf(const CloudParams& c) {
    if (c.constant_density) return 0.0;
    return c.tile_width_km * double(std::max(c.border_voxels - 1, 0)) / double(c.volume_size);
}

CloudReference::CloudReference(const atmosphere::AtmosphereParameters& atmosphere,
                               const atmosphere::AtmosphereTables& tables, const noise::CloudVolume* volume,
                               const noise::WeatherMap* weather, int mipLevels)
    : atmosphere_(atmosphere),
      tables_(tables),
      volume_(volume),
      volumeMips_(volume ? noise::cloudVolumeMips(*volume, mipLevels) : std::vector<noise::CloudVolume>{}),
      weather_(weather),
      clearSky_(weather ? buildClearSkyMap(*weather) : ClearSkyMap{}) {}

CloudProbeResult CloudReference::march(const CloudBlock& block, const CloudProbeRay& ray) const {
    glsl::CloudMarchModel model(atmosphere_, tables_, block, volume_, &volumeMips_, weather_, &clearSky_);
    // clouds/cloud_probe.comp's call.
    const glsl::CloudMarchModel::ViewMarch m =
        model.MarchView(ray.origin, ray.direction, ray.distanceKm, ray.sun, model.MarchQualityOf(0.5));
    return {m.transmittance, m.inscatter, m.steps, m.skipped};
}

std::vector<CloudProbeResult> CloudReference::march(const std::vector<CloudBlock>& blocks,
                                                    const std::vector<CloudProbeRay>& rays) const {
    std::vector<CloudProbeResult> results(rays.size());
    noise::cloud_bake::parallelFor(
        static_cast<int>(rays.size()), [&](int i) { results[i] = march(blocks[i], rays[i]); }, {}, 0.0, 1.0);
    return results;
}

}  // namespace planet::clouds
