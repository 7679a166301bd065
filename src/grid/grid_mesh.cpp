#include "grid/grid_mesh.h"

#include "gl/context.h"
#include "render/bindings.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "grid/projected_grid.h"

namespace planet {

namespace {

// NearFirst: blocks of 8 x 8 patches, ring by ring from the centre's block (a block's ring: the
// larger of its two offsets from it, in blocks), each block row by row: a block's 9 x 9 corners
// stay in llvmpipe's vertex cache, so the vertex stage runs 1.18 times per grid point at the
// ground view (1.38 in row order; rings of single patches took 1.9). The centre's block is
// centred on the grid's centre (to half a patch), partial blocks at the edges, so each ring
// reaches equally far every way: at 2 m the centre's block alone holds the ground within 4.8 km.
constexpr int kBlock = 8;

struct PatchBlock {
    glm::ivec2 from, to;  // patch indices, `to` exclusive
};

std::vector<std::vector<PatchBlock>> ringBlocks(int size) {
    const int n = size - 1;  // patches per side
    const int centreStart = std::max(0, (n - kBlock) / 2);
    std::vector<int> starts;  // each block's first patch along a side
    if (centreStart % kBlock != 0) starts.push_back(0);
    for (int first = centreStart % kBlock; first < n; first += kBlock) starts.push_back(first);
    const int blocks = static_cast<int>(starts.size());
    const int centre = static_cast<int>(std::find(starts.begin(), starts.end(), centreStart) - starts.begin());
    const auto end = [&](int b) { return b + 1 < blocks ? starts[static_cast<std::size_t>(b + 1)] : n; };
    std::vector<std::vector<PatchBlock>> rings(static_cast<std::size_t>(std::max(centre, blocks - 1 - centre) + 1));
    for (int bj = 0; bj < blocks; ++bj)
        for (int bi = 0; bi < blocks; ++bi) {
            const int ring = std::max(std::abs(bi - centre), std::abs(bj - centre));
            rings[static_cast<std::size_t>(ring)].push_back(
                {{starts[static_cast<std::size_t>(bi)], starts[static_cast<std::size_t>(bj)]}, {end(bi), end(bj)}});
        }
    return rings;
}

// Each ring's patches in draw order and the box of rings 0..k (PatchRun).
std::vector<PatchRun> ringsOf(const std::vector<std::vector<PatchBlock>>& ringBlocks, int size) {
    const int n = size - 1;
    std::vector<PatchRun> rings;
    int first = 0;
    glm::ivec2 low(n), high(0);
    for (const std::vector<PatchBlock>& blocks : ringBlocks) {
        PatchRun ring;
        ring.firstPatch = first;
        for (const PatchBlock& b : blocks) {
            ring.patchCount += (b.to.x - b.from.x) * (b.to.y - b.from.y);
            low = glm::min(low, b.from);
            high = glm::max(high, b.to);
        }
        ring.pointMin = low;
        ring.pointMax = high;
        first += ring.patchCount;
        rings.push_back(ring);
    }
    return rings;
}

}  // namespace

std::vector<PatchRun> nearFirstRings(int size) { return ringsOf(ringBlocks(size), size); }

std::vector<PatchRun> nearFirstBlocks(int size) {
    std::vector<PatchRun> runs;
    int first = 0;
    for (const std::vector<PatchBlock>& ring : ringBlocks(size))
        for (const PatchBlock& b : ring)
            for (int j = b.from.y; j < b.to.y; ++j) {  // the block's rows, each a run of the index buffer
                const int count = b.to.x - b.from.x;
                runs.push_back({first, count, {b.from.x, j}, {b.to.x, j + 1}});
                first += count;
            }
    return runs;
}

std::vector<GLuint> stridePatches(int size, int stride) {
    const int n = size - 1;  // cells per side
    std::vector<int> starts;
    for (int first = 0; first < n; first += stride) starts.push_back(first);
    const auto end = [&](std::size_t b) { return b + 1 < starts.size() ? starts[b + 1] : n; };
    std::vector<GLuint> patches;
    patches.reserve(starts.size() * starts.size() * 4);
    const auto at = [size](int x, int y) { return static_cast<GLuint>(y * size + x); };
    for (std::size_t bj = 0; bj < starts.size(); ++bj)
        for (std::size_t bi = 0; bi < starts.size(); ++bi) {
            const int i0 = starts[bi], i1 = end(bi), j0 = starts[bj], j1 = end(bj);
            patches.insert(patches.end(), {at(i0, j0), at(i1, j0), at(i1, j1), at(i0, j1)});
        }
    return patches;
}

std::vector<PatchRun> rowBlocks(int size) {
    const int n = size - 1;
    std::vector<PatchRun> runs;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; i += kBlock) {
            const int to = std::min(i + kBlock, n);
            runs.push_back({j * n + i, to - i, {i, j}, {to, j + 1}});
        }
    return runs;
}

void GridMesh::setOrder(PatchOrder order) {
    if (order == order_) return;
    order_ = order;
    const int size = size_;
    size_ = 0;
    if (size > 0) resize(size);
}

void GridMesh::resize(int size) {
    if (size == size_) return;
    std::vector<glm::vec2> coordinates;
    coordinates.reserve(static_cast<std::size_t>(size) * size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) coordinates.push_back(glm::vec2(gridVertexCoordinate(i, j, size)));
    std::vector<GLuint> patches;
    patches.reserve(static_cast<std::size_t>(size - 1) * (size - 1) * 4);
    const auto at = [size](int x, int y) { return static_cast<GLuint>(y * size + x); };
    const auto add = [&](int i, int j) { patches.insert(patches.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}); };
    const int n = size - 1;  // patches per side
    rings_.clear();
    blocks_.clear();
    shown_.clear();
    if (order_ == PatchOrder::Rows) {
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) add(i, j);
        blocks_ = rowBlocks(size);
    } else {
        const std::vector<std::vector<PatchBlock>> blocks = ringBlocks(size);
        rings_ = ringsOf(blocks, size);
        for (const std::vector<PatchBlock>& ring : blocks)
            for (const PatchBlock& b : ring)
                for (int j = b.from.y; j < b.to.y; ++j)
                    for (int i = b.from.x; i < b.to.x; ++i) add(i, j);
        blocks_ = nearFirstBlocks(size);
    }
    vertices_ = gl::Buffer();
    indices_ = gl::Buffer();
    for (int k = 0; k < 3; ++k) {
        coarseIndices_[k] = gl::Buffer();
        coarsePatchCount_[k] = 0;
    }
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
    patchCount_ = (size - 1) * (size - 1);
    const int stride = stride_;
    stride_ = 1;
    setStride(stride);
}

void GridMesh::setStride(int stride) {
    if (stride != 1 && stride != 2 && stride != 4 && stride != 8) throw std::invalid_argument("GridMesh: stride 1, 2, 4 or 8");
    if (size_ < 2) {
        stride_ = stride;
        return;
    }
    if (stride == stride_) return;
    stride_ = stride;
    shown_.clear();
    if (stride == 1) {
        glVertexArrayElementBuffer(vertexArray_.id(), indices_.id());
        patchCount_ = (size_ - 1) * (size_ - 1);
        return;
    }
    const int k = stride == 2 ? 0 : stride == 4 ? 1 : 2;
    if (coarsePatchCount_[k] == 0) {
        const std::vector<GLuint> patches = stridePatches(size_, stride);
        glNamedBufferStorage(coarseIndices_[k].id(), static_cast<GLsizeiptr>(patches.size() * sizeof(GLuint)),
                             patches.data(), 0);
        coarseIndices_[k].label((label_ + " grid patches, stride " + std::to_string(stride)).c_str());
        coarsePatchCount_[k] = static_cast<int>(patches.size() / 4);
    }
    glVertexArrayElementBuffer(vertexArray_.id(), coarseIndices_[k].id());
    patchCount_ = coarsePatchCount_[k];
}

GridBlock makeGridBlock(const GridProjection& projection, int exponent, const glm::dvec3& cameraPosition,
                        double radius, int pointsPerSide, int stride) {
    GridBlock b{};
    for (int i = 0; i < 3; ++i) b.worldFromGridColumns[i] = glm::dvec4(projection.worldFromGrid[i], 0.0);
    b.cameraPositionAndRadius = glm::dvec4(cameraPosition, radius);
    b.zShift = projection.zShift;
    b.exponent = exponent;
    b.pointsPerSide = pointsPerSide;
    b.stride = stride;
    return b;
}

GridMesh::GridMesh(std::string label, PatchOrder order)
    : label_(std::move(label)), order_(order), splitDraws_(gl::softwareRenderer(gl::rendererDescription())) {
    glNamedBufferStorage(block_.id(), sizeof(GridBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    block_.label((label_ + " GridBlock").c_str());
}

void GridMesh::setProjection(const GridBlock& block) {
    glNamedBufferSubData(block_.id(), 0, sizeof block, &block);
}

void GridMesh::bindBlock() const { glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_GRID, block_.id()); }

void GridMesh::showBlocks(std::vector<bool> shown) {
    if (!shown.empty() && shown.size() != blocks().size()) throw std::invalid_argument("GridMesh::showBlocks: one flag per block");
    shown_ = std::move(shown);
}

std::vector<glm::ivec2> GridMesh::runs(int first, int count) const {
    if (shown_.empty() || blocks().empty()) return {glm::ivec2(first, count)};
    std::vector<glm::ivec2> runs;
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        if (!shown_[b]) continue;
        const int from = std::max(first, blocks_[b].firstPatch);
        const int to = std::min(first + count, blocks_[b].firstPatch + blocks_[b].patchCount);
        if (from >= to) continue;
        if (!runs.empty() && runs.back().x + runs.back().y == from)
            runs.back().y += to - from;  // the previous block's run goes on
        else
            runs.push_back(glm::ivec2(from, to - from));
    }
    return runs;
}

int GridMesh::patchesDrawn(int first, int count) const {
    int drawn = 0;
    for (const glm::ivec2& run : runs(first, count)) drawn += run.y;
    return drawn;
}

void GridMesh::draw(int first, int count) const {
    if (count <= 0) return;
    bindBlock();
    glBindVertexArray(vertexArray_.id());
    glPatchParameteri(GL_PATCH_VERTICES, 4);
    const auto offset = [](int patch) { return reinterpret_cast<const void*>(static_cast<std::uintptr_t>(patch) * 4 * sizeof(GLuint)); };
    std::vector<GLsizei> counts;
    std::vector<const void*> offsets;
    const int longest = splitDraws_ ? kPatchesPerSoftwareDraw : count;
    for (const glm::ivec2& run : runs(first, count))
        for (int patch = run.x; patch < run.x + run.y; patch += longest) {
            counts.push_back(4 * std::min(longest, run.x + run.y - patch));
            offsets.push_back(offset(patch));
        }
    if (counts.empty()) return;
    glMultiDrawElements(GL_PATCHES, counts.data(), GL_UNSIGNED_INT, offsets.data(), static_cast<GLsizei>(counts.size()));
}

}  // namespace planet
