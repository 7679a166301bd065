// The ocean pass: spherical Gerstner waves (Michelic §4) on the ocean's own persistent
// projected grid (src/grid), tessellated and displaced, then shaded as water over the sea
// floor's surface radiance (see shaders/ocean/sea_light.frag), in two draws:
//
//   ocean.vert   grid coordinates of the N x N vertices
//   ocean.tesc   frustum culling with the highest crest and lowest trough, patches over land
//                dropped (land_cull.h), levels from edge size
//   ocean.tese   grid -> sea sphere direction (double) -> Eq. 8 displacement (in shallow water
//                each wave no higher than 0.78 x depth) -> camera-relative position
//   ocean.frag   fragments under land or behind the terrain discarded first (cheap tests that
//                give the same pixels), the shore's coverage, the water's depth and path, the
//                far field's sphere: the sea surface's G-buffer (ocean/sea_surface.glsl) and the
//                depth, the stencil set where the sea is the nearest surface; where every sea pixel
//                is the far field's (far_field.h), its build OCEAN_FAR_FIELD instead of the mesh,
//                once per pixel of the ground sphere's rectangle from the pixel's ray
//   sea_light.frag  over the whole frame where the stencil is set, once per pixel (a software
//                renderer shades a 4x4 block for each triangle touching it: the mesh's fragments
//                were two to three times the sea's pixels): Eq. 10 normal (from below, with the
//                camera under the sea: a program of its own, UNDER_WATER), Fresnel sky
//                reflection (from high up the clear sky plus the grid's change for the clouds,
//                ocean/grid_reflection.comp, or all of it from the grid), sun glitter, water body
//
// prepare() (before the frame's passes) uploads the waves (a shader storage buffer at
// BUFFER_OCEAN_WAVES, one record per wave, refreshed every frame with the camera's phases:
// ocean/ocean_gpu.h), the grid's projection and the OceanBlock; the draws only draw. The water
// between a submerged camera and what it sees is the sky pass's (render/sky.frag).
#pragma once

#include <functional>
#include <memory>

#include "atmosphere/tables.h"
#include "gl/handle.h"
#include "gl/program.h"
#include "grid/grid_mesh.h"
#include "grid/grid_stride.h"
#include "grid/projected_grid.h"
#include "noise/continents.h"
#include "render/atmosphere_program.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace planet {

class OceanPass {
public:
    // `stencilExport`: the GL has ARB_shader_stencil_export, and the far field's draw marks the open sea
    // with each pixel's own stencil value (kOpenSeaStencil, ocean/ocean.frag).
    OceanPass(const gl::ShaderSources& sources, const atmosphere::TableSizes& tables, bool stencilExport);

    // `continents`: the CPU map the GPU samples (the land culling's bounds are made from it
    // when it changes); `radiansPerPixel`: the angle of a pixel (the flat mirror's test); with
    // `aspect`, the view's, for the grid's stride (grid/grid_stride.h).
    void prepare(const Scene& scene, const Camera& camera, double radiansPerPixel, double aspect,
                 const std::shared_ptr<const noise::CubeMap>& continents);
    // The sea's surface into the bound targets (the surface distance and the sea surface's
    // G-buffer: RenderTargets::seaSurfaceFramebuffer, the G-buffer's depth tested and written),
    // reading the seabed depth's copy and the terrain's height field (the sea floor); the stencil's
    // ops are the caller's (it marks the pixels where a fragment is written). `drawFarField` draws
    // a full-screen triangle over the pixels that may show the sea (the ground sphere's rectangle):
    // called, with the far field's program bound, where the whole sea is the far field
    // (farField(), src/ocean/far_field.h); else the mesh is drawn.
    void drawSurface(const std::function<void()>& drawFarField);
    // Whether the last prepare() found every sea pixel in the far field (and it is allowed).
    bool farField() const { return farField_; }
    // Tests: the far field's per-pixel draw allowed (the default) or not (the mesh always).
    void setFarFieldAllowed(bool on) { farFieldAllowed_ = on; }
    // Binds the program for the water's light (ocean/sea_light.frag) of the frame's variant (the
    // table in use, the clouds' far field) and the sea's buffers, first forming the grid's
    // reflection where the sea is a flat or smooth mirror; the caller draws its full-screen
    // triangle over the pixels drawSurface() marked. `underWater`: the camera under the sea (the
    // frame's PrepareReport), the surface seen from below.
    void useLightProgram(const AtmosphereVariant& variant, bool underWater);
    // After useLightProgram: its OPEN_SEA build (ocean/sea_light.frag), for the pixels marked
    // kOpenSeaStencil, in the same mode. Not under the sea (the light passes the sky on there).
    void useOpenSeaLightProgram(const AtmosphereVariant& variant);
    // Whether the last prepared frame's surface marks the open sea apart (kOpenSeaStencil): the far
    // field's draw where the GL lets a fragment give its own stencil value; else all of it kSeaStencil.
    bool marksOpenSea() const { return stencilExport_ && farField_; }

    // Binds the sea's parameters (the last prepare()'s OceanBlock) for a program other than this
    // pass's that reads them: the terrain shadow's samples of the sea's surface.
    void bindBlock() const;

    // Its programs that read the atmosphere's tables (the sea's light, and the grid's reflection).
    std::vector<AtmosphereProgram*> atmospherePrograms() { return {&light_, &openSeaLight_, &gridReflectionProgram_}; }
    // Those of their variants built so far, and the mesh's (hot reload).
    std::vector<gl::HotProgram*> builtPrograms();

    // The program's mode OCEAN_FLAT_MIRROR (the clouds' share of the reflection from the grid's
    // points) where the sea is a flat mirror to every pixel, and OCEAN_SMOOTH_MIRROR (all of the
    // reflected sky from the grid's points) where it is a smooth one (Auto: flat_mirror.h, per
    // frame), or always the one (On: flat, Smooth: smooth) or neither (Off), to compare with
    // (tests). flatMirror(), smoothMirror(): the last prepare()'s (a smooth mirror is flat too).
    enum class FlatMirror { Auto, On, Smooth, Off };
    void setFlatMirror(FlatMirror mode) { flatMirrorMode_ = mode; }
    bool flatMirror() const { return flatMirror_; }
    bool smoothMirror() const { return smoothMirror_; }

    // Land culling (on by default): patches over land dropped in the control stage, fragments
    // under land or behind the terrain discarded before the water is shaded. Off only to
    // compare with (tests): the pixels are the same either way.
    void setLandCulling(bool on) { landCulling_ = on; }
    // Where the terrain may leave out the sea floor's dark depths under this sea (src/ocean/
    // land_cull.h, darkFloorContinentThreshold), from the last prepare(): whether it may (land
    // culling on, such a value exists), the patch's bound with the filter's slack, the map's slope.
    bool darkFloorCulling() const { return landCulling_ && darkContinent_ >= -1.0; }
    double patchDarkContinent() const { return darkContinent_ - sampleSlack_; }
    // The stencil's value the mesh (or its far field's draw) leaves where a sea fragment is the nearest (not the terrain's,
    // which the same stencil held before the ocean pass cleared it: src/terrain/terrain_pass.h).
    static constexpr int kSeaStencil = 3;
    // ...and where no land lies within reach of its reflected ray or its sun ray (ocean/ocean.frag's
    // openSea), where the far field's draw marks it (marksOpenSea()): kSeaStencil's bits
    // and one more, so that a test of kSeaStencil's bits alone finds every sea pixel.
    static constexpr int kOpenSeaStencil = 7;
    static constexpr unsigned kSeaStencilBits = kSeaStencil, kOpenSeaStencilBits = kOpenSeaStencil;
    // Tests: the patches' stride forced (1, 2, 4 or 8), or 0 (the default) to let the grid's cells
    // on screen decide above the terrain detail's reach (grid/grid_stride.h); the last prepared frame's.
    void setStrideOverride(int stride) { strideOverride_ = stride; }
    int stride() const { return mesh_.stride(); }
    bool landCulling() const { return landCulling_; }
    // Tests: whole blocks of patches out of the view left undrawn (grid/view_cull.h; on by default),
    // and how many patches the last prepared frame draws.
    void setViewCulling(bool on) { viewCulling_ = on; }
    int patchesDrawn() const { return mesh_.patchesDrawn(0, mesh_.patchCount()); }
    // Counts the primitives the pass's tessellation emits (GL_PRIMITIVES_GENERATED) while on;
    // lastPrimitives() is the last drawn frame's count (read back at once: tests, bench).
    void setCountPrimitives(bool on) { countPrimitives_ = on; }
    // Tests: the grid's reflection the last flat or smooth mirror's frame formed (N x N, RGBA32F; 0 at
    // the points ocean/grid_reflection.comp did not march).
    const gl::Texture& gridReflection() const { return gridReflection_; }
    int gridSize() const { return mesh_.size(); }
    long long lastPrimitives() const { return lastPrimitives_; }
    // The bounds in use (land_cull.h): continent value, slope per radian.
    double landContinent() const { return landContinent_; }
    double continentLipschitz() const { return lipschitz_; }

private:
    void uploadWaves(const Scene& scene, const Camera& camera);
    // The light program's mode (the index in AtmosphereProgram::get): under the sea, else the mirror in use.
    int lightMode(bool underWater) const;
    void bindWavesAndBlock() const;  // the waves' buffer and the OceanBlock, for the mesh's and the light's programs
    // ocean/grid_reflection.comp over the grid's points, for the program in the flat or smooth mode.
    void formGridReflection(const AtmosphereVariant& variant);

    gl::HotProgram surface_;    // the mesh (ocean/ocean.vert, .tesc, .tese, .frag)
    gl::HotProgram farFieldSurface_;  // ocean/ocean.frag's OCEAN_FAR_FIELD build, per pixel
    bool farField_ = false;
    bool farFieldAllowed_ = true;
    AtmosphereProgram light_;  // modes OCEAN_FLAT_MIRROR, UNDER_WATER (the surface seen from below), OCEAN_SMOOTH_MIRROR
    AtmosphereProgram openSeaLight_;  // its OPEN_SEA build, the same modes
    bool stencilExport_;
    FlatMirror flatMirrorMode_ = FlatMirror::Auto;
    bool flatMirror_ = false;
    bool smoothMirror_ = false;
    // ocean/grid_reflection.comp (modes OCEAN_FLAT_MIRROR, OCEAN_SMOOTH_MIRROR) and its output, a
    // vec4 per grid point, read by the vertex stage where the sea is a flat or smooth mirror.
    AtmosphereProgram gridReflectionProgram_;
    gl::Texture gridReflection_{GL_TEXTURE_2D};  // N x N RGBA32F, bilinear (ocean/grid_reflection_points.glsl)
    int gridReflectionPoints_ = 0;
    GridMesh mesh_{"ocean"};
    gl::Buffer waves_;
    gl::Buffer block_;  // OceanBlock
    std::size_t waveCapacity_ = 0;
    GridAnchor anchor_;
    GridStride stride_;
    int strideOverride_ = 0;
    bool landCulling_ = true;
    bool viewCulling_ = true;
    double darkContinent_ = -2.0;
    bool countPrimitives_ = false;
    long long lastPrimitives_ = -1;
    gl::Query primitives_{GL_PRIMITIVES_GENERATED};
    std::shared_ptr<const noise::CubeMap> continents_;  // the map lipschitz_ was measured on
    double lipschitz_ = 0.0, sampleSlackRad_ = 0.0, sampleSlack_ = 0.0, landContinent_ = 2.0;
};

}  // namespace planet
