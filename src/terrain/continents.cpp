#include "terrain/continents.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "terrain/continent_bound.h"
#include "terrain/height.h"

namespace planet::terrain {

gl::Texture makeContinentsTexture(const noise::CubeMap& map) {
    const int n = map.size;
    gl::Texture texture(GL_TEXTURE_CUBE_MAP);
    glTextureStorage2D(texture.id(), 1, GL_RGBA32F, n, n);
    for (int face = 0; face < 6; ++face)  // DSA: a cube map's faces are layers 0..5 in GL's face order
        glTextureSubImage3D(texture.id(), 0, 0, 0, face, n, n, 1, GL_RGBA, GL_FLOAT, &map.at(face, 0, 0));
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(texture.id(), wrap, GL_CLAMP_TO_EDGE);
    texture.label("continents " + std::to_string(n) + "^2 x 6");
    return texture;
}

Continents::Continents(std::filesystem::path cacheRoot) : cacheRoot_(std::move(cacheRoot)) {}

bool Continents::update(const TerrainParams& params) {
    const noise::ContinentParams wanted = continentParams(params);
    if (map_ && params_ == wanted && size_ == params.continent_map_size) return false;
    map_ = std::make_shared<const noise::CubeMap>(
        noise::loadOrBakeContinents(wanted, params.continent_map_size, cacheRoot_));
    params_ = wanted;
    size_ = params.continent_map_size;
    textureStale_ = true;
    maxTexture_.reset();
    ++loads_;
    return true;
}

const gl::Texture& Continents::texture() {
    if (!map_) throw std::logic_error("terrain::Continents::texture() before update()");
    if (textureStale_ || !texture_) {
        texture_ = makeContinentsTexture(*map_);
        textureStale_ = false;
    }
    return *texture_;
}

const gl::Texture& Continents::maxTexture() {
    if (!map_) throw std::logic_error("terrain::Continents::maxTexture() before update()");
    if (!maxTexture_) maxTexture_ = makeContinentMaxTexture(buildContinentMaxPyramid(*map_));
    return *maxTexture_;
}

void Continents::releaseTexture() {
    texture_.reset();
    maxTexture_.reset();
    textureStale_ = true;
}

}  // namespace planet::terrain
