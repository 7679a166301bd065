#include "ocean/ocean_pass.h"

#include <algorithm>
#include <vector>

#include "grid/constants.h"
#include "grid/view_cull.h"
#include "ocean/far_field.h"
#include "ocean/flat_mirror.h"
#include "ocean/ocean_block.h"
#include "ocean/ocean_gpu.h"
#include "ocean/land_cull.h"
#include "render/bindings.h"
#include "terrain/height.h"

namespace planet {

namespace {
constexpr int kGridExponent = grid_constant::OCEAN_GRID_EXPONENT;  // Michelic Eq. 2's n for the ocean grid

double seaRadiusM(const Scene& scene) { return scene.planetRadiusM() + scene.ocean.sea_level_m; }

// The program's modes (AtmosphereProgram), by their index in get().
constexpr int kFlatMirrorMode = 1, kUnderWaterMode = 2, kSmoothMirrorMode = 3;
constexpr int kGridFlatMirrorMode = 1, kGridSmoothMirrorMode = 2;  // the grid reflection program's modes
constexpr int kGridReflectionGroup = 64;  // ocean/grid_reflection.comp's local_size_x
}  // namespace

OceanPass::OceanPass(const gl::ShaderSources& sources, const atmosphere::TableSizes& tables, bool stencilExport)
    : surface_(sources,
               gl::ProgramDesc{"ocean", {"ocean/ocean.vert", "ocean/ocean.tesc", "ocean/ocean.tese", "ocean/ocean.frag"}}),
      farFieldSurface_(sources.withDefine("OCEAN_FAR_FIELD").withDefine("STENCIL_EXPORT", stencilExport),
                       gl::ProgramDesc{"ocean, far field", {"common/fullscreen.vert", "ocean/ocean.frag"}}),
      light_(sources, tables, gl::ProgramDesc{"sea light", {"common/fullscreen.vert", "ocean/sea_light.frag"}},
             {"OCEAN_FLAT_MIRROR", "UNDER_WATER", "OCEAN_SMOOTH_MIRROR"}),
      openSeaLight_(sources.withDefine("OPEN_SEA"), tables,
                    gl::ProgramDesc{"sea light, open sea", {"common/fullscreen.vert", "ocean/sea_light.frag"}},
                    {"OCEAN_FLAT_MIRROR", "UNDER_WATER", "OCEAN_SMOOTH_MIRROR"}),
      stencilExport_(stencilExport),
      gridReflectionProgram_(sources, tables, gl::ProgramDesc{"ocean grid reflection", {"ocean/grid_reflection.comp"}},
                             {"OCEAN_FLAT_MIRROR", "OCEAN_SMOOTH_MIRROR"}) {
    waves_.label("ocean waves");
    glNamedBufferStorage(block_.id(), sizeof(ocean::OceanBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    block_.label("OceanBlock");
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
}

void OceanPass::prepare(const Scene& scene, const Camera& camera, double radiansPerPixel, double aspect,
                        const std::shared_ptr<const noise::CubeMap>& continents) {
    GridParams grid;
    grid.size = scene.ocean.grid_size;
    grid.exponent = kGridExponent;
    grid.hysteresisFraction = scene.terrain.grid_hysteresis;
    mesh_.resize(grid.size);
    const double radius = seaRadiusM(scene);
    const double maxHeight = ocean::maxWaveHeight(scene.waves);
    // The grid must reach the horizon of the wave crests seen from the camera, wherever it is.
    updateAnchor(anchor_, camera, anchorThresholdM(grid, std::abs(glm::length(camera.position) - radius)), false);
    // Larger patches where the grid's cells are far under the target on screen (grid/grid_stride.h),
    // only as high up as the terrain's (above the ground detail's reach): the sea near the camera
    // keeps its mesh to the vertex. Its base target: the far edges' factor (ocean/edge_target.glsl)
    // only lowers what a cell needs.
    mesh_.setStride(chooseGridStride(
        stride_, strideOverride_,
        gridStrideAllowed(camera.altitude(scene.planetRadiusM()), scene.terrain.max_height_m,
                          terrain::terrainNearRangeM()),
        grid, anchor_, radius, maxHeight, camera, radiansPerPixel, aspect, scene.ocean.target_edge_px, 1.0e30));
    const GridProjection projection = gridProjection(anchor_, radius, maxHeight);
    const GridBlock gridBlock = makeGridBlock(projection, grid.exponent, camera.position, radius, grid.size, mesh_.stride());
    mesh_.setProjection(gridBlock);
    if (continents != continents_) {  // a new map: measure its slope once
        continents_ = continents;
        lipschitz_ = continents ? ocean::continentLipschitz(*continents) : 0.0;
        sampleSlackRad_ = continents ? ocean::continentSampleSlackRad(*continents) : 0.0;
        sampleSlack_ = continents ? ocean::continentSampleSlack(*continents, lipschitz_) : 0.0;
    }
    landContinent_ = continents ? ocean::landContinentThreshold(scene.terrain, scene.ocean.sea_level_m, maxHeight) : 2.0;
    // The runs of patches that cannot reach the view not drawn (grid/view_cull.h): the control
    // stage formed four directions in double and read the continents for every patch of the grid.
    // The waves move the surface up, down and sideways by at most the sum of their amplitudes.
    std::vector<bool> shown = viewCulling_ && !mesh_.blocks().empty()
                                  ? gridBlocksInView(mesh_.blocks(), gridBlock, camera, aspect, radius - maxHeight,
                                                     radius + maxHeight, maxHeight)
                                  : std::vector<bool>{};
    // Nor those over land throughout, where the ground stands above the highest crest (the control
    // stage's overLand for the whole run, with the map as the CPU filters it: the GPU's filter differs
    // by at most the slack in patchLandContinent; the cap widened by the waves' sideways reach). At
    // the inland `ground` view the control stage ran for every run in view to cull all of them.
    if (landCulling_ && continents && landContinent_ <= 1.0 && !mesh_.blocks().empty()) {
        const double threshold = landContinent_ + sampleSlack_, sidewaysRad = maxHeight / radius;
        // Over land throughout where the value less the slope bound over the cap passes the threshold;
        // some of it may be where the value plus that does (at sea no patch is tested one by one).
        const auto bound = [&](const glm::dvec3& centre, double angle, double sign) {
            return terrain::continentValue(glm::vec3(centre), *continents) +
                       sign * lipschitz_ * (angle + sidewaysRad + 1.0e-6) > threshold;
        };
        const std::vector<bool> overLand = gridBlocksWhere(
            mesh_.blocks(), gridBlock, shown, [&](const glm::dvec3& c, double a) { return bound(c, a, -1.0); },
            [&](const glm::dvec3& c, double a) { return bound(c, a, 1.0); });
        if (shown.empty()) shown.assign(overLand.size(), true);
        for (std::size_t i = 0; i < shown.size(); ++i) shown[i] = shown[i] && !overLand[i];
    }
    mesh_.showBlocks(std::move(shown));
    uploadWaves(scene, camera);
    ocean::OceanBlock block = ocean::makeOceanBlock(scene);
    darkContinent_ = continents ? ocean::darkFloorContinentThreshold(scene.terrain, scene.ocean.sea_level_m) : -2.0;
    block.landContinent = static_cast<float>(landContinent_);
    block.patchLandContinent = static_cast<float>(landContinent_ + sampleSlack_);
    block.continentLipschitz = static_cast<float>(lipschitz_);
    block.continentSampleSlackRad = static_cast<float>(sampleSlackRad_);
    block.landCulling = landCulling_ && landContinent_ <= 1.0 ? 1 : 0;
    glNamedBufferSubData(block_.id(), 0, sizeof block, &block);
    const double height = glm::length(camera.position) - radius;
    // (Only while the grid's z_s > 0, the domain of its inverse, terrain/grid.glsl's gridPointOf: from
    // about 120 000 km out the grid's cap reaches past the camera's horizon plane and z_s < 0.)
    farField_ = farFieldAllowed_ && projection.zShift > 0.0 &&
                ocean::seaIsFarField(height, radiansPerPixel, maxHeight, scene.ocean.target_edge_px,
                                     block.coarsestEdgePixels, scene.planetRadiusM());
    smoothMirror_ = flatMirrorMode_ == FlatMirror::Auto ? ocean::seaIsASmoothMirror(scene.waves, height, radiansPerPixel)
                                                        : flatMirrorMode_ == FlatMirror::Smooth;
    flatMirror_ = smoothMirror_ || (flatMirrorMode_ == FlatMirror::Auto
                                        ? ocean::seaIsAFlatMirror(scene.waves, height, radiansPerPixel,
                                                                  scene.clouds.top_altitude_km * 1000.0 - scene.ocean.sea_level_m)
                                        : flatMirrorMode_ == FlatMirror::On);
}

void OceanPass::bindBlock() const { glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_OCEAN, block_.id()); }

std::vector<gl::HotProgram*> OceanPass::builtPrograms() {
    std::vector<gl::HotProgram*> programs{&surface_, &farFieldSurface_};
    for (AtmosphereProgram* a : atmospherePrograms())
        for (gl::HotProgram* p : a->built()) programs.push_back(p);
    return programs;
}

void OceanPass::formGridReflection(const AtmosphereVariant& variant) {
    const int points = mesh_.pointCount();
    if (points != gridReflectionPoints_) {
        const int side = mesh_.size();
        gridReflection_ = gl::Texture(GL_TEXTURE_2D);
        glTextureStorage2D(gridReflection_.id(), 1, GL_RGBA32F, side, side);
        glTextureParameteri(gridReflection_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(gridReflection_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(gridReflection_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(gridReflection_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        gridReflection_.label("ocean grid reflection");
        gridReflectionPoints_ = points;
    }
    mesh_.bindBlock();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_OCEAN_GRID_POINTS, mesh_.points().id());
    glBindImageTexture(binding::IMAGE_OCEAN_GRID_REFLECTION, gridReflection_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glUseProgram(gridReflectionProgram_.get(variant, smoothMirror_ ? kGridSmoothMirrorMode : kGridFlatMirrorMode).id());
    glDispatchCompute(static_cast<GLuint>((points + kGridReflectionGroup - 1) / kGridReflectionGroup), 1, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindTextureUnit(binding::UNIT_OCEAN_GRID_REFLECTION, gridReflection_.id());
}

void OceanPass::bindWavesAndBlock() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_OCEAN_WAVES, waves_.id());
    bindBlock();
}

void OceanPass::drawSurface(const std::function<void()>& drawFarField) {
    bindWavesAndBlock();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reversed-Z
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);  // the surface is seen from below too
    if (farField_) {
        mesh_.bindBlock();  // the grid's projection: the place on the grid of each pixel's point
        glUseProgram(farFieldSurface_.id());
        drawFarField();
        if (countPrimitives_) lastPrimitives_ = 0;
        glDisable(GL_DEPTH_TEST);
        return;
    }
    glUseProgram(surface_.id());
    if (countPrimitives_) glBeginQuery(GL_PRIMITIVES_GENERATED, primitives_.id());
    mesh_.draw();
    if (countPrimitives_) {
        glEndQuery(GL_PRIMITIVES_GENERATED);
        GLuint64 count = 0;
        glGetQueryObjectui64v(primitives_.id(), GL_QUERY_RESULT, &count);
        lastPrimitives_ = static_cast<long long>(count);
    }
    glDisable(GL_DEPTH_TEST);
}

int OceanPass::lightMode(bool underWater) const {
    return underWater ? kUnderWaterMode : smoothMirror_ ? kSmoothMirrorMode : flatMirror_ ? kFlatMirrorMode : 0;
}

void OceanPass::useLightProgram(const AtmosphereVariant& variant, bool underWater) {
    bindWavesAndBlock();
    const int mode = lightMode(underWater);
    if (mode == kFlatMirrorMode || mode == kSmoothMirrorMode) formGridReflection(variant);
    glUseProgram(light_.get(variant, mode).id());
}

void OceanPass::useOpenSeaLightProgram(const AtmosphereVariant& variant) {
    glUseProgram(openSeaLight_.get(variant, lightMode(false)).id());
}

}  // namespace planet
