// The continents map (noise/continents.h; Michelic §6) as one owned resource: the CPU copy
// (for the camera's ground and every CPU height query) and the GL cube map the terrain and
// the ocean sample, both made from the same bake, loaded from the cache or baked once per
// change of its parameters, for the whole process.
//
// The caller (Session::continents) owns one and shares it with the renderer, which brings it
// up to date in its prepare step, before any pass draws, and with the session's height field
// (terrain::HeightField), whichever asks first doing the one load. The CPU part needs no GL
// context (tests, sky-probe, the bake); only texture() does.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "gl/handle.h"
#include "noise/continents.h"
#include "scene/scene.h"

namespace planet::terrain {

// The continents map as the terrain samples it: an immutable RGBA32F cube map, GL_LINEAR,
// one level (the shaders read level 0), clamped to the edge (seamless filtering, which
// replaces the clamp, is the context's GL_TEXTURE_CUBE_MAP_SEAMLESS).
gl::Texture makeContinentsTexture(const noise::CubeMap& map);

class Continents {
public:
    // Needs no GL context: the texture is made on the first texture().
    explicit Continents(std::filesystem::path cacheRoot = noise::defaultContinentsCacheRoot());

    // Follows the bake's parameters (continentParams, continent_map_size): loads or bakes
    // the map only when they changed or there is none yet. Returns true when it did (the
    // GL texture is then remade on the next texture()). Throws std::invalid_argument for
    // parameters out of range. Needs no GL context.
    bool update(const TerrainParams& params);

    bool ready() const { return map_ != nullptr; }
    // The CPU map (shared, immutable); null before the first update().
    std::shared_ptr<const noise::CubeMap> map() const { return map_; }
    // The GL cube map of map(), uploaded on first use after each update(). Needs a GL
    // context; throws std::logic_error before the first update().
    const gl::Texture& texture();
    // Deletes the GL texture (the next texture() makes it again). Needs the GL context it
    // was made in: an owner that outlives the renderer's context (the session's) must have
    // its texture released while the context is there (the Renderer's destructor).
    void releaseTexture();
    // The map's maxima (src/terrain/continent_bound.h) as a cube map with a mip level per level,
    // built and uploaded on first use after each update(). Needs a GL context.
    const gl::Texture& maxTexture();
    // Whether the next texture() uploads a new map.
    bool textureStale() const { return textureStale_; }
    // How many times the map was loaded or baked (tests: once per change).
    int loads() const { return loads_; }

private:
    std::filesystem::path cacheRoot_;
    std::shared_ptr<const noise::CubeMap> map_;
    std::optional<noise::ContinentParams> params_;  // what map_ was made from
    int size_ = 0;
    std::optional<gl::Texture> texture_;  // made by texture(): creating a GL object needs a context
    std::optional<gl::Texture> maxTexture_;  // made by maxTexture()
    bool textureStale_ = true;
    int loads_ = 0;
};

}  // namespace planet::terrain
