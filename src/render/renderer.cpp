#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <initializer_list>
#include <set>
#include <stdexcept>

#include "gl/debug.h"
#include "render/bindings.h"
#include "scene/preset.h"
#include "util/log.h"

namespace planet {

namespace {

using R = FrameResource;

gl::ShaderSources withAtmosphere(const gl::ShaderSources& s, const atmosphere::TableSizes& sizes) {
    return {s.root, s.preamble + atmosphere::atmosphereShaderDefines(sizes)};
}

// A camera that moved farther than this in one frame (or turned further) has jumped: what
// the history shows is somewhere else (a view bookmark, a teleport), not the last frame.
constexpr double kJumpFractionOfAltitude = 0.25;
constexpr double kJumpMinimumM = 10.0;
constexpr double kJumpTurnCos = 0.866;  // 30 degrees
// A sun that turned farther than this in one frame has jumped too (a time-of-day drag); a
// slower one (a path through dusk) keeps the history, which the temporal march clamps.
constexpr double kSunJumpCos = 0.99985;  // 1 degree

// Every parameter that the history depends on, as a preset would save them: all but the sun's
// position (compared as a direction, kSunJumpCos) and the exposure (applied after the history).
std::string historyKey(const Scene& scene) {
    Scene keyed = scene;
    keyed.sun.latitude_deg = 0.0;
    keyed.sun.longitude_deg = 0.0;
    keyed.render.exposure = 1.0;
    return presetToToml(keyed, "", "");
}

// The sky passes' program variant with the terrain's shadows in the air (atmosphere_program.h).
bool lightShafts(const Scene& s) { return s.terrain.light_shafts && s.terrain.shadows; }

// One invocation of the bound compute program per pixel of `list` (render/pixel_list.glsl),
// dispatched indirectly with the group count its listing left (none when it listed none); what
// the invocations stored is then visible to texture reads, draws and image loads.
void dispatchOverList(const gl::Buffer& list) {
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, list.id());
    glDispatchComputeIndirect(0);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

// The built variants of a pass's programs, for its hot-reload list.
std::vector<gl::HotProgram*> builtVariants(std::initializer_list<AtmosphereProgram*> programs) {
    std::vector<gl::HotProgram*> all;
    for (AtmosphereProgram* p : programs) {
        const std::vector<gl::HotProgram*> built = p->built();
        all.insert(all.end(), built.begin(), built.end());
    }
    return all;
}

// A pass's programs and more, for its hot-reload list.
std::vector<gl::HotProgram*> withPrograms(std::vector<gl::HotProgram*> programs, const std::vector<gl::HotProgram*>& more) {
    programs.insert(programs.end(), more.begin(), more.end());
    return programs;
}

// The bound program's full-screen triangle on the pixels of `rect` alone (scissored; nothing
// when it is empty): on a software renderer the pixels outside cost nothing.
void drawScissored(const ScreenRect& rect, glm::ivec2 size) {
    if (rect.coversScreen(size)) {
        glDrawArrays(GL_TRIANGLES, 0, 3);
        return;
    }
    if (rect.empty()) return;
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.min.x, rect.min.y, rect.max.x - rect.min.x, rect.max.y - rect.min.y);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_SCISSOR_TEST);
}

// The stencil's three states in the passes that split a draw by it: marking the pixels a draw
// writes with `ref` (in the bits of `mask` alone: the others keep what an earlier pass left there);
// a test for `ref` in those bits, or for anything else there (`equal` false), which writes nothing
// and so may run before the shader (a software renderer then spares the pixels it rejects); off
// again, as every pass finds it.
void stencilMark(GLint ref, GLuint mask = 0xFF) {
    glEnable(GL_STENCIL_TEST);
    glStencilMask(mask);
    glStencilFunc(GL_ALWAYS, ref, mask);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
}
void stencilTest(GLint ref, GLuint mask = 0xFF, bool equal = true) {
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilFunc(equal ? GL_EQUAL : GL_NOTEQUAL, ref, mask);
}
void stencilOff() {
    glStencilMask(0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glDisable(GL_STENCIL_TEST);
}

}  // namespace

const char* frameResourceName(FrameResource r) {
    switch (r) {
        case R::GBuffer: return "G-buffer";
        case R::TerrainShadow: return "terrain shadow samples";
        case R::SurfaceRadiance: return "surface radiance";
        case R::SeaReflection: return "sea reflection";
        case R::SparseSky: return "sparse sky";
        case R::SkyRefine: return "sky refine list";
        case R::HdrRadiance: return "HDR radiance";
        case R::LdrImage: return "LDR image";
        case R::Window: return "window";
    }
    return "?";
}

std::vector<std::string> checkPassOrder(const std::vector<PassDeclaration>& passes) {
    std::vector<std::string> problems;
    std::set<FrameResource> written;
    for (const PassDeclaration& p : passes) {
        for (FrameResource r : p.reads)
            if (!written.count(r))
                problems.push_back("pass '" + p.name + "' reads " + frameResourceName(r) + " before any pass writes it");
        written.insert(p.writes.begin(), p.writes.end());
    }
    return problems;
}

Renderer::Renderer(const std::filesystem::path& shaderRoot, const atmosphere::TablePlan& atmosphereTables,
                   std::shared_ptr<terrain::Continents> continents)
    : sources_{shaderRoot, gl::shaderPreamble()},
      atmosphere_(shaderRoot, atmosphereTables),
      programTables_(atmosphereTables.firstSizes()),
      continents_(continents ? std::move(continents) : std::make_shared<terrain::Continents>()),
      terrain_(sources_),
      terrainShadow_(withAtmosphere(sources_, programTables_), "terrain shadow", "render/terrain_shadow.frag"),
      stencilExport_(epoxy_has_gl_extension("GL_ARB_shader_stencil_export")),
      surfaceMarks_(surfaceMarksSources(programTables_), "surface light marks", "render/surface_marks.frag"),
      surfaceLight_(sources_, programTables_,
                    gl::ProgramDesc{"surface light", {"common/fullscreen.vert", "render/surface_light.frag"}},
                    {"SEA_FLOOR_DARK", "SUN_CLEAR_OF_CLOUDS"}),
      ocean_(sources_, programTables_, stencilExport_),
      seaReflection_(sources_, programTables_,
                     gl::ProgramDesc{"sea reflection", {"common/fullscreen.vert", "ocean/sea_reflection.frag"}},
                     {"SEA_REFLECTION_COMPOSE", "SEA_REFLECTION_LIST_ALL"}),
      terrainShadowMarches_(sources_, programTables_,
                        gl::ProgramDesc{"terrain shadow, sample marches", {"render/terrain_shadow_sample_marches.comp"}}),
      terrainShadowListed_(sources_, programTables_,
                           gl::ProgramDesc{"terrain shadow, listed pixels", {"render/terrain_shadow_list.comp"}},
                           {"TERRAIN_SHADOW_LIST_GROUND"}),
      seaReflectionListed_(sources_, programTables_,
                           gl::ProgramDesc{"sea reflection, listed pixels", {"ocean/sea_reflection.comp"}}),
      terrainReflection_(sources_, programTables_,
                         gl::ProgramDesc{"terrain reflection", {"ocean/terrain_reflection.comp"}}),
      sky_(sources_, programTables_, gl::ProgramDesc{"sky", {"common/fullscreen.vert", "render/sky.frag"}},
           {"UNDER_WATER"}),
      skySparse_(sources_, programTables_,
                 gl::ProgramDesc{"sky march", {"common/fullscreen.vert", "render/sky_sparse.frag"}}, {"STILL_FRAME"}),
      skyTemporal_(sources_, programTables_,
                   gl::ProgramDesc{"sky temporal", {"common/fullscreen.vert", "render/sky_temporal.frag"}},
                   {"STILL_FRAME", "STILL_FRAME_UNJITTERED"}),
      skyRefine_(sources_, programTables_, gl::ProgramDesc{"sky refine", {"render/sky_refine.comp"}}, {"STILL_FRAME"}),
      skySpace_(withAtmosphere(sources_, programTables_), "sky space", "render/sky_space.frag"),
      skyNoCloud_(sources_, "sky meeting no cloud", "render/sky_no_cloud.frag"),
      skySparseNoCloud_(sources_.withDefine("SPARSE_LATTICE"),
                        "sky march meeting no cloud", "render/sky_no_cloud.frag"),
      antialias_(sources_, "antialias", "render/antialias.frag"),
      tonemap_(sources_, "tonemap", "render/tonemap.frag"),
      passes_(makePasses()) {
    glNamedBufferStorage(frameUniforms_.id(), sizeof(FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    frameUniforms_.label("FrameBlock");
    emptyVertexArray_.label("fullscreen triangle");
    const std::vector<std::string> problems = checkPassOrder(passDeclarations());
    if (!problems.empty()) throw std::logic_error("frame pass order: " + problems.front());
}

// The terrain's shadow at the pixels a pass listed (render/terrain_shadow_list.glsl), marched each
// on its own from the ground or from sea level and taken from the surface radiance in place. (It
// reads neither the clouds nor the scattering table: one program per start.)
void Renderer::marchListedTerrainShadow(bool fromGround) {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindImageTexture(binding::IMAGE_SURFACE_RADIANCE, targets_.surfaceRadiance().id(), 0, GL_FALSE, 0, GL_READ_WRITE,
                       GL_RGBA16F);
    glBindTextureUnit(binding::UNIT_SURFACE_DISTANCE, targets_.surfaceDistance().id());
    ocean_.bindBlock();
    glUseProgram(terrainShadowListed_.get(AtmosphereVariant{}, fromGround ? 1 : 0).id());
    dispatchOverList(targets_.terrainShadowList());
}

std::vector<Renderer::Pass> Renderer::makePasses() {
    auto always = [](const Scene&) { return true; };
    std::vector<Pass> passes;
    passes.push_back({{"terrain", {}, {R::GBuffer}}, always,
                      [this](const Scene&) {
                          const GLuint fb = targets_.gbuffer().framebuffer.id();
                          const float zero[4] = {0, 0, 0, 0};
                          for (GLint i = 0; i < 3; ++i) glClearNamedFramebufferfv(fb, GL_COLOR, i, zero);
                          // (reversed-Z: 0 is infinitely far; the stencil 0: no terrain)
                          glClearNamedFramebufferfi(fb, GL_DEPTH_STENCIL, 0, 0.0f, 0);
                          // The mesh first: its fragments' points, marked in the stencil; then the
                          // ground's material once per marked pixel, each program kept off the
                          // others' pixels by the early stencil test (a software renderer shades a
                          // 4x4 block for each triangle that touches it: two to nine times the pixels).
                          glBindFramebuffer(GL_FRAMEBUFFER, targets_.terrainMeshFramebuffer());
                          stencilMark(TerrainPass::kPlainStencil);  // (drawMesh() sets each draw's value)
                          terrain_.drawMesh();
                          glBindFramebuffer(GL_FRAMEBUFFER, fb);
                          targets_.bindMeshSurface();
                          glBindVertexArray(emptyVertexArray_.id());
                          for (const bool detailed : {true, false}) {
                              if (detailed && !terrain_.detailDrawn()) continue;
                              stencilTest(detailed ? TerrainPass::kDetailedStencil : TerrainPass::kPlainStencil);
                              terrain_.useMaterialProgram(detailed);
                              drawScissored(lastPrepare_.groundBound, targets_.size());  // the ground lies within it
                          }
                          stencilOff();
                      },
                      [this] { return terrain_.programs(); }});
    // The terrain's shadow marched at one pixel of each block (render/terrain_shadow.frag), on
    // the ground and on the sea's surface in front of it; the surface light and the ocean march
    // only where those around a pixel disagree.
    passes.push_back({{"terrain shadow", {R::GBuffer}, {R::TerrainShadow}},
                      [](const Scene& s) { return s.terrain.shadows; },
                      [this](const Scene&) {
                          const TerrainShadowSamples& samples = targets_.terrainShadowSamples();
                          glBindFramebuffer(GL_FRAMEBUFFER, samples.framebuffer.id());
                          glViewport(0, 0, samples.size.x, samples.size.y);
                          const GBuffer& g = targets_.gbuffer();
                          glBindTextureUnit(binding::UNIT_GBUFFER_NORMAL, g.normal.id());
                          glBindTextureUnit(binding::UNIT_GBUFFER_DEPTH, g.depth.id());
                          ocean_.bindBlock();  // the sea's level and its land bounds (the g channel)
                          targets_.clearTerrainShadowSampleMarches();
                          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_TERRAIN_SHADOW_SAMPLE_MARCHES,
                                           targets_.terrainShadowSampleMarches().id());
                          glBindVertexArray(emptyVertexArray_.id());
                          glUseProgram(terrainShadow_.program().id());
                          // The samples that the pixels which can see the ground read around them.
                          drawScissored(blocksAround(lastPrepare_.groundBound, samples.spacing, samples.size),
                                        samples.size);
                          glViewport(0, 0, targets_.size().x, targets_.size().y);
                          // The sea's march at the samples the pass listed (land within the sun
                          // ray's reach), each on its own.
                          glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT |
                                          GL_FRAMEBUFFER_BARRIER_BIT);
                          glBindImageTexture(binding::IMAGE_TERRAIN_SHADOW_SAMPLES, samples.visibility.id(), 0, GL_FALSE,
                                             0, GL_READ_WRITE, GL_RG32F);
                          glUseProgram(terrainShadowMarches_.get(AtmosphereVariant{}).id());
                          dispatchOverList(targets_.terrainShadowSampleMarches());
                          glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
                      },
                      [this] {
                          return withPrograms({&terrainShadow_.program()}, terrainShadowMarches_.built());
                      }});
    // Reads the terrain shadow's samples only when the preset's terrain.shadows is on (the
    // block's terrainShadows), which is when that pass runs; so does the ocean (their g: the
    // sea's surface).
    passes.push_back({{"surface light", {R::GBuffer, R::TerrainShadow}, {R::SurfaceRadiance}}, always,
                      [this](const Scene& s) {
                          targets_.clearSurface();
                          // The lighting program marks ground above the sea on screen (render/land_on_screen.glsl)
                          // and lists the pixels whose terrain shadow is marched after it.
                          targets_.clearLandOnScreen();
                          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_LAND_ON_SCREEN,
                                           targets_.landOnScreen().id());
                          targets_.clearTerrainShadowList();
                          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_TERRAIN_SHADOW_LIST,
                                           targets_.terrainShadowList().id());
                          glBindFramebuffer(GL_FRAMEBUFFER, targets_.surfaceFramebuffer());
                          const GBuffer& g = targets_.gbuffer();
                          glBindTextureUnit(binding::UNIT_GBUFFER_NORMAL, g.normal.id());
                          glBindTextureUnit(binding::UNIT_GBUFFER_ALBEDO, g.albedo.id());
                          glBindTextureUnit(binding::UNIT_GBUFFER_MATERIAL, g.material.id());
                          glBindTextureUnit(binding::UNIT_GBUFFER_DEPTH, g.depth.id());
                          glBindTextureUnit(binding::UNIT_TERRAIN_SHADOW, targets_.terrainShadowSamples().visibility.id());
                          glBindVertexArray(emptyVertexArray_.id());
                          drawSurfaceLight(s);
                          // The terrain's shadow at the pixels the lighting listed (a shadow's edge),
                          // marched from the ground before the ocean copies what it sees through the water.
                          marchListedTerrainShadow(true);
                      },
                      [this] {
                          std::vector<gl::HotProgram*> p = builtVariants({&surfaceLight_, &terrainShadowListed_});
                          p.push_back(&surfaceMarks_.program());
                          return p;
                      }});
    passes.push_back({{"ocean", {R::GBuffer, R::TerrainShadow, R::SurfaceRadiance}, {R::SurfaceRadiance, R::GBuffer, R::SeaReflection}},
                      [](const Scene& s) { return s.terrain.ocean; },
                      [this](const Scene& s) {
                          targets_.copySeabed();
                          targets_.clearSeaStencil();
                          // The sea's mesh first: which pixels show the sea and where its water is
                          // (the sea surface's G-buffer), marked in the stencil; then the water's
                          // light once per marked pixel, kept off the others by the early stencil
                          // test (a software renderer shades a 4x4 block for each triangle that
                          // touches it: the mesh's fragments are two to three times the sea's pixels).
                          glBindFramebuffer(GL_FRAMEBUFFER, targets_.seaSurfaceFramebuffer());
                          glBindTextureUnit(binding::UNIT_SEABED_DEPTH, targets_.seabedDepth().id());
                          stencilMark(OceanPass::kSeaStencil);
                          glBeginQuery(GL_ANY_SAMPLES_PASSED, oceanDrew_.id());
                          ocean_.drawSurface([this] {
                              glBindVertexArray(emptyVertexArray_.id());
                              drawScissored(lastPrepare_.groundBound, targets_.size());  // the sea lies within it
                          });
                          glEndQuery(GL_ANY_SAMPLES_PASSED);
                          glBindFramebuffer(GL_FRAMEBUFFER, targets_.oceanFramebuffer());
                          glBindTextureUnit(binding::UNIT_SEABED_RADIANCE, targets_.seabedRadiance().id());
                          glBindTextureUnit(binding::UNIT_TERRAIN_SHADOW, targets_.terrainShadowSamples().visibility.id());
                          targets_.bindMeshSurface();
                          targets_.clearTerrainShadowList();
                          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_TERRAIN_SHADOW_LIST,
                                           targets_.terrainShadowList().id());
                          // The light lists the pixels for the terrain reflection's search too, where
                          // ground above the sea is on screen (the surface light marked it).
                          targets_.clearTerrainReflectionList();
                          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_TERRAIN_REFLECTION_LIST,
                                           targets_.terrainReflectionList().id());
                          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_LAND_ON_SCREEN,
                                           targets_.landOnScreen().id());
                          glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
                          ocean_.useLightProgram(variantFor(s), lastPrepare_.underWater);
                          glBindVertexArray(emptyVertexArray_.id());
                          glBeginConditionalRender(oceanDrew_.id(), GL_QUERY_WAIT);
                          // The sea's light writes both at every sea pixel; the terrain reflection reads
                          // only those, the sea reflection pass the blocks around them too (0 past the
                          // sea). Two RGBA32F targets: 4 ms of the pass at orbit, 1280x720; cleared only
                          // where the sea drew (a clear obeys the condition too), since where it drew
                          // none no pass reads them (the sea reflection's own draws wait on the same
                          // query, the terrain reflection's list stays empty). At the inland `ground`
                          // view the pass's own time went from 23-33 to 18-20 ms on llvmpipe; the frame's
                          // did not move measurably (the clear ran beside other work).
                          if (seaReflectionRuns(s)) targets_.clearSeaReflection();
                          drawSeaLight(s);
                          glEndConditionalRender();
                          stencilOff();
                          // The terrain's shadow at the pixels the sea listed (a shadow's edge near land).
                          marchListedTerrainShadow(false);
                      },
                      [this] { return ocean_.builtPrograms(); }});  // (the listed march: the surface light's)
    // The terrain in the sea's reflection: searched at the pixels where the ocean's light found
    // that land may lie within the reflected ray's reach and listed them (ocean/terrain_reflection.glsl),
    // a tenth of the sea from orbit, and only where some ground above the sea is on screen;
    // where none was listed the indirect dispatch runs no group.
    passes.push_back({{"terrain reflection", {R::SurfaceRadiance, R::SeaReflection}, {R::SurfaceRadiance, R::SeaReflection}},
                      [this](const Scene& s) { return s.terrain.ocean && !lastPrepare_.underWater; },
                      [this](const Scene& s) {
                          glBindTextureUnit(binding::UNIT_SEA_SKY_REFLECTION, targets_.seaSkyReflection().id());
                          glBindTextureUnit(binding::UNIT_SEABED_DEPTH, targets_.seabedDepth().id());
                          glBindTextureUnit(binding::UNIT_SEABED_RADIANCE, targets_.seabedRadiance().id());
                          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_TERRAIN_REFLECTION_LIST,
                                           targets_.terrainReflectionList().id());
                          glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
                          glBindImageTexture(binding::IMAGE_SURFACE_RADIANCE, targets_.surfaceRadiance().id(), 0,
                                             GL_FALSE, 0, GL_READ_WRITE, GL_RGBA16F);
                          glBindImageTexture(binding::IMAGE_SEA_REFLECTION, targets_.seaReflection().id(), 0, GL_FALSE,
                                             0, GL_READ_WRITE, GL_RGBA32F);
                          glUseProgram(terrainReflection_.get(variantFor(s)).id());
                          dispatchOverList(targets_.terrainReflectionList());
                      },
                      [this] { return builtVariants({&terrainReflection_}); }});
    // The clouds in the sea's reflection: marched at one pixel of each block along the rays the
    // ocean left, then spread and added to the surface radiance (ocean/sea_reflection.frag).
    // Only where the ocean's per-pixel program ran with clouds in the sky: from high up the
    // flat mirror has them from the grid, and from below the sea reflects nothing of them.
    passes.push_back({{"sea reflection", {R::SurfaceRadiance, R::SeaReflection}, {R::SurfaceRadiance}},
                      [this](const Scene& s) { return seaReflectionRuns(s); },
                      [this](const Scene& s) {
                          // Nothing to do where the ocean drew no pixel (an inland view): its
                          // draws skipped on the GPU, and the list left empty dispatches no group.
                          glBeginConditionalRender(oceanDrew_.id(), GL_QUERY_WAIT);
                          const SeaReflectionSamples& samples = targets_.seaReflectionSamples();
                          glBindTextureUnit(binding::UNIT_SEA_REFLECTION, targets_.seaReflection().id());
                          glBindTextureUnit(binding::UNIT_SURFACE_DISTANCE, targets_.surfaceDistance().id());
                          glBindVertexArray(emptyVertexArray_.id());
                          if (seaReflectionSamples_) {
                              glBindFramebuffer(GL_FRAMEBUFFER, samples.framebuffer.id());
                              glViewport(0, 0, samples.size.x, samples.size.y);
                              glUseProgram(seaReflection_.get(variantFor(s)).id());
                              glDrawArrays(GL_TRIANGLES, 0, 3);
                              glViewport(0, 0, targets_.size().x, targets_.size().y);
                          }
                          glBindTextureUnit(binding::UNIT_SEA_REFLECTION_SAMPLES, samples.change.id());
                          glBindFramebuffer(GL_FRAMEBUFFER, targets_.surfaceRadianceFramebuffer());
                          targets_.clearSeaReflectionList();
                          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_SEA_REFLECTION_LIST,
                                           targets_.seaReflectionList().id());
                          glEnablei(GL_BLEND, 0);
                          glBlendFunci(0, GL_ONE, GL_ONE);
                          // Mode SEA_REFLECTION_COMPOSE, or SEA_REFLECTION_LIST_ALL (every pixel listed).
                          glUseProgram(seaReflection_.get(variantFor(s), seaReflectionSamples_ ? 1 : 2).id());
                          glDrawArrays(GL_TRIANGLES, 0, 3);
                          glDisablei(GL_BLEND, 0);
                          glEndConditionalRender();
                          // The pixels the compose listed, each marched on its own and added in place.
                          glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT |
                                          GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
                          glBindImageTexture(binding::IMAGE_SURFACE_RADIANCE, targets_.surfaceRadiance().id(), 0,
                                             GL_FALSE, 0, GL_READ_WRITE, GL_RGBA16F);
                          glUseProgram(seaReflectionListed_.get(variantFor(s)).id());
                          dispatchOverList(targets_.seaReflectionList());
                      },
                      [this] { return builtVariants({&seaReflection_, &seaReflectionListed_}); }});
    auto fullRate = [this](const Scene&) { return !lastPrepare_.reducedRate; };
    auto reducedRate = [this](const Scene&) { return lastPrepare_.reducedRate; };
    passes.push_back({{"sky", {R::SurfaceRadiance}, {R::HdrRadiance}}, fullRate,
                      [this](const Scene& s) {
                          glBindFramebuffer(GL_FRAMEBUFFER, targets_.hdrFramebuffer());
                          glBindTextureUnit(binding::UNIT_SURFACE_RADIANCE, targets_.surfaceRadiance().id());
                          glBindTextureUnit(binding::UNIT_SURFACE_DISTANCE, targets_.surfaceDistance().id());
                          glBindVertexArray(emptyVertexArray_.id());
                          const int underWater = lastPrepare_.underWater ? 1 : 0;  // sky_'s mode UNDER_WATER
                          drawSpaceAround(lastPrepare_.skyBound);
                          drawSkyBound(sky_, s, underWater);
                      },
                      [this] { return withPrograms(sky_.built(), {&skySpace_.program()}); }});
    passes.push_back({{"sky march", {R::SurfaceRadiance}, {R::SparseSky}}, reducedRate,
                      [this](const Scene& s) {
                          const SparseSky& sparse = targets_.sparseSky();
                          glBindFramebuffer(GL_FRAMEBUFFER, sparse.framebuffer.id());
                          glViewport(0, 0, sparse.size.x, sparse.size.y);
                          const FrameHistory& history = targets_.history();
                          glBindTextureUnit(binding::UNIT_SURFACE_RADIANCE, targets_.surfaceRadiance().id());
                          glBindTextureUnit(binding::UNIT_SURFACE_DISTANCE, targets_.surfaceDistance().id());
                          glBindTextureUnit(binding::UNIT_HISTORY_SKY_MEDIUM, history.skyMedium.id());
                          glBindTextureUnit(binding::UNIT_HISTORY_SURFACE_DISTANCE, history.surfaceDistance.id());
                          glBindVertexArray(emptyVertexArray_.id());
                          drawSkyMarch(s);
                          glViewport(0, 0, targets_.size().x, targets_.size().y);
                      },
                      [this] { return withPrograms(skySparse_.built(), {&skySparseNoCloud_.program()}); }});
    passes.push_back({{"sky temporal", {R::SurfaceRadiance, R::SparseSky}, {R::HdrRadiance, R::SkyRefine}}, reducedRate,
                      [this](const Scene& s) {
                          glBindFramebuffer(GL_FRAMEBUFFER, targets_.hdrFramebuffer());
                          targets_.clearSkyRefineList();
                          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_SKY_REFINE,
                                           targets_.skyRefineList().id());
                          const SparseSky& sparse = targets_.sparseSky();
                          const FrameHistory& history = targets_.history();
                          glBindTextureUnit(binding::UNIT_SURFACE_RADIANCE, targets_.surfaceRadiance().id());
                          glBindTextureUnit(binding::UNIT_SURFACE_DISTANCE, targets_.surfaceDistance().id());
                          glBindTextureUnit(binding::UNIT_SPARSE_INSCATTER, sparse.inscatter.id());
                          glBindTextureUnit(binding::UNIT_SPARSE_TRANSMITTANCE, sparse.transmittance.id());
                          glBindTextureUnit(binding::UNIT_SPARSE_DISTANCE_ERROR, sparse.distanceError.id());
                          glBindTextureUnit(binding::UNIT_HISTORY_SKY_MEDIUM, history.skyMedium.id());
                          glBindTextureUnit(binding::UNIT_HISTORY_SURFACE_DISTANCE, history.surfaceDistance.id());
                          glBindVertexArray(emptyVertexArray_.id());
                          drawSpaceAround(lastPrepare_.skyBound);
                          if (lastPrepare_.clockOnlyOffLayer) {
                              drawSkyTemporalSplit(s);
                              return;
                          }
                          // Modes: 1 STILL_FRAME, 2 STILL_FRAME_UNJITTERED (the jitter stood too).
                          const int still = !stillProgram() ? 0 : lastPrepare_.jitterStood ? 2 : 1;
                          drawSkyBound(skyTemporal_, s, still);
                      },
                      [this] {
                          return withPrograms(skyTemporal_.built(), {&skySpace_.program(), &skyNoCloud_.program()});
                      }});
    passes.push_back({{"sky refine", {R::SurfaceRadiance, R::SparseSky, R::SkyRefine}, {R::HdrRadiance}}, reducedRate,
                      [this](const Scene& s) {
                          glBindTextureUnit(binding::UNIT_SURFACE_RADIANCE, targets_.surfaceRadiance().id());
                          glBindTextureUnit(binding::UNIT_SURFACE_DISTANCE, targets_.surfaceDistance().id());
                          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_SKY_REFINE,
                                           targets_.skyRefineList().id());
                          glBindImageTexture(binding::IMAGE_HDR_RADIANCE, targets_.hdr().id(), 0, GL_FALSE, 0,
                                             GL_WRITE_ONLY, GL_RGBA16F);
                          glBindImageTexture(binding::IMAGE_SKY_MEDIUM, targets_.skyMedium().id(), 0, GL_FALSE, 0,
                                             GL_WRITE_ONLY, GL_RGBA32UI);
                          // A still frame's program: the spatial estimate, from the samples, at the
                          // pixels whose surface changed (STILL_FRAME, render/sky_refine.comp).
                          const SparseSky& sparse = targets_.sparseSky();
                          glBindTextureUnit(binding::UNIT_SPARSE_INSCATTER, sparse.inscatter.id());
                          glBindTextureUnit(binding::UNIT_SPARSE_TRANSMITTANCE, sparse.transmittance.id());
                          glBindTextureUnit(binding::UNIT_SPARSE_DISTANCE_ERROR, sparse.distanceError.id());
                          glUseProgram(skyRefine_.get(skyVariantFor(s), stillProgram() ? 1 : 0).id());
                          // The list and its group counts, written by the reconstruction's fragments.
                          glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
                          // One invocation per listed pixel: a software renderer pays for the pixels
                          // it marches, not for each marked pixel's 4x4 block (a fragment pass over
                          // the marks did), and a still frame without the anti-aliasing's jitter,
                          // which lists none, dispatches nothing.
                          glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, targets_.skyRefineList().id());
                          glDispatchComputeIndirect(0);
                          glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
                          // The passes after read hdr and the history copies T, S.
                          glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                                          GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                                          GL_PIXEL_BUFFER_BARRIER_BIT);
                      },
                      [this] { return skyRefine_.built(); }});
    passes.push_back({{"antialias", {R::HdrRadiance, R::SurfaceRadiance}, {R::HdrRadiance}},
                      [this](const Scene&) { return temporalAntialiasing_; },
                      [this](const Scene&) {
                          glBindFramebuffer(GL_FRAMEBUFFER, targets_.antialiasFramebuffer());
                          glBindTextureUnit(binding::UNIT_HDR_RADIANCE, targets_.hdr().id());
                          glBindTextureUnit(binding::UNIT_SURFACE_DISTANCE, targets_.surfaceDistance().id());
                          glBindTextureUnit(binding::UNIT_HISTORY_RADIANCE, targets_.history().radiance.id());
                          glBindVertexArray(emptyVertexArray_.id());
                          antialias_.draw();
                          targets_.keepAntialiased();
                      },
                      [this] { return std::vector<gl::HotProgram*>{&antialias_.program()}; }});
    passes.push_back({{"tonemap", {R::HdrRadiance}, {R::LdrImage}}, always,
                      [this](const Scene&) {
                          glBindFramebuffer(GL_FRAMEBUFFER, targets_.ldrFramebuffer());
                          glBindTextureUnit(binding::UNIT_HDR_RADIANCE, targets_.hdr().id());
                          glBindVertexArray(emptyVertexArray_.id());
                          tonemap_.draw();
                      },
                      [this] { return std::vector<gl::HotProgram*>{&tonemap_.program()}; }});
    passes.push_back({{"ui", {R::LdrImage}, {R::Window}}, [this](const Scene&) { return bool(present_); },
                      [this](const Scene&) {
                          glBindFramebuffer(GL_FRAMEBUFFER, 0);
                          present_();
                      },
                      [] { return std::vector<gl::HotProgram*>{}; }});
    return passes;
}

std::vector<PassDeclaration> Renderer::passDeclarations() const {
    std::vector<PassDeclaration> d;
    for (const Pass& p : passes_) d.push_back(p.declaration);
    return d;
}

bool Renderer::historyUsable(const Scene& scene, const Camera& camera, bool resized) const {
    if (resized || !previous_) return false;
    const Camera& before = previous_->camera;
    const double altitude = std::max(camera.altitude(scene.planetRadiusM()), 0.0);
    const double moved = glm::length(camera.position - before.position);
    if (moved > std::max(kJumpMinimumM, kJumpFractionOfAltitude * altitude)) return false;
    if (glm::dot(camera.forward(), before.forward()) < kJumpTurnCos) return false;
    if (camera.fovY_rad != before.fovY_rad) return false;
    // Across the sea surface the history holds the water body, not the sky's T and S.
    if ((cameraDepthBelowSeaM(scene, before) > 0.0) != (cameraDepthBelowSeaM(scene, camera) > 0.0)) return false;
    if (glm::dot(scene.sunDirection(), previous_->sunDirection) < kSunJumpCos) return false;
    return sceneKey_ == previousSceneKey_;
}

Renderer::~Renderer() { continents_->releaseTexture(); }

// The surface light's draws (render/surface_light.frag), its programs kept off each other's pixels by
// the early stencil test: the sea floor's dark depths and the pixels with no ground marked first
// (SEA_FLOOR_DARK), then the ground whose way to the sun surely meets no cloud (SUN_CLEAR_OF_CLOUDS),
// then the general program on the rest.
void Renderer::drawSurfaceLight(const Scene& scene) {
    // (The 4D table's program: it reads no scattering table, only the clouds.)
    AtmosphereVariant variant = variantFor(scene);
    variant.elekTable = false;
    // The sea floor's dark depths and the pixels with no ground (1), and the ground whose way to the sun
    // surely meets no cloud (kSunClearOfClouds), marked in the stencil first, each fragment with its own
    // value (render/surface_marks.frag): the lighting programs run on the rest, the dark depths' program
    // (SEA_FLOOR_DARK: their distance, no light) on the first, the program without the clouds' shadow
    // (SUN_CLEAR_OF_CLOUDS) on the second.
    const bool darkApart = seaFloorDarkStencil_ && scene.terrain.ocean;
    const bool clearApart = sunClearStencil_ && !variant.cloudsOff && lastPrepare_.clearSkyDepth < 1.0f;
    if (darkApart || clearApart) {
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the stencil alone
        glUseProgram(surfaceMarks_.program().id());
        glUniform1f(0, clearApart ? lastPrepare_.clearSkyDepth : 1.0f);  // (1: no pixel)
        glUniform1i(1, darkApart ? 1 : 0);
        if (stencilExport_) {
            stencilMark(0);  // (the value is the fragment's)
            drawScissored(lastPrepare_.groundBound, targets_.size());
        } else {  // a pass per mark, its value the reference
            for (const GLint mark : {GLint{1}, GLint{kSunClearOfClouds}}) {
                if (mark == 1 ? !darkApart : !clearApart) continue;
                stencilMark(mark);
                glUniform1i(2, mark);
                drawScissored(lastPrepare_.groundBound, targets_.size());
            }
        }
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    // The dark depths' own program (their distance, no light) only where the sea is not drawn over them
    // from above: there the ocean writes both at every such pixel (the sea's distance, and the light over
    // a floor that sends none back, which the cleared target holds too). From orbit most of the marked
    // pixels have no ground at all (the terrain left the dark depths out), where the program ran its
    // whole body to discard: 9-10 ms at 1280x720.
    if (darkApart && lastPrepare_.underWater) {
        stencilTest(1);
        glUseProgram(surfaceLight_.get(variant, 1).id());
        drawScissored(lastPrepare_.groundBound, targets_.size());
    }
    if (clearApart) {
        stencilTest(kSunClearOfClouds);
        glUseProgram(surfaceLight_.get(variant, 2).id());
        drawScissored(lastPrepare_.groundBound, targets_.size());
    }
    if (darkApart || clearApart) stencilTest(0);
    glUseProgram(surfaceLight_.get(variant).id());
    drawScissored(lastPrepare_.groundBound, targets_.size());  // it discards elsewhere
    if (darkApart || clearApart) stencilOff();
}

// The reduced-rate march (render/sky_sparse.frag) at the blocks the reconstruction reads around the pixels
// it rebuilds. Where the frame has clouds, the blocks whose ray meets no cloud (render/sky_no_cloud.frag,
// in the lattice's stencil) are marched by the program without the clouds' code (CLOUDS_OFF), which
// computes what the march does for such a ray, to the bit (one lookup of the air), and the rest by the
// general one: a software renderer runs the clouds' code for every pixel, masked (the `ground` view, no
// cloud in sight: 36 -> 5 ms without it, 1280x720 on llvmpipe).
void Renderer::drawSkyMarch(const Scene& scene) {
    const SparseSky& sparse = targets_.sparseSky();
    const ScreenRect blocks = blocksAround(lastPrepare_.skyBound, kSparseBlock, sparse.size);
    // A still frame's program leaves out the samples' history errors, which only the general
    // reconstruction reads (render/sky_sparse.frag).
    const int mode = stillProgram() ? 1 : 0;
    const AtmosphereVariant variant = skyVariantFor(scene);
    if (!skyMarchSplit_ || variant.cloudsOff) {
        glUseProgram(skySparse_.get(variant, mode).id());
        drawScissored(blocks, sparse.size);
        return;
    }
    constexpr GLuint kNoCloud = 1;
    const GLint clear = 0;
    glClearNamedFramebufferiv(sparse.framebuffer.id(), GL_STENCIL, 0, &clear);
    stencilMark(kNoCloud);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(skySparseNoCloud_.program().id());
    glUniform1f(0, lastPrepare_.clearAxisKm);
    drawScissored(blocks, sparse.size);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    AtmosphereVariant noCloud = variant;
    noCloud.cloudsOff = true;
    noCloud.cloudFarField = false;
    stencilTest(kNoCloud);
    glUseProgram(skySparse_.get(noCloud, mode).id());
    drawScissored(blocks, sparse.size);
    stencilTest(kNoCloud, 0xFF, false);
    glUseProgram(skySparse_.get(variant, mode).id());
    drawScissored(blocks, sparse.size);
    stencilOff();
}

// The water's light (ocean/sea_light.frag) at the pixels the sea's mesh marked, the open sea's
// (OceanPass::kOpenSeaStencil: no land within reach of its reflected or sun ray, ocean/ocean.frag)
// by the OPEN_SEA build, the rest by the whole program, each kept off the other's pixels by the early
// stencil test: a software renderer ran the terrain reflection's and shadow's code at every sea pixel,
// masked (`orbit`, 1280x720 on llvmpipe: the light 31 -> 23 ms, the far field's draw that marks the open
// sea 22-25 -> 26-27). Under the sea, where the light only passes the sky on, or where the surface marks
// no open sea (the mesh, nearer than the far field), the whole program everywhere.
void Renderer::drawSeaLight(const Scene& scene) {
    const bool split = openSeaSplit_ && ocean_.marksOpenSea() && !lastPrepare_.underWater;
    // (The whole program is bound: OceanPass::useLightProgram.)
    stencilTest(OceanPass::kSeaStencil, split ? OceanPass::kOpenSeaStencilBits : OceanPass::kSeaStencilBits);
    drawScissored(lastPrepare_.groundBound, targets_.size());  // the sea lies within it
    if (!split) return;
    stencilTest(OceanPass::kOpenSeaStencil, OceanPass::kOpenSeaStencilBits);
    ocean_.useOpenSeaLightProgram(variantFor(scene));
    drawScissored(lastPrepare_.groundBound, targets_.size());
}

// A frame where only the clock ran, the camera under or above the cloud layer: the pixels whose ray
// meets no cloud, marked in the stencil's top bit (render/sky_no_cloud.frag), are rebuilt by the
// still program, the rest by the general one, each kept off the other's pixels by the early stencil
// test (a software renderer runs both sides of a branch in every pixel; the `ground` view with the
// clock on: the general program over every pixel cost 126 ms, docs/PERFORMANCE.md, twenty-third).
// The terrain's and the sea's stencil values stay in the lower bits.
void Renderer::drawSkyTemporalSplit(const Scene& scene) {
    constexpr GLuint kNoCloud = 0x80;
    glBindFramebuffer(GL_FRAMEBUFFER, targets_.hdrStencilFramebuffer());
    stencilMark(kNoCloud, kNoCloud);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(skyNoCloud_.program().id());
    glUniform1f(0, lastPrepare_.clearAxisKm);
    drawScissored(lastPrepare_.skyBound, targets_.size());
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // Modes: 1 STILL_FRAME, 2 STILL_FRAME_UNJITTERED (the jitter stood too); 0 the general program.
    stencilTest(kNoCloud, kNoCloud);
    drawSkyBound(skyTemporal_, scene, lastPrepare_.jitterStood ? 2 : 1);
    stencilTest(kNoCloud, kNoCloud, false);
    drawSkyBound(skyTemporal_, scene, 0);
    stencilOff();
    glBindFramebuffer(GL_FRAMEBUFFER, targets_.hdrFramebuffer());
}

// How far from the vertical through the camera (its axis) the cloud layer surely holds no cloud, km
// (0: nowhere): the clear sky map's angle a at the camera's direction (the weather's coverage is 0
// within it, CloudResources::clearAngleAt), as the distance Rc = bottomRadius sin(a) from the axis
// within which a point of the layer (at least bottomRadius from the centre) is less than a from it;
// 10 m less, for the float the passes form their points in.
double Renderer::clearAxisKm(const Camera& camera) const {
    const double angle = clouds_.clearAngleAt(glm::normalize(camera.position));
    return angle > 0.0 ? clouds_.block().bottomRadius * std::sin(angle) - 0.01 : 0.0;
}

// The reversed-Z depth nearer than which every ground point's way to the sun surely meets no cloud
// (render/surface_marks.frag), or 1 (none): the clear sky around the camera's direction (the
// clear sky map's angle, within which the weather's coverage is 0) reaches Rc from the camera's axis
// in the layer. A ground point within D of the camera is within D of that axis; its way to the sun,
// from an altitude of at least the lowest sea floor up to the layer's top, is at most
// t = H / sin(e) long (the sun's elevation e there at least the camera's less the point's angle from
// it, D / R; the sphere's curvature only shortens the climb), and leaves the axis by at most t cos(e).
// So D + t cos(e) < Rc, solved by halving; and a view distance D is at least view depth D cos(the
// view's half diagonal).
float Renderer::clearSkyDepth(const Scene& scene, const Camera& camera, glm::ivec2 size, double clearKm) const {
    const double radiusKm = scene.planetRadiusM() / 1000.0;
    const glm::dvec3 up = glm::normalize(camera.position);
    const double sunElevation = std::asin(std::clamp(glm::dot(scene.sunDirection(), up), -1.0, 1.0));
    const double climbKm = clouds_.block().topRadius - (radiusKm - scene.terrain.ocean_depth_m / 1000.0);
    const auto fits = [&](double d) {
        const double e = sunElevation - d / radiusKm;
        if (e <= 0.01) return false;
        return d + climbKm / std::sin(e) * std::cos(e) < clearKm;
    };
    if (clearKm <= 0.0 || !fits(0.0)) return 1.0f;
    double lo = 0.0, hi = clearKm;
    for (int i = 0; i < 40; ++i) (fits(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
    const double aspect = double(size.x) / double(std::max(size.y, 1));
    const double t = std::tan(0.5 * camera.fovY_rad);
    const double cosHalfDiagonal = 1.0 / std::sqrt(1.0 + t * t * (1.0 + aspect * aspect));
    const double viewZM = lo * 1000.0 * cosHalfDiagonal;
    if (viewZM <= camera.near_m) return 1.0f;
    return static_cast<float>(depthFromViewZ(-viewZM, camera.near_m));
}

// A sky pass's program over the sky's bound, in the builds for what its pixels see (render/sky_air.glsl):
// with the sun's disc on the disc's rectangle, without it on the bands around, and without space's
// code where the camera is in the air; each build gives what the whole program gives at its pixels
// (a software renderer runs a branch's both sides: the disc and the space's side were half of the
// reconstruction's still program at `ground`).
void Renderer::drawSkyBound(AtmosphereProgram& program, const Scene& scene, int mode) {
    AtmosphereVariant variant = skyVariantFor(scene);
    variant.cameraInAir = lastPrepare_.cameraInAir;
    const glm::ivec2 size = targets_.size();
    const ScreenRect disc = intersection(lastPrepare_.sunDiscBound, lastPrepare_.skyBound);
    if (!disc.empty()) {
        glUseProgram(program.get(variant, mode).id());
        drawScissored(disc, size);
    }
    std::array<ScreenRect, 4> offDisc = bandsAround(disc, size);
    for (ScreenRect& band : offDisc) band = intersection(band, lastPrepare_.skyBound);
    if (std::all_of(offDisc.begin(), offDisc.end(), [](const ScreenRect& r) { return r.empty(); })) return;
    variant.noSunDisc = true;
    glUseProgram(program.get(variant, mode).id());
    for (const ScreenRect& band : offDisc) drawScissored(band, size);
}

void Renderer::drawSpaceAround(const ScreenRect& skyBound) const {
    if (skyBound.coversScreen(targets_.size())) return;
    glUseProgram(skySpace_.program().id());
    for (const ScreenRect& band : bandsAround(skyBound, targets_.size())) drawScissored(band, targets_.size());
}

void Renderer::prepare(const Scene& scene, const Camera& camera, glm::ivec2 size) {
    PrepareReport report;
    const bool resized = targets_.resize(size);
    if (atmosphere_.rebuilding()) {  // a chunk of a rebuild: its own profiler line
        gl::DebugGroup group("atmosphere tables");
        auto timing = profiler_.pass("atmosphere tables");
        atmosphere_.update(scene);
        report.atmosphereRebuildStep = true;
    } else {
        const bool first = !atmosphere_.ready();
        atmosphere_.update(scene);  // usually nothing to do; starts a rebuild when the atmosphere changed
        report.atmosphereTablesMade = first;
    }
    report.atmosphereProgramsRebuilt = matchAtmosphereTables();
    gl::DebugGroup group("prepare");
    auto timing = profiler_.pass("prepare");
    continents_->update(scene.terrain);  // nothing when the session's ground already brought it up to date
    report.continentsUpdated = continents_->textureStale();
    glBindTextureUnit(binding::UNIT_CONTINENTS, continents_->texture().id());
    glBindTextureUnit(binding::UNIT_CONTINENT_MAX, continents_->maxTexture().id());
    // Filter across cube faces as the CPU's sampleContinents does.
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

    sceneKey_ = historyKey(scene);
    report.historyValid = historyUsable(scene, camera, resized);
    const bool inAir = cameraDepthBelowSeaM(scene, camera) <= 0.0;
    report.underWater = !inAir;
    report.reducedRate = scene.render.temporal && scene.clouds.enabled && inAir &&
                         (report.historyValid || !fullRateOnReset_);
    frameJitterPx_ = temporalAntialiasing_ ? glm::dvec2(subPixelJitter(frameIndex_)) : jitterPx_;
    const FrameUniforms uniforms = makeFrameUniforms(scene, camera, size, frameIndex_,
                                                     report.historyValid ? previous_ : std::nullopt, frameJitterPx_);
    // Nothing moved at the pixels' scale (the anti-aliasing's sub-pixel jitter may have: each
    // pixel's history is then its own texel all the same, render/sky_history.glsl).
    report.stillFrame = report.historyValid && uniforms.stillSincePrevious > 0.5f;  // the view stood too
    report.jitterStood = report.historyValid && previous_ && previous_->jitterPx == frameJitterPx_;
    const double altitudeKm = camera.altitude(scene.planetRadiusM()) / 1000.0;
    report.clockOnlyOffLayer = report.reducedRate && report.historyValid && stillFrameProgram_ && !report.stillFrame &&
                               uniforms.viewStillSincePrevious > 0.5f &&
                               (altitudeKm < scene.clouds.bottom_altitude_km || altitudeKm > scene.clouds.top_altitude_km);
    // The air's sphere (the preset's top: the model's may end lower, never higher), and the
    // ground's highest (the terrain's highest above the sea, the waves' crests well under the
    // kilometre added).
    const glm::dmat4 clipFromView = jitteredClipFromView(camera, size, frameJitterPx_);
    const glm::dmat3 viewFromWorld = glm::transpose(camera.worldFromView());
    const auto bound = [&](double radius) {
        return screenBounds_ ? sphereScreenBound(clipFromView, viewFromWorld, -camera.position, radius, size)
                             : ScreenRect{{0, 0}, size};
    };
    const double highestGroundM = scene.planetRadiusM() + scene.ocean.sea_level_m + std::max(scene.terrain.max_height_m, 0.0) +
                                  1000.0;
    report.skyBound = bound(scene.atmosphere.top_radius_km * 1000.0);
    // What the sky passes' pixels see, by the parameters the programs read (those of the tables in use).
    const atmosphere::AtmosphereUniforms& air = atmosphere_.uniforms();
    report.sunDiscBound = screenBounds_ ? sunDiscScreenBound(clipFromView, viewFromWorld, scene.sunDirection(),
                                                             air.sunAngularRadius, size)
                                        : ScreenRect{{0, 0}, size};
    report.cameraInAir = screenBounds_ && glm::length(camera.position) / 1000.0 < double(air.topRadius) - 1.0;
    report.groundBound = bound(highestGroundM);
    glNamedBufferSubData(frameUniforms_.id(), 0, sizeof uniforms, &uniforms);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_FRAME, frameUniforms_.id());
    atmosphere_.bind();
    report.cloudsUpdated = clouds_.update(scene, camera, size.y);
    clouds_.bind();
    report.cloudsOff = cloudsOffPrograms_ && clouds_.block().enabled == 0;
    const double clearKm = clearAxisKm(camera);  // (one clear sky map lookup)
    report.clearSkyDepth = clearSkyDepth(scene, camera, size, clearKm);
    report.clearAxisKm = static_cast<float>(std::max(clearKm, 0.0));
    report.cloudFarField = !report.cloudsOff && cloudFarFieldPrograms_ &&
                           clouds::seenInFarFieldOnly(clouds_.block(), glm::length(camera.position) / 1000.0,
                                                      highestGroundM / 1000.0);
    terrain_.prepare(scene, camera, *continents_->map(), camera.fovY_rad / size.y, double(size.x) / size.y);
    if (scene.terrain.ocean) ocean_.prepare(scene, camera, camera.fovY_rad / size.y, double(size.x) / size.y, continents_->map());
    // Where the sea is drawn over the ground from above, the ground under its dark depths is not
    // drawn (terrain/terrain.tesc): the light through that much water is none, and every pass
    // after the ocean sees the sea there (tests: the same frame).
    if (scene.terrain.ocean && !report.underWater && darkFloorCulling_ && ocean_.darkFloorCulling())
        terrain_.setDarkFloorCulling(ocean_.patchDarkContinent(), ocean_.continentLipschitz());
    lastPrepare_ = report;
}

void Renderer::render(const Scene& scene, const Camera& camera, glm::ivec2 size,
                      const std::function<void()>& present) {
    if (size.x <= 0 || size.y <= 0) return;
    present_ = present;
    profiler_.beginFrame();
    prepare(scene, camera, size);

    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // reversed-Z needs [0, 1] clip depth
    glViewport(0, 0, size.x, size.y);
    glDisable(GL_BLEND);
#ifndef NDEBUG
    std::set<FrameResource> written;
#endif
    for (const Pass& pass : passes_) {
        if (!pass.enabled(scene)) continue;
#ifndef NDEBUG  // the declared order, checked against what ran this frame
        for (FrameResource r : pass.declaration.reads)
            if (!written.count(r))
                throw std::logic_error("pass '" + pass.declaration.name + "' reads " + frameResourceName(r) +
                                       " that no pass wrote this frame");
        written.insert(pass.declaration.writes.begin(), pass.declaration.writes.end());
#endif
        gl::DebugGroup group(pass.declaration.name);
        auto timing = profiler_.pass(pass.declaration.name);
        pass.draw(scene);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    targets_.keepHistory();
    previous_ = PreviousFrame{camera, size, scene.time_s, scene.sunDirection(), frameJitterPx_};
    previousSceneKey_ = sceneKey_;
    ++frameIndex_;
    present_ = nullptr;
    profiler_.endFrame();
}

void Renderer::tonemapRadiance(const ImageRGBAF& radiance) {
    const glm::ivec2 size = targets_.size();
    if (radiance.width != size.x || radiance.height != size.y ||
        radiance.pixels.size() != static_cast<std::size_t>(size.x) * size.y * 4)
        throw std::invalid_argument("tonemapRadiance: the image is not the size of the last frame");
    // Rows bottom-up, as GL keeps them (readTextureRGBAF flipped them to row 0 at the top).
    std::vector<float> rows(radiance.pixels.size());
    const std::size_t row = static_cast<std::size_t>(size.x) * 4;
    for (int y = 0; y < size.y; ++y)
        std::copy_n(radiance.pixels.begin() + static_cast<std::ptrdiff_t>(row * (size.y - 1 - y)), row,
                    rows.begin() + static_cast<std::ptrdiff_t>(row * y));
    glTextureSubImage2D(targets_.hdr().id(), 0, 0, 0, size.x, size.y, GL_RGBA, GL_FLOAT, rows.data());
    // The frame block of the last frame is still bound (its exposure); the tonemap pass as in render().
    gl::DebugGroup group("tonemap (accumulated)");
    glViewport(0, 0, size.x, size.y);
    glBindFramebuffer(GL_FRAMEBUFFER, targets_.ldrFramebuffer());
    glBindTextureUnit(binding::UNIT_HDR_RADIANCE, targets_.hdr().id());
    glBindVertexArray(emptyVertexArray_.id());
    tonemap_.draw();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

gl::ShaderSources Renderer::surfaceMarksSources(const atmosphere::TableSizes& sizes) const {
    return withAtmosphere(sources_.withDefine("STENCIL_EXPORT", stencilExport_), sizes);
}

void Renderer::setStencilExport(bool on) {
    stencilExport_ = on && epoxy_has_gl_extension("GL_ARB_shader_stencil_export");
    surfaceMarks_.program().setSources(surfaceMarksSources(programTables_));
    surfaceMarks_.program().reloadIfChanged(true);
    if (!surfaceMarks_.program().error().empty()) throw std::runtime_error(surfaceMarks_.program().error());
}

bool Renderer::stillProgram() const { return lastPrepare_.stillFrame && stillFrameProgram_; }

bool Renderer::seaReflectionRuns(const Scene& s) const {
    return s.terrain.ocean && s.clouds.enabled && !ocean_.flatMirror() && !lastPrepare_.underWater;
}

AtmosphereVariant Renderer::variantFor(const Scene& scene) const {
    return AtmosphereVariant{scene.atmosphere.elek_3d_table, false, lastPrepare_.cloudFarField, lastPrepare_.cloudsOff};
}

AtmosphereVariant Renderer::skyVariantFor(const Scene& scene) const {
    AtmosphereVariant v = variantFor(scene);
    v.lightShafts = lightShafts(scene);
    return v;
}

bool Renderer::matchAtmosphereTables() {
    const atmosphere::TableSizes& sizes = atmosphere_.sizes();
    if (sizes == programTables_) return false;
    // The table sizes are #defines in every program that reads the tables: the same forced
    // rebuild as a hot reload (a program that fails keeps the last good one and shows its error).
    const auto started = std::chrono::steady_clock::now();
    programTables_ = sizes;
    terrainShadow_.program().setSources(withAtmosphere(sources_, sizes));
    surfaceMarks_.program().setSources(surfaceMarksSources(sizes));
    std::vector<gl::HotProgram*> rebuilt{&terrainShadow_.program(), &surfaceMarks_.program()};
    std::vector<AtmosphereProgram*> withTables = ocean_.atmospherePrograms();
    for (AtmosphereProgram* p : {&surfaceLight_, &terrainShadowMarches_, &terrainShadowListed_, &seaReflection_,
                                 &seaReflectionListed_, &terrainReflection_, &sky_, &skySparse_, &skyTemporal_, &skyRefine_})
        withTables.push_back(p);
    for (AtmosphereProgram* p : withTables) {
        p->setTableSizes(sizes);
        const std::vector<gl::HotProgram*> built = p->built();
        rebuilt.insert(rebuilt.end(), built.begin(), built.end());
    }
    for (gl::HotProgram* p : rebuilt) p->reloadIfChanged(true);
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.2f", std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    logInfo("atmosphere: " + std::to_string(rebuilt.size()) + " programs rebuilt for the new table sizes in " + seconds + " s");
    return true;
}

std::vector<gl::HotProgram*> Renderer::programs() {
    std::vector<gl::HotProgram*> all;
    for (const Pass& p : passes_) {
        const std::vector<gl::HotProgram*> mine = p.programs();
        all.insert(all.end(), mine.begin(), mine.end());
    }
    return all;
}

bool Renderer::reloadShaders(bool force) {
    bool any = false;
    for (gl::HotProgram* p : programs()) any = p->reloadIfChanged(force) || any;
    return any;
}

std::vector<std::string> Renderer::shaderErrors() {
    std::vector<std::string> errors;
    for (gl::HotProgram* p : programs())
        if (!p->error().empty()) errors.push_back(p->error());
    return errors;
}

}  // namespace planet
