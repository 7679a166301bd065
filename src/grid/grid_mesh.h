// The projected grid's mesh on the GPU: N x N grid coordinates (gridVertexCoordinate) as
// (N-1)^2 four-vertex patches for the tessellation stages. The terrain and the ocean each
// draw one (Michelic §6: 100 x 100 and 80 x 80).
#pragma once

#include <string>
#include <utility>

#include "gl/handle.h"

namespace planet {

class GridMesh {
public:
    explicit GridMesh(std::string label) : label_(std::move(label)) {}

    // Rebuilds the buffers when the size changed; size in [2, 4096].
    void resize(int size);
    int size() const { return size_; }
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
