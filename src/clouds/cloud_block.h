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

// Whether every footprint a frame sees the clouds with is the far field's alone (shaders/clouds/
// cloud_density.glsl: CloudFarBlend at 1, from 8 voxels), so that its programs may be built
// with CLOUD_FAR_FIELD_ONLY. A footprint is a point's distance from the camera times the angle
// of a pixel (the march's, the surfaces' shadows'; the sea's reflected rays start at the sea,
// farther still), and every point the clouds are looked up at lies in the layer or on the
// ground: no nearer than the camera's height above the higher of the layer's top and
// `highestGroundRadiusKm` (from the planet's centre). Not for a layer of constant density (no
// far field) or without a volume (voxelKm "none"). `cameraRadiusKm`: the camera's distance
// from the planet's centre, in double.
bool seenInFarFieldOnly(const CloudBlock& block, double cameraRadiusKm, double highestGroundRadiusKm);

}  // namespace planet::clouds
