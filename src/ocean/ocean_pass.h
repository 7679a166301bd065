// The ocean pass: spherical Gerstner waves (Michelic §4) on the ocean's own persistent
// projected grid (src/grid), tessellated, displaced and shaded as water, drawn forward into
// the HDR target after the atmosphere pass (see shaders/ocean/ocean.frag).
//
//   ocean.vert   grid coordinates of the N x N vertices
//   ocean.tesc   frustum culling with the highest crest and lowest trough, levels from edge size
//   ocean.tese   grid -> sea sphere direction (double) -> Eq. 8 displacement (in shallow water
//                each wave no higher than 0.78 x depth) -> camera-relative position
//   ocean.frag   Eq. 10 normal per pixel, Fresnel sky reflection, sun glitter, water body, aerial perspective
//   underwater.frag  the water body around a camera below the sea surface
//
// The waves travel in a shader storage buffer (binding 3), one record per wave, refreshed
// every frame with the camera's phases (ocean/ocean_gpu.h).
#pragma once

#include "gl/handle.h"
#include "gl/program.h"
#include "grid/grid_mesh.h"
#include "grid/projected_grid.h"
#include "render/fullscreen_pass.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace planet {

class OceanPass {
public:
    // `sources` must carry the atmosphere's shader defines (the water reflects the sky).
    explicit OceanPass(const gl::ShaderSources& sources);

    // Camera depth below the mean sea surface (m), <= 0 when above it.
    static double cameraDepthM(const Scene& scene, const Camera& camera);

    // The water body around a submerged camera: a full-screen pass into the bound target,
    // reading the seabed copies on units 0 and 1. Call only when cameraDepthM > 0.
    void drawUnderwater(const Scene& scene, const Camera& camera);
    // The sea surface into the bound target (HDR colour + the G-buffer's depth, tested and
    // written), reading the seabed copies on units 0 and 1, the atmosphere tables, and the
    // terrain's height field (TerrainPass::bindHeightField) for the sea floor far away.
    void drawSurface(const Scene& scene, const Camera& camera);

    gl::HotProgram& surfaceProgram() { return surface_; }
    gl::HotProgram& underwaterProgram() { return underwater_.program(); }

private:
    struct Locations {
        GLuint program = 0;
        GridUniforms grid;
        GLint maxWaveHeight, targetEdgePixels,
            waveCount, fadeStart, fadeEnd, cameraUnderwater, subgridSlopeVariance, seaLevel,
            coarsestEdgePixels;
    };
    const Locations& locations();
    void uploadWaves(const Scene& scene, const Camera& camera);

    gl::HotProgram surface_;
    FullscreenPass underwater_;
    GridMesh mesh_{"ocean"};
    gl::Buffer waves_;
    std::size_t waveCapacity_ = 0;
    GridAnchor anchor_;
    Locations locations_;
};

}  // namespace planet
