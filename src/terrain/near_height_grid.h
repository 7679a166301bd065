// The height field near the camera on a grid (shaders/terrain/near_height_grid.glsl): the ground's
// material read the near field (terrainHeightNearGrad, every mountain octave's noise with its gradient) at
// every pixel within the ground detail's reach, a third of the material's time at the `ground` view
// (38 of 112 ms on llvmpipe at 1280x720). Here it is evaluated once at N x N points on the plane
// tangent to the planet at an origin near the camera (terrain/near_height_grid.comp) and read back
// bilinearly: a still camera, or one moving within kRoamM of the origin, evaluates nothing more; a
// camera that moves farther moves the origin, and a change of the terrain's shape or the continents
// under the origin evaluates the grid again.
#pragma once

#include <cstddef>
#include <cstring>

#include <glm/glm.hpp>

#include "gl/handle.h"
#include "gl/program.h"
#include "noise/continents.h"
#include "scene/camera.h"
#include "terrain/height.h"

namespace planet::terrain {

// NearHeightGridBlock (BLOCK_TERRAIN_NEAR_GRID, std140), as the shaders read it.
struct NearHeightGridBlock {
    glm::vec4 origin;  // xyz: the origin from the camera (m, world axes); w: the spacing, m
    glm::vec4 east;    // xyz: unit east at the origin; w: the planet radius, m
    glm::vec4 north;   // xyz: unit north; w: the points per side, N
    glm::vec4 up;      // xyz: unit up at the origin
};
static_assert(sizeof(NearHeightGridBlock) == 64, "NearHeightGridBlock must match std140");

class NearHeightGrid {
public:
    static constexpr int kPoints = 768;             // N: points per side, 9.9 m apart (shaders/terrain/near_height_grid.glsl)
    static constexpr double kHalfExtentM = 3800.0;  // from the origin to the grid's edge, m
    // How far the camera moves from the origin, m, before the grid moves: the detail's reach
    // (TERRAIN_NEAR_RANGE_M, 3 km) from anywhere within it stays inside the half extent.
    static constexpr double kRoamM = 500.0;
    static double spacingM() { return 2.0 * kHalfExtentM / (kPoints - 1); }

    explicit NearHeightGrid(const gl::ShaderSources& sources);

    // Before the frame: moves the origin where the camera has left its roam (or there is none yet),
    // marks the grid for evaluation where it moved or the shape or the continents under it changed,
    // and uploads the block with the origin from this camera.
    void prepare(const TerrainShape& shape, const noise::CubeMap& continents, const Camera& camera,
                 double planetRadiusM);
    // Evaluates the grid where prepare() marked it (a compute dispatch; the TerrainBlock must be
    // bound), then binds the block and the grid for the material. `frameNear`: the frame's
    // TerrainNearBlock, bound again after the dispatch's own (formed at the origin).
    void form(const gl::Buffer& frameNear);
    // How many times the grid has been evaluated (tests: a still camera evaluates it once).
    int evaluations() const { return evaluations_; }
    gl::HotProgram& program() { return program_; }

private:
    gl::HotProgram program_;
    gl::Texture grid_{GL_TEXTURE_2D};  // RGBA32F N x N: height, gradient
    gl::Buffer block_;                 // NearHeightGridBlock, every frame
    gl::Buffer originNear_;            // TerrainNear formed at the origin, for the dispatch
    bool valid_ = false;
    bool dirty_ = true;
    glm::dvec3 origin_{0.0};           // world, m, on the planet-radius sphere
    TerrainShape shape_{};
    glm::vec4 continent_{0.0f};        // the near field's continent term at the origin when evaluated
    GLuint programId_ = 0;             // the program that evaluated it (hot reload: again)
    int evaluations_ = 0;
};

}  // namespace planet::terrain
