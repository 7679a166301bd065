// The terrain pass: Michelic's persistent projected grid (src/grid), tessellated on the GPU
// and displaced by the shared height function (terrain/height.glsl), written into the
// G-buffer like any surface.
//
//   terrain.vert  grid coordinates of the N x N vertices ((N-1)^2 quad patches)
//   terrain.tesc  frustum culling with the highest terrain, levels from edge size on screen
//   terrain.tese  grid -> sphere direction (double) -> height -> camera-relative position
//   terrain.frag  the fragment's point, direction and steps to the next pixels
//                 (terrain/mesh_surface.glsl), and the stencil
//   ground_material.frag  over the frame where the stencil is set, once per pixel (a software
//                 renderer shades a 4x4 block for every triangle that touches it): per-pixel
//                 normal, material, albedo, filtered over the pixel's footprint, with tri-planar
//                 detail from the baked detail texture (terrain/detail_texture.h) where it may show
//
// prepare() (before the frame's passes) follows the grid's projection anchor with
// hysteresis (updateAnchor), so vertices stay put while the camera moves a little, and
// uploads the GridBlock and the TerrainBlock; the draws only draw. The continents map it
// samples is a baked resource the renderer brings up to date before the frame
// (terrain/continents.h) and binds at UNIT_CONTINENTS.
#pragma once

#include <optional>
#include <vector>

#include "gl/handle.h"
#include "gl/program.h"
#include "grid/constants.h"
#include "grid/grid_mesh.h"
#include "grid/grid_stride.h"
#include "grid/projected_grid.h"
#include "noise/continents.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "terrain/near_height_grid.h"

namespace planet {

// The most the terrain's chords may sag, m (shaders/grid/constants.glsl).
inline const double kTerrainMaxSagM = grid_constant::TERRAIN_MAX_SAG_M;

class TerrainPass {
public:
    explicit TerrainPass(const gl::ShaderSources& sources);

    // Uploads the grid's projection and the TerrainBlock (bound at BLOCK_TERRAIN for the
    // frame: the ocean reads the sea floor through it too).
    // Also the TerrainNearBlock, from the CPU copy of the continents map the GPU samples.
    // `radiansPerPixel` and `aspect`: the view's, for the grid's stride (grid/grid_stride.h).
    void prepare(const Scene& scene, const Camera& camera, const noise::CubeMap& continents, double radiansPerPixel,
                 double aspect);
    // Draws the mesh into the bound targets (the mesh surface and the G-buffer's depth:
    // RenderTargets::terrainMeshFramebuffer; depth test on, reversed-Z), with the stencil's
    // reference 2 for the patches that take the detail's material and 1 for the rest (the caller
    // enables the test and sets the op that writes it).
    void drawMesh();
    // Binds the ground's material program (terrain/ground_material.frag) with the detail's code
    // (`detailed`: the stencil's 2, only when detailDrawn()) or without; the caller draws its
    // full-screen triangle into the G-buffer over the pixels of that stencil value.
    void useMaterialProgram(bool detailed);
    // The programs built so far, for hot reload: the mesh's, the material without the ground
    // detail, and with it (TERRAIN_DETAIL 1) once the preset's terrain.detail has been on.
    std::vector<gl::HotProgram*> programs();

    // What the pass's stages did in the last drawn frame, counted while setStatistics(true)
    // (read back at once: tests, profiling). -1 where not counted: the invocation counts
    // need GL 4.6 or ARB_pipeline_statistics_query (llvmpipe has it).
    struct Statistics {
        long long primitives = -1;  // triangles the tessellation emitted (GL_PRIMITIVES_GENERATED)
        long long vertices = -1;    // vertex-stage invocations (one height each)
        long long clipped = -1;     // triangles out of clipping: those at least partly in the view
        long long patches = -1;     // control-stage patches (the heights come from the vertex stage)
        long long evaluations = -1; // evaluation-stage invocations (one height each)
        long long fragments = -1;   // the mesh's fragment-stage invocations (the point's writes; the material's
                                    // are one per pixel after it, terrain/ground_material.frag)
    };
    void setStatistics(bool on) { statistics_ = on; }
    // After prepare(), where the sea is drawn over the ground from above: patches surely under the
    // sea floor's dark depths (their continent values below patchDarkContinent by the map's slope
    // bound, per radian) are not drawn this frame (shaders/terrain/terrain.tesc). Off again at the
    // next prepare().
    // The patches' bound is also the continents' maxima over them where tighter (UNIT_CONTINENT_MAX,
    // src/terrain/continent_bound.h): the slope bound alone kept most of the sea floor from orbit.
    void setDarkFloorCulling(double patchDarkContinent, double continentLipschitz);
    // Whether the last prepared frame draws with the ground detail's program: terrain.detail on
    // and the camera close enough to the ground for any of it to show (detailInReach).
    bool detailDrawn() const { return detailPatches_ > 0; }
    // Whether ground within the detail's range (TERRAIN_NEAR_RANGE_M) can be in view of a camera
    // `cameraAltitudeM` above the planet's radius, the ground reaching at most `maxHeightM`.
    static bool detailInReach(double cameraAltitudeM, double maxHeightM);
    // How many patches, from the first in the NearFirst draw order, take the detail's program:
    // the rings up to the first beyond which no ground (at any height) comes within
    // `rangeM` of the camera; all of them in row order (no rings) or when none is that far.
    static int detailPatchCount(const std::vector<PatchRun>& rings, int patchCount, int gridSize,
                                const GridBlock& grid, double rangeM);
    // The last prepared frame's count (0 when the detail is not drawn).
    int detailPatches() const { return detailPatches_; }
    // The stencil's values the mesh leaves: where its material takes the detail's program, and the plain one.
    static constexpr int kDetailedStencil = 2, kPlainStencil = 1;
    // Tests: the detail's program for every patch, as before the rings (the same image).
    void setDetailOnEveryPatch(bool on) { detailOnEveryPatch_ = on; }
    // The patches' draw order (grid/grid_mesh.h; NearFirst by default). Tests compare.
    void setPatchOrder(PatchOrder order) { mesh_.setOrder(order); }
    // Tests: the patches' stride forced (1, 2, 4 or 8), or 0 (the default) to let the grid's
    // cells on screen decide where the detail is out of reach (grid/grid_stride.h); the last
    // prepared frame's.
    void setStrideOverride(int stride) { strideOverride_ = stride; }
    int stride() const { return mesh_.stride(); }
    // Tests: whole blocks of patches out of the view left undrawn (grid/view_cull.h; on by default),
    // and how many patches the last prepared frame draws.
    void setViewCulling(bool on) { viewCulling_ = on; }
    // Tests: the detail's program reads the near field from its grid (terrain/near_height_grid.h; on
    // by default) or evaluates it at every pixel; the grid, once built.
    void setNearHeightGrid(bool on) {
        if (on != nearGridOn_) detailed_.reset();  // built again with the other code at the next prepare
        nearGridOn_ = on;
    }
    const terrain::NearHeightGrid* nearHeightGrid() const { return nearGrid_ ? &*nearGrid_ : nullptr; }
    int patchesDrawn() const { return mesh_.patchesDrawn(0, mesh_.patchCount()); }
    const Statistics& lastStatistics() const { return lastStatistics_; }

private:
    // The detail's code is in a program of its own rather than behind the block's flag alone,
    // which llvmpipe paid for though no pixel entered it (the terrain pass at the `ground`
    // view, 1280x720: 86 -> 63 ms of fragment work without it; terrain/ground_material.frag).
    gl::ShaderSources sources_;
    gl::HotProgram meshProgram_;
    gl::HotProgram plain_;                    // the material (terrain/ground_material.frag)
    std::optional<gl::HotProgram> detailed_;  // ... with TERRAIN_DETAIL 1, built when terrain.detail is first on
    int detailPatches_ = 0;  // the last prepared frame's: 0 out of reach or with terrain.detail off
    bool detailOnEveryPatch_ = false;
    GridMesh mesh_{"terrain", PatchOrder::NearFirst};
    gl::Buffer block_;      // TerrainBlock
    gl::Buffer nearBlock_;  // TerrainNear (terrain/height.h), every frame
    std::vector<float> detailLostVariance_;  // its DetailTexture::lostSlopeVariance, the shader's table
    std::optional<gl::Texture> detail_;  // terrain/detail_texture.h, baked when terrain.detail is first on (~0.1 s)
    GridParams grid_;
    GridAnchor anchor_;
    GridStride stride_;
    int strideOverride_ = 0;
    bool viewCulling_ = true;
    bool nearGridOn_ = true;
    std::optional<terrain::NearHeightGrid> nearGrid_;  // built with the detail's program
    bool statistics_ = false;
    Statistics lastStatistics_;
    gl::Query primitives_{GL_PRIMITIVES_GENERATED};
    gl::GenQuery vertices_;
    gl::GenQuery clipped_;
    gl::GenQuery patches_;
    gl::GenQuery evaluations_;
    gl::GenQuery fragments_;
};

}  // namespace planet
