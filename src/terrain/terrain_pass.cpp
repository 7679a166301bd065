#include "terrain/terrain_pass.h"

#include "render/bindings.h"
#include "terrain/detail_texture.h"
#include "terrain/terrain_block.h"

namespace planet {

TerrainPass::TerrainPass(const gl::ShaderSources& sources)
    : program_(sources, gl::ProgramDesc{"terrain",
                                        {"terrain/terrain.vert", "terrain/terrain.tesc", "terrain/terrain.tese",
                                         "terrain/terrain.frag"}}) {
    glNamedBufferStorage(block_.id(), sizeof(terrain::TerrainBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    block_.label("TerrainBlock");
    glNamedBufferStorage(nearBlock_.id(), sizeof(terrain::TerrainNear), nullptr, GL_DYNAMIC_STORAGE_BIT);
    nearBlock_.label("TerrainNearBlock");
}

void TerrainPass::prepare(const Scene& scene, const Camera& camera, const noise::CubeMap& continents) {
    grid_.size = scene.terrain.grid_size;
    grid_.exponent = scene.terrain.grid_exponent == 2 ? 2 : 4;  // Eq. 2 is defined for these two
    grid_.hysteresisFraction = scene.terrain.grid_hysteresis;
    mesh_.resize(grid_.size);
    const double radius = scene.planetRadiusM();
    updateAnchor(anchor_, camera, anchorThresholdM(grid_, camera.altitude(radius)), false);
    const GridProjection projection = gridProjection(anchor_, radius, scene.terrain.max_height_m);
    mesh_.setProjection(makeGridBlock(projection, grid_.exponent, camera.position, radius));

    const terrain::TerrainBlock block = terrain::makeTerrainBlock(scene);
    glNamedBufferSubData(block_.id(), 0, sizeof block, &block);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_TERRAIN, block_.id());
    const terrain::TerrainNear near = terrain::makeTerrainNear(block.shape, continents, camera.position, radius);
    glNamedBufferSubData(nearBlock_.id(), 0, sizeof near, &near);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_TERRAIN_NEAR, nearBlock_.id());
    if (scene.terrain.detail && !detail_) detail_.emplace(terrain::makeDetailGlTexture(terrain::bakeDetailTexture()));
    if (detail_) glBindTextureUnit(binding::UNIT_TERRAIN_DETAIL, detail_->id());
}

void TerrainPass::draw() const {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reversed-Z
    glDepthMask(GL_TRUE);
    glUseProgram(program_.id());
    mesh_.draw();
    glDisable(GL_DEPTH_TEST);
}

}  // namespace planet
