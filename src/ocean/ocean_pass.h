// The ocean pass: spherical Gerstner waves (Michelic §4) on the ocean's own persistent
// projected grid (src/grid), tessellated, displaced and shaded as water, drawn into the
// surface radiance and distance targets over the sea floor's (see shaders/ocean/ocean.frag).
//
//   ocean.vert   grid coordinates of the N x N vertices
//   ocean.tesc   frustum culling with the highest crest and lowest trough, levels from edge size
//   ocean.tese   grid -> sea sphere direction (double) -> Eq. 8 displacement (in shallow water
//                each wave no higher than 0.78 x depth) -> camera-relative position
//   ocean.frag   Eq. 10 normal per pixel, Fresnel sky reflection, sun glitter, water body
//
// prepare() (before the frame's passes) uploads the waves (a shader storage buffer at
// BUFFER_OCEAN_WAVES, one record per wave, refreshed every frame with the camera's phases:
// ocean/ocean_gpu.h), the grid's projection and the OceanBlock; draw() only draws. The water
// between a submerged camera and what it sees is the sky pass's (render/sky.frag).
#pragma once

#include "atmosphere/tables.h"
#include "gl/handle.h"
#include "gl/program.h"
#include "grid/grid_mesh.h"
#include "grid/projected_grid.h"
#include "render/atmosphere_program.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace planet {

class OceanPass {
public:
    OceanPass(const gl::ShaderSources& sources, const atmosphere::TableSizes& tables);

    void prepare(const Scene& scene, const Camera& camera);
    // The sea surface into the bound target (surface radiance and distance + the G-buffer's
    // depth, tested and written), reading the seabed copies, the atmosphere and the terrain's
    // height field (the sea floor), with the program for the table in use.
    void draw(bool elekTable);

    AtmosphereProgram& program() { return program_; }

private:
    void uploadWaves(const Scene& scene, const Camera& camera);

    AtmosphereProgram program_;
    GridMesh mesh_{"ocean"};
    gl::Buffer waves_;
    gl::Buffer block_;  // OceanBlock
    std::size_t waveCapacity_ = 0;
    GridAnchor anchor_;
};

}  // namespace planet
