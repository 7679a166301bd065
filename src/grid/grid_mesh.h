// The projected grid's mesh on the GPU: N x N grid coordinates (gridVertexCoordinate) as
// (N-1)^2 four-vertex patches for the tessellation stages. The terrain and the ocean each
// draw one (Michelic §6: 100 x 100 and 80 x 80).
#pragma once

#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "gl/handle.h"
#include "grid/projected_grid.h"

namespace planet {

// The uniforms of shaders/terrain/grid.glsl (the grid's projection on the GPU) in one
// program: looked up once per program, set once per frame by every pass that draws a grid.
struct GridUniforms {
    GLint worldFromGrid = -1, zShift = -1, gridExponent = -1, cameraPosition = -1, planetRadius = -1;

    static GridUniforms lookUp(GLuint program);
    // Eq. 1-4's frame and shift, Eq. 2's n, the camera (world, m) and the sphere's radius (m).
    void set(GLuint program, const GridProjection& projection, int exponent, const glm::dvec3& cameraPosition,
             double radius) const;
};

class GridMesh {
public:
    explicit GridMesh(std::string label) : label_(std::move(label)) {}

    // Rebuilds the buffers when the size changed; size in [2, 4096].
    void resize(int size);
    // Draws the patches (GL_PATCHES, 4 vertices each) with the bound program.
    void draw() const;

private:
    std::string label_;
    gl::VertexArray vertexArray_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    int size_ = 0;
    GLsizei indexCount_ = 0;
};

}  // namespace planet
