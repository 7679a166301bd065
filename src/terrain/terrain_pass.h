// The terrain pass: Michelic's persistent projected grid (src/grid), tessellated
// on the GPU and displaced by the shared height function (terrain/height.glsl),
// written into the G-buffer like any surface.
//
//   terrain.vert  grid coordinates of the N x N vertices ((N-1)^2 quad patches)
//   terrain.tesc  frustum culling with the highest terrain, levels from edge size on screen
//   terrain.tese  grid -> sphere direction (double) -> height -> camera-relative position
//   terrain.frag  per-pixel normal, material, albedo
//
// The grid follows a projection anchor with hysteresis (updateAnchor), so
// vertices stay put while the camera moves a little: no swimming.
#pragma once

#include "gl/handle.h"
#include "gl/program.h"
#include "grid/projected_grid.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace planet {

class TerrainPass {
public:
    explicit TerrainPass(const gl::ShaderSources& sources);

    // Draws into the bound G-buffer (depth test on, reversed-Z).
    void draw(const Scene& scene, const Camera& camera);
    gl::HotProgram& program() { return program_; }
    const GridAnchor& anchor() const { return anchor_; }

private:
    // Uniform locations, looked up again only when hot reload replaced the program.
    struct Locations {
        GLuint program = 0;
        GLint worldFromGrid, zShift, gridExponent, cameraPosition, planetRadius, planetRadiusF, maxTerrainHeight,
            targetEdgePixels, ocean, lowlandAlbedo;
    };
    const Locations& locations();
    void rebuildMesh(int size);

    gl::HotProgram program_;
    gl::VertexArray vertexArray_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::Buffer shape_;
    int meshSize_ = 0;
    GLsizei indexCount_ = 0;
    GridParams grid_;
    GridAnchor anchor_;
    Locations locations_;
};

}  // namespace planet
