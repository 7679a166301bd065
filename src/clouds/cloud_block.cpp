#include "clouds/cloud_block.h"

#include <algorithm>
#include <cmath>

namespace planet::clouds {

glm::dvec3 windDriftKm(const Scene& scene) { return windDriftKm(scene, scene.time_s); }

glm::dvec3 windDriftKm(const Scene& scene, double time_s) {
    const LocalFrame frame = localFrameAt(directionFromLatLon(scene.ocean.wind_latitude_deg,
                                                              scene.ocean.wind_longitude_deg));
    const double bearing = glm::radians(scene.clouds.wind_bearing_deg);
    const glm::dvec3 towards = std::cos(bearing) * frame.north + std::sin(bearing) * frame.east;
    return towards * (scene.clouds.wind_speed_mps * time_s / 1000.0);
}

CloudBlock makeCloudBlock(const Scene& scene, const Camera& camera, double largeStepKm, int volumeSize,
                          double pixelAngle) {
    const CloudParams& c = scene.clouds;
    const double radius = scene.planet.radius_km;
    const double w = c.tile_width_km;
    // Eq. 12's fract(p / w) for the camera, in double: the shaders add only camera-relative
    // lengths to it, so the tile coordinate keeps its precision anywhere on the planet.
    const glm::dvec3 shifted = camera.position / 1000.0 - windDriftKm(scene);
    const glm::dvec3 offset = shifted - w * glm::floor(shifted / w);

    CloudBlock b{};
    b.cameraTileOffset = glm::vec3(offset);
    b.tileWidth = static_cast<float>(w);
    b.cameraFromCentre = glm::vec3(camera.position / 1000.0);
    b.bottomRadius = static_cast<float>(radius + c.bottom_altitude_km);
    b.topRadius = static_cast<float>(radius + c.top_altitude_km);
    b.coverage = static_cast<float>(c.coverage);
    b.densityScale = static_cast<float>(c.density_scale);
    b.extinction = static_cast<float>(c.extinction_per_km);
    b.scattering = static_cast<float>(c.extinction_per_km * c.single_scattering_albedo);
    b.phaseGForward = static_cast<float>(c.phase_g_forward);
    b.phaseGBack = static_cast<float>(c.phase_g_back);
    b.phaseBackWeight = static_cast<float>(c.phase_back_weight);
    b.sunStep = static_cast<float>(c.sun_step_km);
    b.stepKm = static_cast<float>(c.step_km);
    b.largeStepKm = static_cast<float>(std::max(largeStepKm, c.step_km));
    b.powder = static_cast<float>(c.powder);
    b.sunSamples = c.sun_samples;
    b.maxSteps = c.max_steps;
    b.atmosphereSlices = c.atmosphere_slices;
    b.multipleScatteringOctaves = c.multiple_scattering_octaves;
    b.energyConservingStep = c.energy_conserving_step ? 1 : 0;
    b.constantDensity = c.constant_density ? 1 : 0;
    b.typeProfiles = c.type_profiles ? 1 : 0;
    b.pixelAngle = static_cast<float>(pixelAngle);
    // No far field without a volume or when it is switched off (the footprint never reaches
    // twice "no voxel").
    b.voxelKm = volumeSize > 0 && c.far_field ? static_cast<float>(w / volumeSize) : 1.0e30f;
    b.enabled = c.enabled && (c.constant_density || c.coverage > 0.0) && c.density_scale > 0.0 &&
                        c.extinction_per_km > 0.0
                    ? 1
                    : 0;
    return b;
}

bool seenInFarFieldOnly(const CloudBlock& block, double cameraRadiusKm, double highestGroundRadiusKm) {
    if (block.constantDensity != 0 || !(block.voxelKm < 1.0e20f) || !(block.pixelAngle > 0.0f)) return false;
    const double nearestKm = cameraRadiusKm - std::max(double(block.topRadius), highestGroundRadiusKm);
    // A margin over the 8 voxels for the shaders' float rounding of the distances and the blend.
    constexpr double kFarFieldVoxels = 8.0 * 1.02;
    return nearestKm * double(block.pixelAngle) >= kFarFieldVoxels * double(block.voxelKm);
}

}  // namespace planet::clouds
