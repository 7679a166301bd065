// The height field near the camera on a grid (shaders/terrain/near_height_grid.glsl): the ground's
// material read the near field (terrainHeightNearGrad, every mountain octave's noise with its gradient) at
// every pixel within the ground detail's reach, a third of the material's time at the `ground` view
// (38 of 112 ms on llvmpipe at 1280x720). Here it is evaluated once at N x N points on the plane
// tangent to the planet at an origin near the camera (terrain/near_height_grid.comp) and read back
// bilinearly: a still camera, or one moving within kRoamM of the origin, evaluates nothing more. A
// camera that moves kStartM from the origin starts the next grid, at its foot, in a second texture,
// kPoints / kSlices rows a frame (the whole grid at once cost a 55 ms frame on llvmpipe, a hitch every
// 500 m of a low flight), and the material reads the next grid from the frame that completes it. A
// camera that leaves kRoamM behind before that (a jump, or over ~900 m/s at 30 frames a second), a
// change of the terrain's shape or of the continents under the origin, or a reloaded program evaluate
// the grid they need at once.
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
    // How far from the origin the camera starts the next grid at its foot, m, and in how many frames
    // that grid is evaluated (kPoints / kSlices rows each).
    static constexpr double kStartM = 250.0;
    static constexpr int kSlices = 8;
    static double spacingM() { return 2.0 * kHalfExtentM / (kPoints - 1); }

    explicit NearHeightGrid(const gl::ShaderSources& sources);

    // Before the frame: decides what this frame evaluates (the whole grid where there is none yet, the
    // camera left its roam with no next grid near it, or the shape or the continents under the origin
    // changed; else the next grid's next slice, started where the camera is kStartM from the origin, or
    // its remaining rows where the camera left the roam), and uploads the block of the grid the frame
    // reads (the next one from the frame that completes it) with the origin from this camera.
    void prepare(const TerrainShape& shape, const noise::CubeMap& continents, const Camera& camera,
                 double planetRadiusM);
    // Evaluates what prepare() decided (compute dispatches; the TerrainBlock must be bound), then binds
    // the block and the grid for the material. `frameNear`: the frame's TerrainNearBlock, bound again
    // after the dispatches' own (formed at the grid's origin).
    void form(const gl::Buffer& frameNear);
    // How many grids have been evaluated whole, at once or over frames (tests: a still camera evaluates one).
    int evaluations() const { return evaluations_; }
    // The rows evaluated in the last frame, of kPoints (tests: a moving camera's frames stay under a slice).
    int lastRowsFormed() const { return lastRows_; }
    // The grid the material reads, and its origin (world, m).
    const gl::Texture& texture() const { return grids_[current_].texels; }
    glm::dvec3 origin() const { return grids_[current_].origin; }
    gl::HotProgram& program() { return program_; }

private:
    struct Grid {
        gl::Texture texels{GL_TEXTURE_2D};  // RGBA32F N x N: height, gradient
        gl::Buffer near;                    // TerrainNear formed at the origin, for the dispatches
        gl::Buffer block;                   // its NearHeightGridBlock, for the dispatches (the origin unused)
        glm::dvec3 origin{0.0};             // world, m, on the planet-radius sphere
        glm::vec4 continent{0.0f};          // the near field's continent term at the origin when started
        int rows = 0;                       // rows evaluated so far (kPoints: whole)
    };
    // Makes `g` a grid at `origin` with no rows evaluated yet.
    void start(Grid& g, const glm::dvec3& origin, const TerrainShape& shape, const noise::CubeMap& continents,
               double planetRadiusM);

    gl::HotProgram program_;
    Grid grids_[2];
    int current_ = 0;                  // the grid the material reads; the other is the next, while one is due
    bool nextDue_ = false;             // the next grid is being evaluated
    int rowsNow_[2] = {0, 0};          // rows this frame evaluates in each grid
    bool swapNow_ = false;             // this frame completes the next grid, and the material reads it
    gl::Buffer block_;                 // NearHeightGridBlock of the grid read, every frame
    bool valid_ = false;
    TerrainShape shape_{};
    GLuint programId_ = 0;             // the program that evaluated it (hot reload: again)
    int evaluations_ = 0;
    int lastRows_ = 0;
};

}  // namespace planet::terrain
