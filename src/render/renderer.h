// The frame: prepare, then a short list of declared passes (STYLE habits 6 and 15).
//
// prepare   brings every baked resource up to date before anything draws: the atmosphere
//           tables (loaded or made on first use, or the explorer's starter tables; while
//           tuning or refining the starter, chunks of a rebuild each frame, profiled as
//           "atmosphere tables"; the programs that read them rebuilt when their sizes
//           change), the continents map on the GPU and its CPU copy (terrain/continents.h,
//           one owner), the clouds' density volume and weather map (clouds/cloud_resources.h: cached or baked; rebaked in the background
//           for the explorer); then uploads the frame's blocks (FrameBlock, TerrainBlock,
//           GridBlocks, OceanBlock, CloudBlock) and packs the waves, and binds what every pass
//           reads at the units of shaders/common/bindings.glsl.
//
//   pass           reads                                writes
//   terrain        blocks, continents                   G-buffer (normal, albedo, material, depth)
//   surface light  G-buffer, atmosphere, clouds         surface radiance R_G + distance: the light
//                                                       leaving each surface point, no air in it, the
//                                                       clouds' shadow in its sun (render/surface_light.frag;
//                                                       Elek Eq. 17, 20)
//   ocean          seabed copies, waves, atmosphere     the sea's R_G + distance, and depth, where
//                                                       the sea is (when terrain.ocean is on)
//   sky            surface radiance + distance,         HDR radiance: what lies between the camera
//                  atmosphere                           and R_G or space -- transmittance and
//                                                       in-scattering, the sky, the sun disc; the
//                                                       water body under water (render/sky.frag),
//                                                       through the unified march of clouds and air
//                                                       (clouds/cloud_march.glsl; Michelic Eq. 17-20);
//                                                       every pixel (full rate), or instead:
//   sky march      surface radiance + distance,         sparse sky: T and S at one pixel of each 4x4
//                  atmosphere, history                  block, and how far the history was from
//                                                       each (render/sky_sparse.frag; reduced rate)
//   sky temporal   sparse sky, surface radiance +       HDR radiance, from the sparse samples and the
//                  distance, history                    reprojected history (render/sky_temporal.frag),
//                                                       T and S beside it for the next frame's history,
//                                                       and the list of pixels it cannot trust
//                                                       (where nothing moved: its STILL_FRAME program)
//   sky refine     refine list, surface radiance +      HDR radiance, T and S of the listed pixels
//                  distance, atmosphere                 marched at full rate, one compute invocation
//                                                       each (render/sky_refine.comp)
//   antialias      HDR radiance, surface distance,      HDR radiance, anti-aliased over time (the
//                  history                              explorer: render/antialias.frag; off by default)
//   tonemap        HDR radiance, exposure               LDR (display-ready sRGB)
//   ui             LDR                                  the window (explorer only: blit + panels)
//
// Each pass is a record {name, reads, writes, draw}: the debug group, the profiler scope and
// the order check (every read written earlier in the frame; checked when the list is built,
// and on every frame in debug builds) come from it, and so does the hot-reload list.
// After the passes the HDR radiance, surface distance and the sky's T and S are kept as the
// frame history, with the camera (double) they were rendered from; the history is dropped on
// a resize, a jump of the camera, a change of the scene's parameters (the sun may move a
// little), or a dive across the sea surface.
//
// The reduced rate (scene render.temporal, with clouds) runs where there is a history; a
// frame without one is marched at full rate (a still, the first frame of a sequence), or, for
// the explorer (setFullRateOnReset(false)), reconstructed from its sparse samples alone so
// that dragging a slider costs no more than a reduced-rate frame.
//
// `planet render` reads HDR or LDR back instead of presenting. A still with --samples N
// renders N frames, each with its projection moved by a sub-pixel offset (setJitter; see
// render/frame_uniforms.h) and without history (dropHistory: each at full rate, as a
// one-sample still is), averages their HDR radiance on the CPU, and tone maps the mean
// (tonemapRadiance).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "atmosphere/atmosphere.h"
#include "clouds/cloud_resources.h"
#include "gl/handle.h"
#include "gl/program.h"
#include "ocean/ocean_pass.h"
#include "render/atmosphere_program.h"
#include "render/fullscreen_pass.h"
#include "render/frame_uniforms.h"
#include "render/image_io.h"
#include "render/profiler.h"
#include "render/render_targets.h"
#include "render/screen_bound.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "terrain/continents.h"
#include "terrain/terrain_pass.h"

namespace planet {

// What a pass reads and writes, for the order check. The baked resources, the blocks and
// the atmosphere tables are made by prepare() and are not listed.
enum class FrameResource { GBuffer, TerrainShadow, SurfaceRadiance, SeaReflection, SparseSky, SkyRefine, HdrRadiance, LdrImage, Window };
const char* frameResourceName(FrameResource r);

struct PassDeclaration {
    std::string name;
    std::vector<FrameResource> reads;
    std::vector<FrameResource> writes;
};
// The problems of a pass order: each read that no earlier pass wrote, as
// "pass 'sky' reads surface radiance before any pass writes it". Empty when the order holds.
std::vector<std::string> checkPassOrder(const std::vector<PassDeclaration>& passes);

// What prepare() did in the last frame (tests and the log read it).
struct PrepareReport {
    bool atmosphereTablesMade = false;   // loaded or computed at once (first use)
    bool atmosphereRebuildStep = false;  // one chunk of a rebuild ran
    bool atmosphereProgramsRebuilt = false;  // the tables' sizes changed (refined): their readers rebuilt
    bool continentsUpdated = false;      // the continents map was loaded or baked, and uploaded
    bool cloudsUpdated = false;          // the cloud volume or weather map was made and uploaded
    // The reversed-Z depth nearer than which the ground's way to the sun surely meets no cloud
    // (render/surface_marks.frag; Renderer::clearSkyDepth); 1: no pixel.
    float clearSkyDepth = 1.0f;
    // km from the vertical through the camera within which the cloud layer surely holds no cloud (the clear
    // sky map's angle at the camera's direction, Renderer::clearAxisKm; 0: none): render/sky_no_cloud.frag.
    float clearAxisKm = 0.0f;
    bool historyValid = false;           // the previous frame may be reprojected
    bool reducedRate = false;            // the sky was marched at the reduced rate (sky march, temporal, refine)
    bool stillFrame = false;             // with a history, nothing moved since it (but the jitter, maybe): the reconstruction's
                                         // still-frame program (render/sky_temporal.frag, STILL_FRAME)
    bool jitterStood = false;            // with a history, the projection's sub-pixel jitter the same as its: in a
                                         // still frame, that program's STILL_FRAME_UNJITTERED build
    bool underWater = false;             // the camera under the sea: the sky pass's and the ocean's UNDER_WATER programs
                                         // (render/sky.frag, ocean/sea_light.frag)
    bool cloudFarField = false;          // every footprint the clouds are seen with is the far field's: the programs
                                         // built with CLOUD_FAR_FIELD_ONLY (clouds/cloud_block.h, seenInFarFieldOnly)
    bool clockOnlyOffLayer = false;      // only the clock ran (the camera and the sun stood, with a history), the
                                         // camera under or above the cloud layer: the sky's reconstruction takes the
                                         // still program where a pixel's ray meets no cloud (render/sky_no_cloud.frag)
    bool cloudsOff = false;              // no cloud layer this frame (the cloud block's enabled 0): the programs built
                                         // with CLOUDS_OFF (clouds/cloud_density.glsl), and never the far field's
    ScreenRect skyBound;                 // the pixels the sky passes ran their programs on: those that can see the air
                                         // (render/screen_bound.h; the whole frame where it fills it), space elsewhere
    ScreenRect sunDiscBound;             // the pixels whose ray can see the sun's disc: the sky passes' programs
                                         // without it elsewhere (NO_SUN_DISC; Renderer::drawSkyBound)
    bool cameraInAir = false;            // the camera a kilometre or more under the air's top: no ray misses the air,
                                         // the sky passes' programs without space's code (CAMERA_IN_AIR)
    ScreenRect groundBound;              // the pixels the terrain shadow and the surface light ran on: those that can
                                         // see the ground's highest sphere (terrain.max_height_m above the sea)
};

class Renderer {
public:
    // Throws gl::ShaderError. The first render() makes the atmosphere tables and the
    // continents (from the cache when they are there). `continents` is the map's owner the
    // caller shares with its CPU height queries (Session::continents), so the map is loaded
    // once per process for both; without one the renderer makes its own (default cache).
    // `atmosphereTables`: the table sizes, or a plan that starts with smaller tables and
    // refines them in the background (the explorer; atmosphere/atmosphere.h). The programs
    // that read the tables are built for the sizes in use, rebuilt when they change.
    Renderer(const std::filesystem::path& shaderRoot, const atmosphere::TablePlan& atmosphereTables,
             std::shared_ptr<terrain::Continents> continents = nullptr);
    // Releases the continents' GL texture: the map may outlive this renderer's GL context
    // (a Session owns it), its texture must not.
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Renders one frame into targets(). `present`, when given, runs last as the
    // "ui" pass (the explorer blits LDR to its window and draws panels there),
    // so the profiler's frame covers everything. A size with a zero side
    // (minimised window) renders nothing and keeps the previous targets.
    void render(const Scene& scene, const Camera& camera, glm::ivec2 size,
                const std::function<void()>& present = {});

    const RenderTargets& targets() const { return targets_; }
    const atmosphere::Atmosphere& atmosphere() const { return atmosphere_; }
    // The continents map the terrain draws, also on the CPU (share it with the camera's ground).
    const terrain::Continents& continents() const { return *continents_; }
    Profiler& profiler() { return profiler_; }
    // Bake the clouds' volume and weather map on a worker thread and draw meanwhile (the
    // explorer); off (the default), a frame waits for them.
    void setBackgroundBakes(bool on) { clouds_.setBackgroundBakes(on); }
    // In [0, 1) while a background cloud bake runs, 1 otherwise.
    double cloudBakeProgress() const { return clouds_.bakeProgress(); }
    const clouds::CloudResources& clouds() const { return clouds_; }
    // Count the sky pass's cloud march steps from the next frame on (planet bench).
    void setCloudStatistics(bool on) { clouds_.setStatistics(on); }
    OceanPass& ocean() { return ocean_; }
    // The clouds in the sea's reflection from samples at one pixel of each block and a march
    // where they do not serve (true, the default; ocean/sea_reflection.glsl), or marched at
    // every sea pixel (false: tests compare the two).
    void setSeaReflectionSamples(bool on) { seaReflectionSamples_ = on; }
    TerrainPass& terrain() { return terrain_; }
    // What a reduced-rate frame without history does: march at full rate (true, the default:
    // stills and sequences start exact) or reconstruct from its sparse samples alone (the
    // explorer: a reset costs no more than any other frame, and converges in 16 frames).
    void setFullRateOnReset(bool on) { fullRateOnReset_ = on; }
    // Frames where nothing moved (but the jitter, maybe) run the reconstruction's still-frame program (on, the default),
    // or the general one, which gives the same image at five times the cost on llvmpipe (tests
    // compare the two).
    void setStillFrameProgram(bool on) { stillFrameProgram_ = on; }
    // Frames that see the clouds in the far field alone (from space) run programs built for it
    // (on, the default), or the general ones, which give the same image at more cost on llvmpipe
    // (tests compare the two).
    void setCloudFarFieldPrograms(bool on) { cloudFarFieldPrograms_ = on; }
    // Whether a frame without clouds runs the programs built without their code (CLOUDS_OFF; on by
    // default), for the tests that compare the two.
    void setCloudsOffPrograms(bool on) { cloudsOffPrograms_ = on; }
    // Whether the surface light draws the sea floor's dark depths first and keeps its lighting off
    // them by the stencil (on by default), for the tests that compare the two.
    void setSeaFloorDarkStencil(bool on) { seaFloorDarkStencil_ = on; }
    // Tests: the surface light's ground whose way to the sun surely meets no cloud lit by the program
    // without the clouds' shadow (render/surface_marks.frag; on by default), or all by the one.
    void setSunClearStencil(bool on) { sunClearStencil_ = on; }
    // Tests: the surface light's marks in a pass per mark even where the GL lets one pass give each
    // fragment its own stencil value (render/surface_marks.frag); true: one pass where the GL can.
    void setStencilExport(bool on);
    // Whether the sky march splits off the blocks whose ray meets no cloud (Renderer::drawSkyMarch;
    // tests: the same frame either way).
    void setSkyMarchSplit(bool on) { skyMarchSplit_ = on; }
    // Tests: the sea's light on the open sea by its OPEN_SEA build (the default, where the GL lets the
    // mesh mark it: OceanPass::marksOpenSea), or the whole program on every sea pixel.
    void setOpenSeaSplit(bool on) { openSeaSplit_ = on; }
    // Whether the terrain leaves out the sea floor's dark depths where the sea covers them (on by
    // default), for the tests that compare the two.
    void setDarkFloorCulling(bool on) { darkFloorCulling_ = on; }
    // The sky passes scissored to the rectangle that holds the air's sphere, space drawn around
    // it by render/sky_space.frag, and the terrain shadow and the surface light to the one that
    // holds the ground's highest sphere; the sky passes' programs built without the sun's disc off
    // its rectangle, and without space's code where the camera is in the air (on, the default), or
    // the whole programs run over the whole frame (tests compare the two: the same image).
    void setScreenBounds(bool on) { screenBounds_ = on; }
    // The sub-pixel offset (pixels, about [-0.5, 0.5]) of the projection of the frames
    // rendered from now on; (0, 0), the default, renders unjittered.
    void setJitter(glm::dvec2 pixels) { jitterPx_ = pixels; }
    // Temporal anti-aliasing (the explorer): every frame jittered by subPixelJitter(frame
    // index) instead of setJitter's offset, and blended into the reprojected history of the
    // previous results (pass "antialias", render/antialias.frag). Off by default: stills
    // average jittered frames instead (render --samples).
    void setTemporalAntialiasing(bool on) { temporalAntialiasing_ = on; }
    bool temporalAntialiasing() const { return temporalAntialiasing_; }
    // Forget the frame history: the next frame is rendered as the first (at full rate when
    // setFullRateOnReset holds; historyValid 0).
    void dropHistory() { previous_.reset(); }
    // Tone maps a linear HDR image (row 0 at the top, the size of the last frame) into
    // targets().ldr() with the last frame's exposure, as the tonemap pass does with hdr():
    // the mean of several frames' radiance becomes a PNG. It overwrites targets().hdr();
    // the history is not touched.
    void tonemapRadiance(const ImageRGBAF& radiance);
    const PrepareReport& lastPrepare() const { return lastPrepare_; }
    int frameIndex() const { return frameIndex_; }
    std::vector<PassDeclaration> passDeclarations() const;

    // Hot reload: rebuilds programs whose files changed. Broken edits keep the
    // last good program; shaderErrors() then lists the messages (empty when all is well).
    bool reloadShaders(bool force = false);
    std::vector<std::string> shaderErrors();

private:
    struct Pass {
        PassDeclaration declaration;
        std::function<bool(const Scene&)> enabled;      // drawn this frame?
        std::function<void(const Scene&)> draw;
        std::function<std::vector<gl::HotProgram*>()> programs;  // for hot reload
    };
    std::vector<Pass> makePasses();
    void marchListedTerrainShadow(bool fromGround);  // the terrain shadow list's compute pass
    void prepare(const Scene& scene, const Camera& camera, glm::ivec2 size);
    // The variant of the programs that read the atmosphere for this frame (the last prepare()'s),
    // and the sky passes' (with the terrain's shadows in the air where the preset asks for them).
    AtmosphereVariant variantFor(const Scene& scene) const;
    AtmosphereVariant skyVariantFor(const Scene& scene) const;
    void drawSkyBound(AtmosphereProgram& program, const Scene& scene, int mode);
    // Whether the sky's reconstruction and refine run their still-frame programs (STILL_FRAME) this frame.
    bool stillProgram() const;
    // Whether the sea reflection pass runs this frame (the clouds in the sea's reflection, marched
    // at the ocean's per-pixel program's pixels).
    bool seaReflectionRuns(const Scene& scene) const;
    bool historyUsable(const Scene& scene, const Camera& camera, bool resized) const;
    // Space around the air's bound where it does not fill the frame (render/sky_space.frag), in
    // up to four scissored bands: the sky passes then run scissored to the bound.
    float clearSkyDepth(const Scene& scene, const Camera& camera, glm::ivec2 size, double clearKm) const;
    double clearAxisKm(const Camera& camera) const;
    void drawSurfaceLight(const Scene& scene);
    // The surface light's marks' sources for tables of `sizes` (render/surface_marks.frag): one pass where
    // the GL lets a fragment give its own stencil value (STENCIL_EXPORT), else a pass per mark.
    gl::ShaderSources surfaceMarksSources(const atmosphere::TableSizes& sizes) const;
    void drawSpaceAround(const ScreenRect& skyBound) const;
    void drawSkyMarch(const Scene& scene);
    void drawSkyTemporalSplit(const Scene& scene);
    void drawSeaLight(const Scene& scene);
    // Rebuilds the programs that read the atmosphere tables when the tables' sizes changed
    // (a starter refined to its target). Returns whether it did.
    bool matchAtmosphereTables();
    std::vector<gl::HotProgram*> programs();

    gl::ShaderSources sources_;
    atmosphere::Atmosphere atmosphere_;
    atmosphere::TableSizes programTables_;  // the sizes the programs reading the tables were built for
    std::shared_ptr<terrain::Continents> continents_;
    clouds::CloudResources clouds_;
    TerrainPass terrain_;
    FullscreenPass terrainShadow_;
    // The surface light's stencil: the sea floor's dark depths and the ground clear of the clouds' shadow
    // (render/surface_marks.frag), in one pass where the GL has ARB_shader_stencil_export.
    bool stencilExport_;
    FullscreenPass surfaceMarks_;
    AtmosphereProgram surfaceLight_;
    // Its bit in the surface light's stencil, above the dark depths' value.
    static constexpr GLuint kSunClearOfClouds = 0x40;
    OceanPass ocean_;
    AtmosphereProgram seaReflection_;  // mode SEA_REFLECTION_COMPOSE: the samples' spread (ocean/sea_reflection.frag)
    AtmosphereProgram terrainShadowMarches_;  // the terrain shadow's listed samples (render/terrain_shadow_sample_marches.comp)
    AtmosphereProgram terrainShadowListed_;  // the terrain's shadow at the listed pixels, the ground's (mode 1) and the sea's (render/terrain_shadow_list.comp)
    AtmosphereProgram seaReflectionListed_;  // the pixels the spread could not serve (ocean/sea_reflection.comp)
    AtmosphereProgram terrainReflection_;      // their search (ocean/terrain_reflection.comp)
    AtmosphereProgram sky_;  // mode UNDER_WATER: the camera under the sea
    AtmosphereProgram skySparse_;
    AtmosphereProgram skyTemporal_;  // mode STILL_FRAME: frames where nothing moved (but the jitter, maybe)
    AtmosphereProgram skyRefine_;    // mode STILL_FRAME: a still frame's pixels whose surface changed
    FullscreenPass skySpace_;  // space around the air's bound (render/sky_space.frag)
    // The rays that meet no cloud, into the stencil (render/sky_no_cloud.frag): the full frame's pixels, and the
    // reduced-rate lattice's (SPARSE_LATTICE).
    FullscreenPass skyNoCloud_;
    FullscreenPass skySparseNoCloud_;
    FullscreenPass antialias_;
    FullscreenPass tonemap_;
    gl::Buffer frameUniforms_;
    gl::VertexArray emptyVertexArray_;
    RenderTargets targets_;
    Profiler profiler_;
    std::vector<Pass> passes_;
    std::function<void()> present_;  // this frame's ui, while render() runs

    int frameIndex_ = 0;
    bool fullRateOnReset_ = true;
    bool stillFrameProgram_ = true;
    bool cloudFarFieldPrograms_ = true;
    bool cloudsOffPrograms_ = true;
    bool seaFloorDarkStencil_ = true;
    bool sunClearStencil_ = true;
    bool skyMarchSplit_ = true;
    bool openSeaSplit_ = true;
    bool darkFloorCulling_ = true;
    bool seaReflectionSamples_ = true;
    bool screenBounds_ = true;
    // Whether the ocean drew any pixel this frame: the sea reflection pass draws only then
    // (conditional rendering: no read-back, the GPU skips the draws).
    gl::Query oceanDrew_{GL_ANY_SAMPLES_PASSED};
    glm::dvec2 jitterPx_{0.0};
    bool temporalAntialiasing_ = false;
    glm::dvec2 frameJitterPx_{0.0};          // this frame's: jitterPx_, or the TAA's
    std::optional<PreviousFrame> previous_;  // the frame the history holds
    std::string previousSceneKey_;           // its parameters (presetToToml)
    std::string sceneKey_;                   // this frame's
    PrepareReport lastPrepare_;
};

}  // namespace planet
