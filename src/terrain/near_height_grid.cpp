#include "terrain/near_height_grid.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "render/bindings.h"

namespace planet::terrain {

namespace {

// East and north at the unit `up` (any pair at the poles, where east is undefined).
void tangentAxes(const glm::dvec3& up, glm::dvec3& east, glm::dvec3& north) {
    east = glm::normalize(std::abs(up.z) < 0.9 ? glm::cross(glm::dvec3(0.0, 0.0, 1.0), up)
                                               : glm::cross(glm::dvec3(1.0, 0.0, 0.0), up));
    north = glm::cross(up, east);
}

// The block of a grid at `origin`, its origin seen from `camera` (world, m).
NearHeightGridBlock blockAt(const glm::dvec3& origin, const glm::dvec3& camera, double planetRadiusM) {
    const glm::dvec3 originUp = origin / glm::length(origin);
    glm::dvec3 east, north;
    tangentAxes(originUp, east, north);
    NearHeightGridBlock block{};
    block.east = glm::vec4(glm::vec3(east), static_cast<float>(planetRadiusM));
    block.north = glm::vec4(glm::vec3(north), static_cast<float>(NearHeightGrid::kPoints));
    block.up = glm::vec4(glm::vec3(originUp), 0.0f);
    block.origin = glm::vec4(glm::vec3(origin - camera), static_cast<float>(NearHeightGrid::spacingM()));
    return block;
}

}  // namespace

NearHeightGrid::NearHeightGrid(const gl::ShaderSources& sources)
    : program_(sources, gl::ProgramDesc{"terrain near height grid", {"terrain/near_height_grid.comp"}}) {
    for (Grid& g : grids_) {
        glTextureStorage2D(g.texels.id(), 1, GL_RGBA32F, kPoints, kPoints);
        g.texels.label("terrain near height grid");
        glNamedBufferStorage(g.near.id(), sizeof(TerrainNear), nullptr, GL_DYNAMIC_STORAGE_BIT);
        g.near.label("TerrainNearBlock at a near grid's origin");
        glNamedBufferStorage(g.block.id(), sizeof(NearHeightGridBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
        g.block.label("NearHeightGridBlock of a near grid, for its evaluation");
    }
    glNamedBufferStorage(block_.id(), sizeof(NearHeightGridBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    block_.label("NearHeightGridBlock");
}

void NearHeightGrid::start(Grid& g, const glm::dvec3& origin, const TerrainShape& shape,
                           const noise::CubeMap& continents, double planetRadiusM) {
    // Formed at the origin as if a camera stood there, so the grid's values are the world's, not
    // this camera's (the near field's continents are first order about its camera).
    const TerrainNear near = makeTerrainNear(shape, continents, origin, planetRadiusM);
    glNamedBufferSubData(g.near.id(), 0, sizeof near, &near);
    const NearHeightGridBlock block = blockAt(origin, origin, planetRadiusM);
    glNamedBufferSubData(g.block.id(), 0, sizeof block, &block);
    g.origin = origin;
    g.continent = near.continent;
    g.rows = 0;
}

void NearHeightGrid::prepare(const TerrainShape& shape, const noise::CubeMap& continents, const Camera& camera,
                             double planetRadiusM) {
    const double distance = glm::length(camera.position);
    const glm::dvec3 up = distance > 0.0 ? camera.position / distance : glm::dvec3(0.0, 0.0, 1.0);
    const glm::dvec3 ground = up * planetRadiusM;  // the camera's foot on the planet-radius sphere
    Grid& current = grids_[current_];
    Grid& next = grids_[1 - current_];
    rowsNow_[0] = rowsNow_[1] = 0;
    swapNow_ = false;
    const bool changed = !valid_ || std::memcmp(&shape, &shape_, sizeof shape) != 0 || program_.id() != programId_ ||
                         makeTerrainNear(shape, continents, current.origin, planetRadiusM).continent != current.continent;
    const double fromOrigin = glm::length(ground - current.origin);
    if (nextDue_ && glm::length(ground - next.origin) > kRoamM) nextDue_ = false;  // left behind: a jump
    if (changed || (fromOrigin > kRoamM && !nextDue_)) {
        // The whole grid, at once, where the camera is.
        shape_ = shape;
        start(current, ground, shape, continents, planetRadiusM);
        nextDue_ = false;
    }
    if (current.rows < kPoints) {
        rowsNow_[current_] = kPoints - current.rows;  // (also one started in a frame that did not form it)
    } else if (fromOrigin > kStartM) {
        if (!nextDue_) start(next, ground, shape, continents, planetRadiusM);
        nextDue_ = true;
        // A slice a frame; the rest at once where the camera has left the roam.
        rowsNow_[1 - current_] = fromOrigin > kRoamM ? kPoints - next.rows : std::min(kPoints / kSlices, kPoints - next.rows);
        swapNow_ = next.rows + rowsNow_[1 - current_] == kPoints;
    }
    const Grid& read = swapNow_ ? next : current;
    const NearHeightGridBlock block = blockAt(read.origin, camera.position, planetRadiusM);
    glNamedBufferSubData(block_.id(), 0, sizeof block, &block);
}

void NearHeightGrid::form(const gl::Buffer& frameNear) {
    lastRows_ = 0;
    for (int k = 0; k < 2; ++k) {
        if (rowsNow_[k] <= 0) continue;
        Grid& g = grids_[k];
        glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_TERRAIN_NEAR, g.near.id());
        glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_TERRAIN_NEAR_GRID, g.block.id());
        glBindImageTexture(binding::IMAGE_TERRAIN_NEAR_GRID, g.texels.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        glUseProgram(program_.id());
        glUniform2i(0, g.rows, g.rows + rowsNow_[k]);  // the rows [first, end) of this dispatch
        const GLuint groups = (kPoints + 7) / 8;
        glDispatchCompute(groups, static_cast<GLuint>((rowsNow_[k] + 7) / 8), 1);
        g.rows += rowsNow_[k];
        lastRows_ += rowsNow_[k];
        if (g.rows == kPoints) ++evaluations_;
        rowsNow_[k] = 0;
    }
    if (lastRows_ > 0) {
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_TERRAIN_NEAR, frameNear.id());
        programId_ = program_.id();
        valid_ = true;
    }
    if (swapNow_) {
        current_ = 1 - current_;
        nextDue_ = false;
        swapNow_ = false;
    }
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_TERRAIN_NEAR_GRID, block_.id());
    glBindTextureUnit(binding::UNIT_TERRAIN_NEAR_GRID, grids_[current_].texels.id());
}

}  // namespace planet::terrain
