// CloudBlock: the cloud layer as the shaders read it (BLOCK_CLOUDS), C++ mirror of
// shaders/clouds/cloud_block.glsl (std140, offsets static_asserted), formed in double.
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/scene.h"

namespace planet::clouds {

struct CloudBlock {
    glm::vec3 cameraTileOffset;
    float tileWidth;
    glm::vec3 cameraFromCentre;
    float bottomRadius;
    float topRadius;
    float coverage;
    float densityScale;
    float extinction;
    float scattering;
    float phaseGForward;
    float phaseGBack;
    float phaseBackWeight;
    float sunStep;
    float stepKm;
    float largeStepKm;
    float powder;
    int sunSamples;
    int maxSteps;
    int atmosphereSlices;
    int multipleScatteringOctaves;
    int energyConservingStep;
    int constantDensity;
    int enabled;
    int typeProfiles;
    float pixelAngle;
    float voxelKm;
    int statistics = 0;
    float padding2 = 0.0f;
};
static_assert(offsetof(CloudBlock, cameraFromCentre) == 16 && offsetof(CloudBlock, bottomRadius) == 28 &&
                  offsetof(CloudBlock, sunSamples) == 80 && offsetof(CloudBlock, enabled) == 104 &&
                  offsetof(CloudBlock, pixelAngle) == 112 && sizeof(CloudBlock) == 128,
              "CloudBlock must match std140 (shaders/clouds/cloud_block.glsl)");

// The drift of the clouds after the scene's time_s seconds of wind (or `time_s`): a
// world-space translation, km, along the wind's bearing at the ocean's wind point (a fixed
// place, so that the drift does not change as the camera moves).
glm::dvec3 windDriftKm(const Scene& scene);
glm::dvec3 windDriftKm(const Scene& scene, double time_s);

// The block for a scene seen from a camera. `largeStepKm` is the step the volume's
// zero-density border allows and `volumeSize` its voxels per side (cloud_resources.h; 0:
// none, no far field); `pixelAngle` the angle a pixel spans (0: no far field either).
// `enabled` false gives the clear sky.
CloudBlock makeCloudBlock(const Scene& scene, const Camera& camera, double largeStepKm, int volumeSize = 0,
                          double pixelAngle = 0.0);

}  // namespace planet::clouds
