// The CPU reference of the unified cloud and atmosphere march: shaders/clouds/
// cloud_density.glsl and cloud_march.glsl (Michelic §5, Eq. 12-20) compiled as C++ in
// double precision, as src/atmosphere/model.h compiles the atmosphere's GLSL. The same
// text the sky pass and clouds/cloud_probe.comp run is included into a class whose members
// stand in for the GLSL globals:
//
//   clouds                      the CloudBlock, widened to double (CloudBlockDouble): the
//                               float values the GPU is given, so both march the same layer
//   cloudVolume, weatherMap,    CPU samplers with GL's filtering: the volume trilinear with
//   clearSky                    GL_REPEAT, voxel (i, j, k) at ((i, j, k) + 0.5) / size, the
//                               weather map noise::sampleWeather (a seamless samplerCube), the
//                               clear sky map nearest (clearSkyAngleAt, built from the weather);
//                               without data, CloudResources' placeholders (-1; coverage 0; 0)
//   the atmosphere interface    AirRay, SkyRadianceOfRay, SkyRadianceToPointOfRay (4D table, no shadow
//                               length: interface.glsl with ELEK_TABLE 0, as the probe is
//                               built), atmosphereParameters(), the tables, and through the
//                               base class Model the model's GetTransmittanceToSun,
//                               GetIrradiance, NightFade and PI, on CPU tables.
//
// CloudReference::march is then what probeClouds (cloud_probe.h) computes on the GPU,
// ray for ray: MarchView with the block's slices and step budget, jitter 1/2, no pixel footprint
// (the steps' own lengths still pick the volume's levels where a step spans voxels).
//
// How close (tests/test_cloud_reference.cpp: 36 rays from below, inside and above the layer,
// from orbit down and along the limb, sun high and low, through a baked 64^3 volume and 16^2
// weather faces, reduced tables computed once for both, the GPU given the same float rays):
// on Mesa llvmpipe the GPU's in-scattering is within 0.71 % of this reference (0.11 % on
// average), its transmittance within 3.5e-4; the test allows 5 %, 0.5 % and 2e-3, because
// light that reaches a sample through optically thick cloud moves by percents with the float
// rounding of positions at planet scale, and GPUs with 8-bit filtering weights differ more
// (3.6 %, 0.33 %, 1.1e-3 emulated here). `planet sky-probe` through clouds, GPU against
// --reference (each with its own tables): 0.3 % at most on its test rows.
// Convergence (the same rays, this reference): halving clouds.step_km from 0.1 to 0.05 km
// changes the in-scattering by 16 % at most (a thin sunlit edge), 2.2 % on average; from
// 0.05 to 0.025 km by 3.4 %, 0.46 %. Cost: about 0.2 us per cloud step on one
// core (clouds.sunSamples density samples towards the sun each), 0.02-0.6 ms per ray here.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "atmosphere/model.h"
#include "atmosphere/tables.h"
#include "clouds/clear_sky.h"
#include "clouds/cloud_block.h"
#include "clouds/cloud_model.h"
#include "clouds/cloud_probe.h"
#include "noise/cloud_volume.h"
#include "noise/continents.h"
#include "scene/scene.h"

namespace planet::clouds {

namespace glsl {
using atmosphere::glsl::AtmosphereParameters;
using vec4 = glm::dvec4;
using glm::abs;
using glm::dot;
using glm::length;
using glm::mix;
using glm::smoothstep;
using glm::log2;

// shaders/clouds/cloud_block.glsl's members the march reads, in double (same names).
struct CloudBlockDouble {
    vec3 cameraTileOffset;
    Length tileWidth;
    vec3 cameraFromCentre;
    Length bottomRadius, topRadius;
    Number coverage, densityScale, extinction, scattering;
    Number phaseGForward, phaseGBack, phaseBackWeight;
    Length sunStep, stepKm, largeStepKm;
    Number powder;
    int sunSamples, maxSteps, atmosphereSlices, multipleScatteringOctaves;
    int energyConservingStep, constantDensity, enabled, typeProfiles;
    Number pixelAngle;
    Length voxelKm;
};
CloudBlockDouble widen(const CloudBlock& block);

// The two samplers (nullptr: CloudResources' placeholder texture).
struct VolumeSampler {
    const noise::CloudVolume* volume = nullptr;
    const std::vector<noise::CloudVolume>* mips = nullptr;  // levels 1, 2, ... (noise::cloudVolumeMips)
};
struct WeatherSampler {
    const noise::WeatherMap* map = nullptr;
};
struct ClearSkySampler {
    const ClearSkyMap* map = nullptr;  // clear_sky.h, nearest (nullptr: 0, the placeholder's)
};

// The GLSL globals and the shared march, in double (see the file header). Cheap to make:
// it refers to the tables and the baked data, it does not copy them.
class CloudMarchModel : public atmosphere::glsl::Model {
public:
    CloudMarchModel(const AtmosphereParameters& atmosphere, const atmosphere::AtmosphereTables& tables,
                    const CloudBlock& block, const noise::CloudVolume* volume,
                    const std::vector<noise::CloudVolume>* volumeMips, const noise::WeatherMap* weather,
                    const ClearSkyMap* clearSkyMap);

    // clouds/cloud_block.glsl
    CloudBlockDouble clouds;
    VolumeSampler cloudVolume;
    WeatherSampler weatherMap;
    ClearSkySampler clearSky;
    vec4 textureLod(const VolumeSampler& sampler, vec3 uvw, Number lod) const;
    vec4 textureLod(const WeatherSampler& sampler, vec3 direction, Number lod) const;
    vec4 textureLod(const ClearSkySampler& sampler, vec3 direction, Number lod) const;

    // atmosphere/uniforms.glsl and atmosphere/interface.glsl
    AtmosphereParameters atmosphereParameters() const { return atmosphere_; }
    const atmosphere::Table2D& transmittance_texture;
    const atmosphere::Table3D& scattering_texture;
    const atmosphere::Table3D& single_mie_scattering_texture;
    const atmosphere::Table2D& irradiance_texture;
    ViewRay AirRay(vec3 up, Length altitudeKm, bool byAltitude, vec3 position, vec3 viewRay, vec3 sun);
    vec3 SkyRadianceOfRay(const ViewRay& ray, vec3 camera, vec3 viewRay, vec3 sun, vec3& transmittance);
    vec3 SkyRadianceToPointOfRay(const ViewRay& ray, vec3 camera, vec3 viewRay, Length distance, vec3 sun,
                                 vec3& transmittance);

#define OUT(x) x&
#define INOUT(x) x&
#include "shaders/clouds/cloud_density.glsl"
#include "shaders/clouds/cloud_march.glsl"
#undef OUT
#undef INOUT

private:
    AtmosphereParameters atmosphere_;
};

}  // namespace glsl

// The largest step through empty space the volume's zero-density border allows, km: the
// rule of CloudResources::largeStepKm (border - 1 voxels; noise/cloud_volume.h), 0 for a
// constant layer (no volume).
double largeStepKmOf(const CloudParams& clouds);

// probeClouds (cloud_probe.h) on the CPU, in double. Keeps references to the tables and the
// baked data: they must outlive it. `volume` and `weather` may be null for a constant layer.
class CloudReference {
public:
    // `mipLevels` of the volume are read where a pixel spans voxels, as the GL texture has
    // them (1: level 0 alone).
    CloudReference(const atmosphere::AtmosphereParameters& atmosphere, const atmosphere::AtmosphereTables& tables,
                   const noise::CloudVolume* volume, const noise::WeatherMap* weather,
                   int mipLevels = noise::kCloudVolumeMipLevels);

    // MarchView as cloud_probe.comp calls it, for one ray with `block` as the CloudBlock.
    CloudProbeResult march(const CloudBlock& block, const CloudProbeRay& ray) const;
    // The same for every ray, each with its block (blocks[i] for rays[i]), on all cores.
    std::vector<CloudProbeResult> march(const std::vector<CloudBlock>& blocks,
                                        const std::vector<CloudProbeRay>& rays) const;

private:
    atmosphere::AtmosphereParameters atmosphere_;
    const atmosphere::AtmosphereTables& tables_;
    const noise::CloudVolume* volume_;
    std::vector<noise::CloudVolume> volumeMips_;  // the GL texture's mip levels 1, 2, 3
    const noise::WeatherMap* weather_;
    ClearSkyMap clearSky_;  // of weather_, as CloudResources makes it
};

}  // namespace planet::clouds
