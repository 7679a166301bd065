// The GPU's unified march of clouds and atmosphere along given rays
// (shaders/clouds/cloud_probe.comp runs MarchView, the function the sky pass runs), for
// tests against closed forms and for `planet sky-probe`.
#pragma once

#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "atmosphere/precompute_gpu.h"
#include "atmosphere/uniforms.h"
#include "clouds/cloud_resources.h"
#include "gl/program.h"

namespace planet::clouds {

struct CloudProbeRay {
    glm::dvec3 origin;     // km from the planet centre
    glm::dvec3 direction;  // unit
    glm::dvec3 sun;        // unit, towards the sun
    double distanceKm = 0; // to the surface point; <= 0: to space
};

struct CloudProbeResult {
    glm::dvec3 transmittance;
    glm::dvec3 inscatter;  // W m^-2 sr^-1 nm^-1, the sky beyond included for rays to space
    int steps = 0;         // small cloud steps
    int skipped = 0;       // large steps through empty space
};

// The probe's program, built once for table sizes and run for any number of ray lists
// (`planet sky-probe` runs one list per camera position). Needs a GL context.
class CloudProbe {
public:
    CloudProbe(const std::filesystem::path& shaderRoot, const atmosphere::TableSizes& sizes);
    // `block` is bound as the CloudBlock (its cameraFromCentre and cameraTileOffset place the
    // volume), the volume and the weather map of `textures` (may be null) at their units;
    // cube maps are sampled seamlessly, as the renderer does.
    std::vector<CloudProbeResult> run(const atmosphere::GpuTables& tables,
                                      const atmosphere::AtmosphereUniforms& atmosphere, const CloudBlock& block,
                                      const CloudResources* textures, const std::vector<CloudProbeRay>& rays) const;

private:
    gl::Program program_;
};

// One CloudProbe run: builds the program, runs it once.
std::vector<CloudProbeResult> probeClouds(const std::filesystem::path& shaderRoot,
                                          const atmosphere::GpuTables& tables,
                                          const atmosphere::AtmosphereUniforms& atmosphere, const CloudBlock& block,
                                          const CloudResources* textures, const std::vector<CloudProbeRay>& rays);

}  // namespace planet::clouds
