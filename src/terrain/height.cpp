// The shared terrain GLSL compiled as C++ in float (see height.h).
//
// shaders/noise/simplex.glsl and shaders/terrain/height.glsl are included here, in one
// translation unit, into namespace planet::terrain::glsl, the way noise/noise.cpp does:
// GLM's float types and functions supply the GLSL names and OUT(x) is x&. The GLSL's
// samplerCube is the CPU map (a const reference) and textureLod its seamless bilinear
// filter, noise::sampleContinents. (The noise functions are compiled a second time here,
// into this namespace; they are small.)
#include "terrain/height.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include <glm/glm.hpp>

#include "noise/noise.h"
#include "terrain/continents.h"

namespace planet::terrain {
namespace glsl {
#include "terrain/glsl_as_cpp.h"
#include "shaders/noise/simplex.glsl"
#include "shaders/terrain/height.glsl"
#undef OUT
}  // namespace glsl

// The C++ mirror is the GLSL struct itself, compiled here; both must keep the std140 layout.
static_assert(sizeof(glsl::TerrainShape) == 48 && sizeof(TerrainShape) == 48, "std140 size of TerrainShape");
static_assert(offsetof(TerrainShape, maxHeight) == 16 && offsetof(TerrainShape, mountainOctaves) == 32 &&
                  offsetof(glsl::TerrainShape, mountainOctaves) == 32,
              "std140 offsets of TerrainShape");
static_assert(int(Material::SeaFloor) == glsl::TERRAIN_MATERIAL_SEA_FLOOR &&
                  int(Material::Rock) == glsl::TERRAIN_MATERIAL_ROCK &&
                  int(Material::Snow) == glsl::TERRAIN_MATERIAL_SNOW &&
                  int(Material::Sand) == glsl::TERRAIN_MATERIAL_SAND &&
                  int(Material::Grass) == glsl::TERRAIN_MATERIAL_GRASS &&
                  kMaterialCount == glsl::TERRAIN_MATERIAL_COUNT,
              "material ids match the GLSL constants");

namespace {

glsl::TerrainShape toGlsl(const TerrainShape& s) {
    return glsl::TerrainShape{s.mountainOffset, s.maxHeight,       s.oceanDepth, s.mountainFrequency, s.ridgedWeight,
                              s.mountainOctaves, s.padding0,        s.padding1,   s.padding2};
}

}  // namespace

static_assert(sizeof(glsl::TerrainNear) == sizeof(TerrainNear) && sizeof(TerrainNear) == 25 * 16 &&
                  offsetof(TerrainNear, octaveLattice) == 48 && offsetof(TerrainNear, octaveOffset) == 208,
              "std140 layout of TerrainNear");

TerrainNear makeTerrainNear(const TerrainShape& shape, const noise::CubeMap& continents,
                            const glm::dvec3& cameraPosition, double planetRadiusM) {
    TerrainNear near{};
    const double distance = glm::length(cameraPosition);
    const glm::dvec3 up = distance > 0.0 ? cameraPosition / distance : glm::dvec3(0.0, 0.0, 1.0);
    near.cameraUp = glm::vec4(glm::vec3(up), static_cast<float>(distance));
    const double wrap = glsl::TERRAIN_NEAR_WRAP_M;
    const glm::dvec3 place = cameraPosition - wrap * glm::floor(cameraPosition / wrap);
    near.cameraPlace = glm::vec4(glm::vec3(place), static_cast<float>(distance - planetRadiusM));
    // The continents to first order: the value the GPU's bilinear filter gives at the camera
    // and the gradient of that filtered map (central differences 50 m apart, in double), not
    // the map's own gradient channel, which is the fBm's: beyond the camera the two part by
    // metres of height within a km where the bilinear facets and the fBm disagree.
    const glm::dvec3 east = glm::normalize(std::abs(up.z) < 0.9 ? glm::cross(glm::dvec3(0.0, 0.0, 1.0), up)
                                                                 : glm::cross(glm::dvec3(1.0, 0.0, 0.0), up));
    const glm::dvec3 north = glm::cross(up, east);
    const double step = 50.0 / planetRadiusM;  // rad
    auto value = [&](glm::dvec3 d) { return double(noise::sampleContinents(continents, glm::normalize(d)).x); };
    const glm::dvec3 gradient = east * ((value(up + step * east) - value(up - step * east)) / (2.0 * step)) +
                                north * ((value(up + step * north) - value(up - step * north)) / (2.0 * step));
    near.continent = glm::vec4(static_cast<float>(value(up)), glm::vec3(gradient));
    // Octave k's noise point 2^k (frequency * up + offset), split as simplexNoiseGrad splits
    // it (skew, floor, unskew), in double; the lattice point reduced modulo 289, where the
    // noise repeats. The same for the ground's patches, at the camera's position in their cells.
    const auto split = [](const glm::dvec3& p, glm::vec4& lattice, glm::vec4& offset) {
        const glm::dvec3 cell = glm::floor(p + (p.x + p.y + p.z) / 3.0);
        lattice = glm::vec4(glm::vec3(cell - 289.0 * glm::floor(cell / 289.0)), 0.0f);
        offset = glm::vec4(glm::vec3(p - cell + (cell.x + cell.y + cell.z) / 6.0), 0.0f);
    };
    const glm::dvec3 base = up * double(shape.mountainFrequency) + glm::dvec3(glm::vec3(shape.mountainOffset));
    double frequency = 1.0;
    for (int k = 0; k < 10; ++k, frequency *= 2.0) split(base * frequency, near.octaveLattice[k], near.octaveOffset[k]);
    split(cameraPosition / double(glsl::TERRAIN_PATCH_CELL_M), near.patchLattice, near.patchOffset);
    return near;
}

namespace {
glsl::TerrainNear toGlsl(const TerrainNear& n) {
    glsl::TerrainNear g{};
    g.cameraUp = n.cameraUp;
    g.cameraPlace = n.cameraPlace;
    g.continent = n.continent;
    for (int k = 0; k < 10; ++k) {
        g.octaveLattice[k] = n.octaveLattice[k];
        g.octaveOffset[k] = n.octaveOffset[k];
    }
    g.patchLattice = n.patchLattice;
    g.patchOffset = n.patchOffset;
    return g;
}
}  // namespace

float terrainHeightNearGrad(glm::vec3 pointFromCamera, const TerrainNear& near, const TerrainShape& shape,
                            glm::vec3& gradient) {
    return glsl::terrainHeightNearGrad(pointFromCamera, toGlsl(near), toGlsl(shape), gradient);
}

float terrainPatchesNear(glm::vec3 pointFromCamera, const TerrainNear& near, glm::vec3& gradient) {
    return glsl::terrainPatchesNear(pointFromCamera, toGlsl(near), gradient);
}

float terrainPatchSlopeRms() { return glsl::TERRAIN_PATCH_SLOPE_RMS; }

bool terrainRayHitNear(glm::vec3 start, const TerrainNear& near, const TerrainShape& shape, glm::vec3& hit) {
    return glsl::terrainRayHitNear(start, toGlsl(near), toGlsl(shape), hit);
}

bool terrainRayHitNearSteps(glm::vec3 start, const TerrainNear& near, const TerrainShape& shape, int steps,
                            glm::vec3& hit) {
    return glsl::terrainRayHitNearSteps(start, toGlsl(near), toGlsl(shape), steps, hit);
}

bool terrainRayHitNearStepFrom(glm::vec3 start, const TerrainNear& near, float h, glm::vec3 gradient,
                               glm::vec3& hit) {
    return glsl::terrainRayHitNearStepFrom(start, toGlsl(near), h, gradient, hit);
}

bool terrainFootprintShowsEveryOctave(const TerrainShape& shape, float footprintM, float planetRadius) {
    return glsl::terrainFootprintShowsEveryOctave(toGlsl(shape), footprintM, planetRadius);
}

float terrainNearRangeM() { return glsl::TERRAIN_NEAR_RANGE_M; }

float terrainNearWrapM() { return glsl::TERRAIN_NEAR_WRAP_M; }

TerrainShape makeTerrainShape(const TerrainParams& p) {
    TerrainShape s{};
    s.mountainOffset = glm::vec4(noise::seedOffset(p.seed, 1), 0.0f);
    s.maxHeight = static_cast<float>(p.max_height_m);
    s.oceanDepth = static_cast<float>(p.ocean_depth_m);
    s.mountainFrequency = static_cast<float>(p.mountain_frequency);
    s.ridgedWeight = static_cast<float>(p.ridged_weight);
    s.mountainOctaves = p.noise_octaves;
    return s;
}

noise::ContinentParams continentParams(const TerrainParams& p) {
    noise::ContinentParams c;
    c.seed = p.seed;
    c.frequency = p.continent_frequency;
    c.octaves = p.continent_octaves;
    c.seaFraction = p.sea_fraction;
    return c;
}

float terrainHeight(glm::vec3 d, const TerrainShape& shape, const noise::CubeMap& continents) {
    return glsl::terrainHeight(d, toGlsl(shape), continents);
}

float terrainHeightBound(const TerrainShape& shape, float e) { return glsl::terrainHeightBound(toGlsl(shape), e); }

float terrainHeightGrad(glm::vec3 d, const TerrainShape& shape, const noise::CubeMap& continents,
                        glm::vec3& gradient) {
    return glsl::terrainHeightGrad(d, toGlsl(shape), continents, gradient);
}

float continentValue(glm::vec3 d, const noise::CubeMap& continents) { return glsl::continentValue(d, continents); }

glm::vec3 terrainNormal(glm::vec3 d, const TerrainShape& shape, const noise::CubeMap& continents,
                        float planetRadius) {
    return glsl::terrainNormal(d, toGlsl(shape), continents, planetRadius);
}

glm::vec3 terrainNormalFiltered(glm::vec3 d, const TerrainShape& shape, const noise::CubeMap& continents,
                                float planetRadius, float footprintM, FootprintSpread& spread) {
    return glsl::terrainNormalFiltered(d, toGlsl(shape), continents, planetRadius, footprintM, spread.meanHeightM,
                                       spread.heightSpreadM, spread.slopeSpread);
}

float terrainSlope(glm::vec3 normal, glm::vec3 up) { return glsl::terrainSlope(normal, up); }

float terrainLatitude(glm::vec3 d) { return glsl::terrainLatitude(d); }

float terrainSnowLine(float latitude) { return glsl::terrainSnowLine(latitude); }

Material terrainMaterial(float height, float slope, float latitude) {
    return static_cast<Material>(glsl::terrainMaterial(height, slope, latitude));
}

float terrainMaterialWeight(Material material, float height, float slope, float latitude) {
    return glsl::terrainMaterialWeight(static_cast<int>(material), height, slope, latitude);
}

float terrainMaterialWeightSpread(Material material, float height, float slope, float latitude, float heightSpreadM,
                                  float slopeSpread) {
    return glsl::terrainMaterialWeightSpread(static_cast<int>(material), height, slope, latitude, heightSpreadM,
                                             slopeSpread);
}

OctaveMoments mountainOctaveMoments() {
    return {glsl::TERRAIN_FBM_OCTAVE_MEAN,    glsl::TERRAIN_FBM_OCTAVE_VARIANCE,    glsl::TERRAIN_FBM_OCTAVE_GRADIENT_MS,
            glsl::TERRAIN_RIDGED_OCTAVE_MEAN, glsl::TERRAIN_RIDGED_OCTAVE_VARIANCE, glsl::TERRAIN_RIDGED_OCTAVE_GRADIENT_MS};
}

MaterialThresholds materialThresholds() {
    return {glsl::TERRAIN_BEACH_DEPTH_M, glsl::TERRAIN_BEACH_HEIGHT_M, glsl::TERRAIN_ROCK_SLOPE,
            glsl::TERRAIN_BLEND_HEIGHT_M, glsl::TERRAIN_BLEND_SNOW_M, glsl::TERRAIN_BLEND_SLOPE};
}

// ------------------------------------------------------------------ HeightField

HeightField::HeightField(std::filesystem::path cacheRoot)
    : HeightField(std::make_shared<Continents>(std::move(cacheRoot))) {}

HeightField::HeightField(std::shared_ptr<Continents> continents) { use(std::move(continents)); }

void HeightField::use(std::shared_ptr<Continents> continents) {
    if (!continents) throw std::invalid_argument("terrain::HeightField::use: no continents");
    source_ = std::move(continents);
    map_.reset();
}

bool HeightField::update(const TerrainParams& params) {
    source_->update(params);  // first: it throws for parameters out of range
    params_ = params;
    shape_ = makeTerrainShape(params);
    if (map_ == source_->map()) return false;
    map_ = source_->map();
    return true;
}

const noise::CubeMap& HeightField::continents() const {
    static const noise::CubeMap kEmpty;
    return map_ ? *map_ : kEmpty;
}

const noise::CubeMap& HeightField::map() const {
    if (!ready()) throw std::logic_error("terrain::HeightField used before update()");
    return *map_;
}

float HeightField::height(glm::vec3 d) const { return terrainHeight(d, shape_, map()); }

float HeightField::heightGrad(glm::vec3 d, glm::vec3& gradient) const {
    return terrainHeightGrad(d, shape_, map(), gradient);
}

glm::vec3 HeightField::normal(glm::vec3 d, float planetRadius) const {
    return terrainNormal(d, shape_, map(), planetRadius);
}

double surfaceHeightM(const HeightField& field, const glm::dvec3& position) {
    const double length = glm::length(position);
    if (!(length > 0.0)) return 0.0;
    const double height = field.height(glm::vec3(position / length));
    return field.params().ocean ? std::max(0.0, height) : height;
}

}  // namespace planet::terrain
