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

// Needs a GL context. `block` is bound as the CloudBlock (its cameraFromCentre and
// cameraTileOffset place the volume), `volume` and `weather` at their units.
std::vector<CloudProbeResult> probeClouds(const std::filesystem::path& shaderRoot,
                                          const atmosphere::GpuTables& tables,
                                          const atmosphere::AtmosphereUniforms& atmosphere, const CloudBlock& block,
                                          const CloudResources* textures, const std::vector<CloudProbeRay>& rays);

}  // namespace planet::clouds
