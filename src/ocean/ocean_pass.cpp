#include "ocean/ocean_pass.h"

#include <algorithm>
#include <vector>

#include "ocean/ocean_gpu.h"

namespace planet {

namespace {
constexpr GLuint kWaveBinding = 3;  // shaders/ocean/ocean_waves.glsl
constexpr int kGridExponent = 4;    // Michelic Eq. 2's n for the ocean grid

double seaRadiusM(const Scene& scene) { return scene.planetRadiusM() + scene.ocean.sea_level_m; }
}  // namespace

OceanPass::OceanPass(const gl::ShaderSources& sources)
    : surface_(sources, gl::ProgramDesc{"ocean", {"ocean/ocean.vert", "ocean/ocean.tesc", "ocean/ocean.tese",
                                                  "ocean/ocean.frag"}}),
      underwater_(sources, "underwater", "ocean/underwater.frag") {
    waves_.label("ocean waves");
}

double OceanPass::cameraDepthM(const Scene& scene, const Camera& camera) {
    return seaRadiusM(scene) - glm::length(camera.position);
}

const OceanPass::Locations& OceanPass::locations() {
    const GLuint p = surface_.id();
    if (locations_.program == p) return locations_;
    auto at = [p](const char* name) { return glGetUniformLocation(p, name); };
    locations_ = {p,
                  GridUniforms::lookUp(p),
                  at("uMaxWaveHeight"),
                  at("uTargetEdgePixels"),
                  at("uWaveCount"),
                  at("uFadeStart"),
                  at("uFadeEnd"),
                  at("uCameraUnderwater"),
                  at("uSubgridSlopeVariance"),
                  at("uSeaLevel"),
                  at("uCoarsestEdgePixels")};
    return locations_;
}

void OceanPass::uploadWaves(const Scene& scene, const Camera& camera) {
    const std::vector<ocean::OceanWaveGpu> records =
        ocean::packWaves(scene.waves, camera.position, seaRadiusM(scene), scene.time_s);
    const std::size_t needed = std::max<std::size_t>(records.size(), 1);
    if (needed > waveCapacity_) {  // grow only: a buffer with storage cannot be resized
        waves_ = gl::Buffer();
        waves_.label("ocean waves");
        glNamedBufferStorage(waves_.id(), static_cast<GLsizeiptr>(needed * sizeof(ocean::OceanWaveGpu)), nullptr,
                             GL_DYNAMIC_STORAGE_BIT);
        waveCapacity_ = needed;
    }
    if (!records.empty())
        glNamedBufferSubData(waves_.id(), 0, static_cast<GLsizeiptr>(records.size() * sizeof(ocean::OceanWaveGpu)),
                             records.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWaveBinding, waves_.id());
}

void OceanPass::drawUnderwater(const Scene& scene, const Camera& camera) {
    const GLuint p = underwater_.program().id();
    glProgramUniform1f(p, glGetUniformLocation(p, "uCameraDepth"), static_cast<float>(cameraDepthM(scene, camera)));
    glDisable(GL_DEPTH_TEST);
    underwater_.draw();
}

void OceanPass::drawSurface(const Scene& scene, const Camera& camera) {
    GridParams grid;
    grid.size = scene.ocean.grid_size;
    grid.exponent = kGridExponent;
    grid.hysteresisFraction = scene.terrain.grid_hysteresis;
    mesh_.resize(grid.size);
    const double radius = seaRadiusM(scene);
    const double maxHeight = ocean::maxWaveHeight(scene.waves);
    // The grid must reach the horizon of the wave crests seen from the camera, wherever it is.
    updateAnchor(anchor_, camera, anchorThresholdM(grid, std::abs(glm::length(camera.position) - radius)), false);
    const GridProjection projection = gridProjection(anchor_, radius, maxHeight);
    uploadWaves(scene, camera);

    const Locations& l = locations();
    const GLuint p = l.program;
    l.grid.set(p, projection, grid.exponent, camera.position, radius);
    glProgramUniform1f(p, l.maxWaveHeight, static_cast<float>(maxHeight));
    glProgramUniform1f(p, l.targetEdgePixels, static_cast<float>(scene.ocean.target_edge_px));
    glProgramUniform1i(p, l.waveCount, static_cast<GLint>(scene.waves.size()));
    glProgramUniform1f(p, l.fadeStart, static_cast<float>(scene.ocean.fade_start));
    glProgramUniform1f(p, l.fadeEnd, static_cast<float>(scene.ocean.fade_end));
    glProgramUniform1f(p, l.subgridSlopeVariance,
                       static_cast<float>(ocean::subgridSlopeVariance(scene.waves, scene.ocean.wind_speed_mps)));
    glProgramUniform1f(p, l.seaLevel, static_cast<float>(scene.ocean.sea_level_m));
    glProgramUniform1f(p, l.coarsestEdgePixels,
                       static_cast<float>(std::max(scene.terrain.target_edge_px, scene.ocean.target_edge_px)));
    glProgramUniform1i(p, l.cameraUnderwater, cameraDepthM(scene, camera) > 0.0 ? 1 : 0);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reversed-Z
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);  // the surface is seen from below too
    glUseProgram(p);
    mesh_.draw();
    glDisable(GL_DEPTH_TEST);
}

}  // namespace planet
