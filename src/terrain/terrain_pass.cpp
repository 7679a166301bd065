#include "terrain/terrain_pass.h"

#include <string_view>

#include "render/bindings.h"
#include "terrain/detail_texture.h"
#include "terrain/height.h"
#include "terrain/terrain_block.h"

namespace planet {

namespace {

gl::ProgramDesc terrainProgram(const char* name) {
    return gl::ProgramDesc{name, {"terrain/terrain.vert", "terrain/terrain.tesc", "terrain/terrain.tese", "terrain/terrain.frag"}};
}

}  // namespace

bool TerrainPass::detailInReach(double cameraAltitudeM, double maxHeightM) {
    return cameraAltitudeM - maxHeightM < terrain::terrainNearRangeM();
}

TerrainPass::TerrainPass(const gl::ShaderSources& sources)
    : sources_(sources), plain_(sources, terrainProgram("terrain")) {
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
    if (scene.terrain.detail && !detail_) {
        const terrain::DetailTexture baked = terrain::bakeDetailTexture();
        detail_.emplace(terrain::makeDetailGlTexture(baked));
        detailLostVariance_ = baked.lostSlopeVariance;
    }
    if (scene.terrain.detail && !detailed_)
        detailed_.emplace(gl::ShaderSources{sources_.root, sources_.preamble + "#define TERRAIN_DETAIL 1\n"},
                          terrainProgram("terrain (TERRAIN_DETAIL)"));
    // The detail fades out by TERRAIN_NEAR_RANGE_M from the camera (terrain/terrain.frag); a
    // camera higher than that above the highest possible ground has none in view, and the
    // program without the detail's code draws the same pixels for less (llvmpipe pays for
    // code no pixel enters: `orbit` 640x360, 33 -> 73 ms of terrain pass with it).
    detailOn_ = scene.terrain.detail && detailInReach(camera.altitude(radius), scene.terrain.max_height_m);
    if (detail_) glBindTextureUnit(binding::UNIT_TERRAIN_DETAIL, detail_->id());
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

void TerrainPass::draw() {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reversed-Z
    glDepthMask(GL_TRUE);
    const gl::HotProgram& program = detailDrawn() ? *detailed_ : plain_;
    glUseProgram(program.id());
    // The detail filter's table (terrain/detail.glsl); absent from the program when unused.
    const GLint lostVariance = glGetUniformLocation(program.id(), "uTerrainDetailLostVariance");
    if (lostVariance >= 0 && !detailLostVariance_.empty())
        glUniform1fv(lostVariance, static_cast<GLsizei>(detailLostVariance_.size()), detailLostVariance_.data());
    const bool stages = statistics_ && pipelineStatistics();
    if (statistics_) glBeginQuery(GL_PRIMITIVES_GENERATED, primitives_.id());
    if (stages) {
        glBeginQuery(GL_VERTEX_SHADER_INVOCATIONS, vertices_.id());
        glBeginQuery(GL_CLIPPING_OUTPUT_PRIMITIVES, clipped_.id());
        glBeginQuery(GL_TESS_CONTROL_SHADER_PATCHES, patches_.id());
        glBeginQuery(GL_TESS_EVALUATION_SHADER_INVOCATIONS, evaluations_.id());
        glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS, fragments_.id());
    }
    mesh_.draw();
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

std::vector<gl::HotProgram*> TerrainPass::programs() {
    std::vector<gl::HotProgram*> built{&plain_};
    if (detailed_) built.push_back(&*detailed_);
    return built;
}

}  // namespace planet
