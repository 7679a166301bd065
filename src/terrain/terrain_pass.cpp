#include "terrain/terrain_pass.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>

#include "grid/view_cull.h"
#include "render/bindings.h"
#include "terrain/continent_bound.h"
#include "terrain/detail_texture.h"
#include "terrain/height.h"
#include "terrain/near_height_grid.h"
#include "terrain/terrain_block.h"

namespace planet {

namespace {

gl::ProgramDesc materialProgram(const char* name) {
    return gl::ProgramDesc{name, {"common/fullscreen.vert", "terrain/ground_material.frag"}};
}

}  // namespace

bool TerrainPass::detailInReach(double cameraAltitudeM, double maxHeightM) {
    return cameraAltitudeM - maxHeightM < terrain::terrainNearRangeM();
}

int TerrainPass::detailPatchCount(const std::vector<PatchRun>& rings, int patchCount, int gridSize,
                                  const GridBlock& grid, double rangeM) {
    // A fragment lies on a triangle whose corners are tessellated points of its patch; the
    // triangle's chord can come nearer than its corners by (edge^2 / 8 range): metres for
    // the edges of hundreds of metres there can be, which the margin covers (the detail's
    // strength is under 3 % beyond 0.95 of its range anyway: terrain/ground_material.frag's smoothstep).
    constexpr double kMargin = 1.05;
    const glm::dvec3 camera(grid.cameraPositionAndRadius);
    const glm::dvec3 axis(grid.worldFromGridColumns[2]);  // grid z, towards the projection camera
    const double cameraAngle = std::atan2(glm::length(glm::cross(camera, axis)), glm::dot(camera, axis));
    for (const PatchRun& ring : rings) {
        const double beyond = angleOutsideVertexBox(ring.pointMin, ring.pointMax, gridSize, grid.exponent, grid.zShift);
        // Every point beyond the ring's box is at least `beyond - cameraAngle` from the
        // camera's direction (seen from the centre), so at least |camera| sin of that away.
        const double apart = beyond - cameraAngle;
        const double nearest = apart <= 0.0 ? 0.0 : glm::length(camera) * std::sin(std::min(apart, 0.5 * std::numbers::pi));
        if (nearest >= kMargin * rangeM) return ring.firstPatch + ring.patchCount;
    }
    return patchCount;
}

TerrainPass::TerrainPass(const gl::ShaderSources& sources)
    : sources_(sources),
      meshProgram_(sources, gl::ProgramDesc{"terrain", {"terrain/terrain.vert", "terrain/terrain.tesc",
                                                        "terrain/terrain.tese", "terrain/terrain.frag"}}),
      plain_(sources, materialProgram("ground material")) {
    glNamedBufferStorage(block_.id(), sizeof(terrain::TerrainBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    block_.label("TerrainBlock");
    glNamedBufferStorage(nearBlock_.id(), sizeof(terrain::TerrainNear), nullptr, GL_DYNAMIC_STORAGE_BIT);
    nearBlock_.label("TerrainNearBlock");
}

void TerrainPass::prepare(const Scene& scene, const Camera& camera, const noise::CubeMap& continents,
                          double radiansPerPixel, double aspect) {
    grid_.size = scene.terrain.grid_size;
    grid_.exponent = scene.terrain.grid_exponent == 2 ? 2 : 4;  // Eq. 2 is defined for these two
    grid_.hysteresisFraction = scene.terrain.grid_hysteresis;
    mesh_.resize(grid_.size);
    const double radius = scene.planetRadiusM();
    updateAnchor(anchor_, camera, anchorThresholdM(grid_, camera.altitude(radius)), false);
    // Larger patches where the grid's cells are far under the target on screen (grid/grid_stride.h),
    // only above the detail's reach: the views near the ground keep their mesh to the vertex.
    mesh_.setStride(chooseGridStride(
        stride_, strideOverride_,
        gridStrideAllowed(camera.altitude(radius), scene.terrain.max_height_m, terrain::terrainNearRangeM()), grid_,
        anchor_, radius, scene.terrain.max_height_m, camera, radiansPerPixel, aspect, scene.terrain.target_edge_px,
        kTerrainMaxSagM));
    const GridProjection projection = gridProjection(anchor_, radius, scene.terrain.max_height_m);
    const GridBlock gridBlock = makeGridBlock(projection, grid_.exponent, camera.position, radius, grid_.size, mesh_.stride());
    mesh_.setProjection(gridBlock);

    const terrain::TerrainBlock block = terrain::makeTerrainBlock(scene);
    // The runs of patches that cannot reach the view not drawn (grid/view_cull.h): at `ground` the
    // vertex and control stages ran for the whole grid (9801 patches; now 3592 at 160x90), on
    // llvmpipe's one submitting thread.
    mesh_.showBlocks(viewCulling_ && !mesh_.blocks().empty()
                         ? gridBlocksInView(mesh_.blocks(), gridBlock, camera, aspect,
                                            radius - static_cast<double>(block.shape.oceanDepth),
                                            radius + static_cast<double>(block.shape.maxHeight))
                         : std::vector<bool>{});
    glNamedBufferSubData(block_.id(), 0, sizeof block, &block);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_TERRAIN, block_.id());
    const terrain::TerrainNear near = terrain::makeTerrainNear(block.shape, continents, camera.position, radius);
    glNamedBufferSubData(nearBlock_.id(), 0, sizeof near, &near);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_TERRAIN_NEAR, nearBlock_.id());
    if (scene.terrain.detail && !detail_) {
        const terrain::DetailTexture baked = terrain::bakeDetailTexture();
        detail_.emplace(terrain::makeDetailGlTexture(baked));
        detailLostVariance_ = baked.lostSlopeVariance;
    }
    if (scene.terrain.detail && !detailed_)
        detailed_.emplace(sources_.withDefine("TERRAIN_DETAIL").withDefine("TERRAIN_NEAR_GRID", nearGridOn_),
                          materialProgram(nearGridOn_ ? "ground material (TERRAIN_DETAIL, TERRAIN_NEAR_GRID)"
                                                      : "ground material (TERRAIN_DETAIL)"));
    if (scene.terrain.detail && nearGridOn_ && !nearGrid_) nearGrid_.emplace(sources_);
    // The detail fades out by TERRAIN_NEAR_RANGE_M from the camera (terrain/ground_material.frag); a
    // camera higher than that above the highest possible ground has none in view, and the
    // program without the detail's code draws the same pixels for less (llvmpipe pays for
    // code no pixel enters: `orbit` 640x360, 33 -> 73 ms of terrain pass with it).
    // Within reach, only the patches that can come within the range take the detail's program
    // (`ground`: the 64 of the centre's block of 9801), the rest the plain one, for the same reason.
    const bool inReach =
        scene.terrain.detail && detailed_ && detailInReach(camera.altitude(radius), scene.terrain.max_height_m);
    detailPatches_ = !inReach             ? 0
                     : detailOnEveryPatch_ ? mesh_.patchCount()
                                           : detailPatchCount(mesh_.rings(), mesh_.patchCount(), grid_.size, gridBlock,
                                                              terrain::terrainNearRangeM());
    if (detail_) glBindTextureUnit(binding::UNIT_TERRAIN_DETAIL, detail_->id());
    // The near field on its grid, for the detail's program (terrain/near_height_grid.h): only where
    // that program draws, the camera near the ground.
    if (detailPatches_ > 0 && nearGrid_) nearGrid_->prepare(block.shape, continents, camera, radius);
}

namespace {

bool pipelineStatistics() {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major > 4 || (major == 4 && minor >= 6)) return true;
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i)
        if (std::string_view(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)))) ==
            "GL_ARB_pipeline_statistics_query")
            return true;
    return false;
}

long long queryResult(GLuint query) {
    GLuint64 count = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &count);
    return static_cast<long long>(count);
}

}  // namespace

void TerrainPass::drawMesh() {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reversed-Z
    glDepthMask(GL_TRUE);
    const int nearPatches = detailPatches();
    const bool stages = statistics_ && pipelineStatistics();
    if (statistics_) glBeginQuery(GL_PRIMITIVES_GENERATED, primitives_.id());
    if (stages) {
        glBeginQuery(GL_VERTEX_SHADER_INVOCATIONS, vertices_.id());
        glBeginQuery(GL_CLIPPING_OUTPUT_PRIMITIVES, clipped_.id());
        glBeginQuery(GL_TESS_CONTROL_SHADER_PATCHES, patches_.id());
        glBeginQuery(GL_TESS_EVALUATION_SHADER_INVOCATIONS, evaluations_.id());
        glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS, fragments_.id());
    }
    glUseProgram(meshProgram_.id());
    if (nearPatches > 0) {
        glStencilFunc(GL_ALWAYS, kDetailedStencil, 0xFF);
        mesh_.draw(0, nearPatches);
    }
    glStencilFunc(GL_ALWAYS, kPlainStencil, 0xFF);
    mesh_.draw(nearPatches, mesh_.patchCount() - nearPatches);
    if (stages) {
        glEndQuery(GL_VERTEX_SHADER_INVOCATIONS);
        glEndQuery(GL_CLIPPING_OUTPUT_PRIMITIVES);
        glEndQuery(GL_TESS_CONTROL_SHADER_PATCHES);
        glEndQuery(GL_TESS_EVALUATION_SHADER_INVOCATIONS);
        glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS);
    }
    if (statistics_) {
        glEndQuery(GL_PRIMITIVES_GENERATED);
        lastStatistics_ = Statistics{};
        lastStatistics_.primitives = queryResult(primitives_.id());
        if (stages) {
            lastStatistics_.vertices = queryResult(vertices_.id());
            lastStatistics_.clipped = queryResult(clipped_.id());
            lastStatistics_.patches = queryResult(patches_.id());
            lastStatistics_.evaluations = queryResult(evaluations_.id());
            lastStatistics_.fragments = queryResult(fragments_.id());
        }
    }
    glDisable(GL_DEPTH_TEST);
}

void TerrainPass::useMaterialProgram(bool detailed) {
    if (!detailed || !detailed_) {
        glUseProgram(plain_.id());
        return;
    }
    if (nearGrid_) nearGrid_->form(nearBlock_);  // evaluated where it moved or the terrain changed
    glUseProgram(detailed_->id());
    // The detail filter's table (terrain/detail.glsl); absent from the program when unused.
    const GLint lostVariance = glGetUniformLocation(detailed_->id(), "uTerrainDetailLostVariance");
    if (lostVariance >= 0 && !detailLostVariance_.empty())
        glUniform1fv(lostVariance, static_cast<GLsizei>(detailLostVariance_.size()), detailLostVariance_.data());
}

void TerrainPass::setDarkFloorCulling(double patchDarkContinent, double continentLipschitz) {
    struct {
        float patchDarkContinent, continentLipschitz;
        int darkFloorCulling;
        float continentMaxRadius;
    } cull{static_cast<float>(patchDarkContinent), static_cast<float>(continentLipschitz), 1,
           static_cast<float>(terrain::kContinentMaxRadiusRad)};
    glNamedBufferSubData(block_.id(), offsetof(terrain::TerrainBlock, patchDarkContinent), sizeof cull, &cull);
}

std::vector<gl::HotProgram*> TerrainPass::programs() {
    std::vector<gl::HotProgram*> built{&meshProgram_, &plain_};
    if (detailed_) built.push_back(&*detailed_);
    if (nearGrid_) built.push_back(&nearGrid_->program());
    return built;
}

}  // namespace planet
