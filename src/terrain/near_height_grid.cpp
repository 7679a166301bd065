#include "terrain/near_height_grid.h"

#include <cmath>

#include "render/bindings.h"

namespace planet::terrain {

namespace {

// East and north at the unit `up` (any pair at the poles, where east is undefined).
void tangentAxes(const glm::dvec3& up, glm::dvec3& east, glm::dvec3& north) {
    east = glm::normalize(std::abs(up.z) < 0.9 ? glm::cross(glm::dvec3(0.0, 0.0, 1.0), up)
                                               : glm::cross(glm::dvec3(1.0, 0.0, 0.0), up));
    north = glm::cross(up, east);
}

}  // namespace

NearHeightGrid::NearHeightGrid(const gl::ShaderSources& sources)
    : program_(sources, gl::ProgramDesc{"terrain near height grid", {"terrain/near_height_grid.comp"}}) {
    glTextureStorage2D(grid_.id(), 1, GL_RGBA32F, kPoints, kPoints);
    grid_.label("terrain near height grid");
    glNamedBufferStorage(block_.id(), sizeof(NearHeightGridBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    block_.label("NearHeightGridBlock");
    glNamedBufferStorage(originNear_.id(), sizeof(TerrainNear), nullptr, GL_DYNAMIC_STORAGE_BIT);
    originNear_.label("TerrainNearBlock at the near grid's origin");
}

void NearHeightGrid::prepare(const TerrainShape& shape, const noise::CubeMap& continents, const Camera& camera,
                             double planetRadiusM) {
    const double distance = glm::length(camera.position);
    const glm::dvec3 up = distance > 0.0 ? camera.position / distance : glm::dvec3(0.0, 0.0, 1.0);
    const glm::dvec3 ground = up * planetRadiusM;  // the camera's foot on the planet-radius sphere
    if (!valid_ || glm::length(ground - origin_) > kRoamM) {
        origin_ = ground;
        dirty_ = true;
    }
    // Formed at the origin as if a camera stood there, so the grid's values are the world's, not
    // this camera's (the near field's continents are first order about its camera).
    const TerrainNear near = makeTerrainNear(shape, continents, origin_, planetRadiusM);
    if (std::memcmp(&shape, &shape_, sizeof shape) != 0 || near.continent != continent_ || program_.id() != programId_)
        dirty_ = true;
    if (dirty_) {
        shape_ = shape;
        continent_ = near.continent;
        glNamedBufferSubData(originNear_.id(), 0, sizeof near, &near);
    }
    const glm::dvec3 originUp = origin_ / glm::length(origin_);
    glm::dvec3 east, north;
    tangentAxes(originUp, east, north);
    NearHeightGridBlock block{};
    block.east = glm::vec4(glm::vec3(east), static_cast<float>(planetRadiusM));
    block.north = glm::vec4(glm::vec3(north), static_cast<float>(kPoints));
    block.up = glm::vec4(glm::vec3(originUp), 0.0f);
    block.origin = glm::vec4(glm::vec3(origin_ - camera.position), static_cast<float>(spacingM()));
    glNamedBufferSubData(block_.id(), 0, sizeof block, &block);
}

void NearHeightGrid::form(const gl::Buffer& frameNear) {
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_TERRAIN_NEAR_GRID, block_.id());
    if (dirty_) {
        glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_TERRAIN_NEAR, originNear_.id());
        glBindImageTexture(binding::IMAGE_TERRAIN_NEAR_GRID, grid_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        glUseProgram(program_.id());
        const GLuint groups = (kPoints + 7) / 8;
        glDispatchCompute(groups, groups, 1);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_TERRAIN_NEAR, frameNear.id());
        programId_ = program_.id();
        valid_ = true;
        dirty_ = false;
        ++evaluations_;
    }
    glBindTextureUnit(binding::UNIT_TERRAIN_NEAR_GRID, grid_.id());
}

}  // namespace planet::terrain
