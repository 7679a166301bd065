// The terrain pass: Michelic's persistent projected grid (src/grid), tessellated
// on the GPU and displaced by the shared height function (terrain/height.glsl),
// written into the G-buffer like any surface.
//
// The continents come from a cube map baked once (noise/continents.h; Michelic §6),
// loaded from the cache or baked when the pass first draws and again whenever a
// parameter of the bake changes (a stall: about a second at the default size), and
// sampled as an RGBA32F samplerCube with GL_LINEAR and seamless cube map filtering.
//
//   terrain.vert  grid coordinates of the N x N vertices ((N-1)^2 quad patches)
//   terrain.tesc  frustum culling with the highest terrain, levels from edge size on screen
//   terrain.tese  grid -> sphere direction (double) -> height -> camera-relative position
//   terrain.frag  per-pixel normal, material, albedo
//
// The grid follows a projection anchor with hysteresis (updateAnchor), so
// vertices stay put while the camera moves a little: no swimming.
#pragma once

#include <filesystem>
#include <optional>

#include "gl/handle.h"
#include "gl/program.h"
#include "grid/grid_mesh.h"
#include "grid/projected_grid.h"
#include "noise/continents.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace planet {

// The continents map as the terrain samples it: an immutable RGBA32F cube map, GL_LINEAR,
// one level (the shaders read level 0), clamped to the edge (seamless filtering, which
// replaces the clamp, is the context's GL_TEXTURE_CUBE_MAP_SEAMLESS, enabled by draw()).
gl::Texture makeContinentsTexture(const noise::CubeMap& map);

class TerrainPass {
public:
    // The continents map is cached under `continentsCache`.
    explicit TerrainPass(const gl::ShaderSources& sources,
                         std::filesystem::path continentsCache = noise::defaultContinentsCacheRoot());

    // Draws into the bound G-buffer (depth test on, reversed-Z).
    void draw(const Scene& scene, const Camera& camera);
    gl::HotProgram& program() { return program_; }
    // Binds what terrain/height.glsl needs, as of the last draw: TerrainBlock (uniform
    // binding 2) and the continents (texture unit 10). The ocean uses it for the sea floor.
    void bindHeightField() const;

private:
    // Uniform locations, looked up again only when hot reload replaced the program.
    struct Locations {
        GLuint program = 0;
        GridUniforms grid;
        GLint planetRadiusF, maxTerrainHeight,
            minTerrainHeight,
            targetEdgePixels, ocean, lowlandAlbedo;
    };
    const Locations& locations();
    void updateContinents(const TerrainParams& params);

    gl::HotProgram program_;
    GridMesh mesh_{"terrain"};
    gl::Buffer shape_;
    std::filesystem::path continentsCache_;
    gl::Texture continents_{GL_TEXTURE_CUBE_MAP};  // RGBA32F: elevation, gradient (noise/continents.h)
    std::optional<noise::ContinentParams> continentsBaked_;  // what continents_ holds (none yet: nullopt)
    int continentsSize_ = 0;
    GridParams grid_;
    GridAnchor anchor_;
    Locations locations_;
};

}  // namespace planet
