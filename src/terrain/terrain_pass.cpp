#include "terrain/terrain_pass.h"

#include <string>
#include <utility>
#include <vector>

#include "terrain/height.h"

namespace planet {

namespace {
constexpr GLuint kTerrainShapeBinding = 2;
constexpr GLuint kContinentsUnit = 10;  // layout(binding = 10) uContinents in terrain.tese / terrain.frag
}  // namespace

TerrainPass::TerrainPass(const gl::ShaderSources& sources, std::filesystem::path continentsCache)
    : program_(sources, gl::ProgramDesc{"terrain",
                                        {"terrain/terrain.vert", "terrain/terrain.tesc", "terrain/terrain.tese",
                                         "terrain/terrain.frag"}}),
      continentsCache_(std::move(continentsCache)) {
    glNamedBufferStorage(shape_.id(), sizeof(terrain::TerrainShape), nullptr, GL_DYNAMIC_STORAGE_BIT);
    shape_.label("TerrainShape");
}

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

void TerrainPass::updateContinents(const TerrainParams& params) {
    const noise::ContinentParams wanted = terrain::continentParams(params);
    if (continentsBaked_ == wanted && continentsSize_ == params.continent_map_size) return;
    continents_ = makeContinentsTexture(noise::loadOrBakeContinents(wanted, params.continent_map_size, continentsCache_));
    continentsBaked_ = wanted;
    continentsSize_ = params.continent_map_size;
}

const TerrainPass::Locations& TerrainPass::locations() {
    const GLuint p = program_.id();
    if (locations_.program == p) return locations_;
    auto at = [p](const char* name) { return glGetUniformLocation(p, name); };
    locations_ = {p,
                  GridUniforms::lookUp(p),
                  at("uPlanetRadiusF"),
                  at("uMaxTerrainHeight"),
                  at("uMinTerrainHeight"),
                  at("uTargetEdgePixels"),
                  at("uOcean"),
                  at("uLowlandAlbedo")};
    return locations_;
}

void TerrainPass::draw(const Scene& scene, const Camera& camera) {
    grid_.size = scene.terrain.grid_size;
    grid_.exponent = scene.terrain.grid_exponent == 2 ? 2 : 4;  // Eq. 2 is defined for these two
    grid_.hysteresisFraction = scene.terrain.grid_hysteresis;
    mesh_.resize(grid_.size);
    const double radius = scene.planetRadiusM();
    const double maxHeight = scene.terrain.max_height_m;
    updateAnchor(anchor_, camera, anchorThresholdM(grid_, camera.altitude(radius)), false);
    const GridProjection projection = gridProjection(anchor_, radius, maxHeight);

    const terrain::TerrainShape shape = terrain::makeTerrainShape(scene.terrain);
    glNamedBufferSubData(shape_.id(), 0, sizeof shape, &shape);
    glBindBufferBase(GL_UNIFORM_BUFFER, kTerrainShapeBinding, shape_.id());
    updateContinents(scene.terrain);
    glBindTextureUnit(kContinentsUnit, continents_.id());
    // Filter across cube faces as sampleContinents does (global state; harmless to the other passes).
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

    const Locations& l = locations();
    const GLuint p = l.program;
    l.grid.set(p, projection, grid_.exponent, camera.position, radius);
    glProgramUniform1f(p, l.planetRadiusF, static_cast<float>(radius));
    glProgramUniform1f(p, l.maxTerrainHeight, static_cast<float>(maxHeight));
    glProgramUniform1f(p, l.minTerrainHeight, static_cast<float>(-scene.terrain.ocean_depth_m));
    glProgramUniform1f(p, l.targetEdgePixels, static_cast<float>(scene.terrain.target_edge_px));
    glProgramUniform1i(p, l.ocean, scene.terrain.ocean ? 1 : 0);
    const glm::vec3 lowland(scene.planet.albedo);
    glProgramUniform3fv(p, l.lowlandAlbedo, 1, &lowland.x);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reversed-Z
    glDepthMask(GL_TRUE);
    glUseProgram(p);
    mesh_.draw();
    glDisable(GL_DEPTH_TEST);
}

void TerrainPass::bindHeightField() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, kTerrainShapeBinding, shape_.id());
    glBindTextureUnit(kContinentsUnit, continents_.id());
}

}  // namespace planet
