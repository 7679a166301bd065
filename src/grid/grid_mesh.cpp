#include "grid/grid_mesh.h"

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

GridUniforms GridUniforms::lookUp(GLuint program) {
    auto at = [program](const char* name) { return glGetUniformLocation(program, name); };
    return {at("uWorldFromGrid"), at("uZShift"), at("uGridExponent"), at("uCameraPosition"), at("uPlanetRadius")};
}

void GridUniforms::set(GLuint program, const GridProjection& projection, int exponent,
                       const glm::dvec3& cameraPosition, double radius) const {
    glProgramUniformMatrix3dv(program, worldFromGrid, 1, GL_FALSE, &projection.worldFromGrid[0][0]);
    glProgramUniform1d(program, zShift, projection.zShift);
    glProgramUniform1i(program, gridExponent, exponent);
    glProgramUniform3dv(program, this->cameraPosition, 1, &cameraPosition.x);
    glProgramUniform1d(program, planetRadius, radius);
}

void GridMesh::draw() const {
    glBindVertexArray(vertexArray_.id());
    glPatchParameteri(GL_PATCH_VERTICES, 4);
    glDrawElements(GL_PATCHES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace planet
