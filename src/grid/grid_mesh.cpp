#include "grid/grid_mesh.h"

#include "render/bindings.h"

#include <vector>

#include <glm/glm.hpp>

#include "grid/projected_grid.h"

namespace planet {

void GridMesh::resize(int size) {
    if (size == size_) return;
    std::vector<glm::vec2> coordinates;
    coordinates.reserve(static_cast<std::size_t>(size) * size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) coordinates.push_back(glm::vec2(gridVertexCoordinate(i, j, size)));
    std::vector<GLuint> patches;
    patches.reserve(static_cast<std::size_t>(size - 1) * (size - 1) * 4);
    const auto at = [size](int x, int y) { return static_cast<GLuint>(y * size + x); };
    for (int j = 0; j + 1 < size; ++j)
        for (int i = 0; i + 1 < size; ++i) patches.insert(patches.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    vertices_ = gl::Buffer();
    indices_ = gl::Buffer();
    vertexArray_ = gl::VertexArray();
    glNamedBufferStorage(vertices_.id(), static_cast<GLsizeiptr>(coordinates.size() * sizeof(glm::vec2)),
                         coordinates.data(), 0);
    glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(patches.size() * sizeof(GLuint)), patches.data(), 0);
    glVertexArrayVertexBuffer(vertexArray_.id(), 0, vertices_.id(), 0, sizeof(glm::vec2));
    glVertexArrayElementBuffer(vertexArray_.id(), indices_.id());
    glEnableVertexArrayAttrib(vertexArray_.id(), 0);
    glVertexArrayAttribFormat(vertexArray_.id(), 0, 2, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vertexArray_.id(), 0, 0);
    vertices_.label((label_ + " grid coordinates").c_str());
    indices_.label((label_ + " grid patches").c_str());
    vertexArray_.label((label_ + " grid").c_str());
    size_ = size;
    indexCount_ = static_cast<GLsizei>(patches.size());
}

GridBlock makeGridBlock(const GridProjection& projection, int exponent, const glm::dvec3& cameraPosition,
                        double radius) {
    GridBlock b{};
    for (int i = 0; i < 3; ++i) b.worldFromGridColumns[i] = glm::dvec4(projection.worldFromGrid[i], 0.0);
    b.cameraPositionAndRadius = glm::dvec4(cameraPosition, radius);
    b.zShift = projection.zShift;
    b.exponent = exponent;
    return b;
}

GridMesh::GridMesh(std::string label) : label_(std::move(label)) {
    glNamedBufferStorage(block_.id(), sizeof(GridBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    block_.label((label_ + " GridBlock").c_str());
}

void GridMesh::setProjection(const GridBlock& block) {
    glNamedBufferSubData(block_.id(), 0, sizeof block, &block);
}

void GridMesh::draw() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_GRID, block_.id());
    glBindVertexArray(vertexArray_.id());
    glPatchParameteri(GL_PATCH_VERTICES, 4);
    glDrawElements(GL_PATCHES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace planet
