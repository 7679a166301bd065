// Terrain height field, normal and material on the CPU: the very GLSL of
// shaders/terrain/height.glsl compiled as C++ in float (as noise/noise.h does for the noise),
// with the baked continents map (noise/continents.h) where the GPU has its samplerCube.
//
// Directions are unit vectors in the world frame (+Z north); heights in metres above sea
// level, in [-ocean_depth_m, max_height_m]. The GLSL names are the same. tests/
// test_terrain_height.cpp checks the properties and the GPU's values against these.
//
// HeightField bundles what the functions take (shape + continents map) and keeps it in
// step with TerrainParams; whoever needs terrain heights on the CPU owns one (the Session,
// for the camera's ground). It shares the map with the GPU's texture through one
// terrain::Continents (continents.h).
#pragma once

#include <filesystem>
#include <memory>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "noise/continents.h"
#include "terrain/terrain_params.h"

namespace planet::terrain {

class Continents;  // terrain/continents.h

// Material ids of terrainMaterial (the GLSL TERRAIN_MATERIAL_* constants; static_asserted equal).
enum class Material : int { SeaFloor = 0, Rock = 1, Snow = 2, Sand = 3, Grass = 4 };
inline constexpr int kMaterialCount = 5;

// TerrainParams in float, as the shader takes it (the mountains; the continents are in the
// map); mirror of the GLSL struct TerrainShape, laid out as std140 (48 bytes,
// static_asserted in height.cpp), so it can be copied into a uniform block as is.
struct TerrainShape {
    glm::vec4 mountainOffset;   // noise-space offset of the mountains (xyz), from the seed
    float maxHeight;            // m
    float oceanDepth;           // m
    float mountainFrequency;    // per planet radius
    float ridgedWeight;         // [0, 1]
    int mountainOctaves;        // noise layers, [0, 10]; 0: continents only
    float padding0 = 0.0f;
    float padding1 = 0.0f;
    float padding2 = 0.0f;
};

// The shape for a set of parameters. The seed picks the mountains' noise offset
// (noise::seedOffset, stream 1).
TerrainShape makeTerrainShape(const TerrainParams& params);

// What the continents map is baked from: seed, continent_frequency, continent_octaves,
// sea_fraction (the map's face size is continent_map_size).
noise::ContinentParams continentParams(const TerrainParams& params);

// Height above sea level, m. GLSL: terrainHeight(d, shape, continents).
float terrainHeight(glm::vec3 unitDirection, const TerrainShape& shape, const noise::CubeMap& continents);

// Height and its gradient with respect to the direction as a point in R^3 (only the
// tangential part means anything: m per radian). GLSL: terrainHeightGrad.
float terrainHeightGrad(glm::vec3 unitDirection, const TerrainShape& shape, const noise::CubeMap& continents,
                        glm::vec3& gradient);

// The highest the height field rises where the continent value is at most e (m; increasing
// in e). GLSL: terrainHeightBound.
float terrainHeightBound(const TerrainShape& shape, float e);

// Continent value in [-1, 1] (the map, filtered); land where above 0. GLSL: continentValue.
float continentValue(glm::vec3 unitDirection, const noise::CubeMap& continents);

// Unit surface normal of the terrain on a planet of radius planetRadius (m). GLSL: terrainNormal.
glm::vec3 terrainNormal(glm::vec3 unitDirection, const TerrainShape& shape, const noise::CubeMap& continents,
                        float planetRadius);

// What a pixel with a footprint sees (GLSL: terrainNormalFiltered): the mean height over the
// footprint, and the spreads (standard deviations) of height and slope under it that the
// filtered normal no longer shows.
struct FootprintSpread {
    float meanHeightM = 0.0f;    // m above sea level, the mean over the footprint
    float heightSpreadM = 0.0f;  // standard deviation of the height, m
    float slopeSpread = 0.0f;    // standard deviation of the slope (rise over run)
};

// The normal of the terrain's mean surface over a footprint of `footprintM` metres (0: the
// point's normal, terrainNormal, exactly). GLSL: terrainNormalFiltered.
glm::vec3 terrainNormalFiltered(glm::vec3 unitDirection, const TerrainShape& shape, const noise::CubeMap& continents,
                                float planetRadius, float footprintM, FootprintSpread& spread);

// The height field near a camera (GLSL: struct TerrainNear and terrainHeightNearGrad in
// terrain/height.glsl): the camera's place and each mountain octave's noise point there,
// formed in double, so that the shader evaluates the field from camera-relative points
// without float's half-metre rounding of directions. std140 (static_asserted in height.cpp).
struct TerrainNear {
    glm::vec4 cameraUp;             // xyz: unit direction to the camera; w: its distance from the centre, m
    glm::vec4 cameraPlace;          // xyz: the camera modulo TERRAIN_NEAR_WRAP_M, m; w: altitude above the radius, m
    glm::vec4 continent;            // x: continent value at the camera; yzw: its gradient per radian
    glm::vec4 octaveLattice[10];    // per mountain octave: lattice point (skewed, modulo 289)
    glm::vec4 octaveOffset[10];     // ... and the offset from it (unskewed)
    glm::vec4 patchLattice;         // the ground's patches' noise point at the camera: lattice point (skewed, modulo 289)
    glm::vec4 patchOffset;          // ... and the offset from it (unskewed)
};

// The near field for a camera at `cameraPosition` (m, world, from the planet centre) over a
// planet of `planetRadiusM`.
TerrainNear makeTerrainNear(const TerrainShape& shape, const noise::CubeMap& continents,
                            const glm::dvec3& cameraPosition, double planetRadiusM);

// Height and gradient at a camera-relative point from the near field. GLSL: terrainHeightNearGrad.
float terrainHeightNearGrad(glm::vec3 pointFromCamera, const TerrainNear& near, const TerrainShape& shape,
                            glm::vec3& gradient);

// Where the ray from the camera through `start` (camera-relative, near the surface) meets the
// height field; false where it does not converge there, and `hit` is then `start` moved along
// the vertical onto the height field. GLSL: terrainRayHitNear.
// The ground's dry and lush patches at the camera-relative point (GLSL terrainPatchesNear).
float terrainPatchesNear(glm::vec3 pointFromCamera, const TerrainNear& near, glm::vec3& gradient);
// The RMS of that field's slope along the ground, per m, which the detail divides by (GLSL TERRAIN_PATCH_SLOPE_RMS).
float terrainPatchSlopeRms();
bool terrainRayHitNear(glm::vec3 start, const TerrainNear& near, const TerrainShape& shape, glm::vec3& hit);

// The same search with at most `steps` Newton steps; with one, the step taken is trusted where the
// ray descends (what the ground detail uses). GLSL: terrainRayHitNearSteps.
bool terrainRayHitNearSteps(glm::vec3 start, const TerrainNear& near, const TerrainShape& shape, int steps,
                            glm::vec3& hit);

// terrainRayHitNearSteps's one step from `start` given the near field's height `h` and gradient
// there (terrainHeightNearGrad at start): the same step, no height evaluated.
// GLSL: terrainRayHitNearStepFrom (the ground's material, where one evaluation serves the
// normal and the step).
bool terrainRayHitNearStepFrom(glm::vec3 start, const TerrainNear& near, float h, glm::vec3 gradient,
                               glm::vec3& hit);

// Whether a footprint of `footprintM` shows every mountain octave whole, so that
// terrainNormalFiltered is terrainNormal exactly. GLSL: terrainFootprintShowsEveryOctave.
bool terrainFootprintShowsEveryOctave(const TerrainShape& shape, float footprintM, float planetRadius);

// How far from the camera the near field is used, m (TERRAIN_NEAR_RANGE_M).
float terrainNearRangeM();

// Camera-relative positions wrap every this many metres near the camera (TERRAIN_NEAR_WRAP_M).
float terrainNearWrapM();

// The terrain's height field on the CPU: the shape for one set of TerrainParams and the
// continents map, which it shares with the map's owner (terrain::Continents, continents.h):
// its own by default (the map from the cache under `cacheRoot`, or baked there), or one
// given, such as the session's, which the renderer shares too, so the process holds one map
// for the CPU and the GPU and loads it once.
class HeightField {
public:
    // A field with an owner of its own: for callers without a renderer (tests, sky-probe).
    explicit HeightField(std::filesystem::path cacheRoot = noise::defaultContinentsCacheRoot());
    // A field that shares `continents` (not null).
    explicit HeightField(std::shared_ptr<Continents> continents);

    // Shares `continents` (not null) from now on; the field is not ready() again until the
    // next update(), which takes the owner's map (loading it only if the owner must).
    void use(std::shared_ptr<Continents> continents);
    const std::shared_ptr<Continents>& source() const { return source_; }

    // Follows `params`: the shape at once; the map through the owner, which loads or bakes
    // only when a parameter of the bake (continentParams, continent_map_size) changed or it
    // has none yet (a stall of about a second at the default size). Returns true when the
    // field's map changed (also when another sharer of the owner brought it up to date).
    // Throws std::invalid_argument for parameters out of range.
    bool update(const TerrainParams& params);

    bool ready() const { return map_ != nullptr; }
    const TerrainParams& params() const { return params_; }
    const TerrainShape& shape() const { return shape_; }
    const noise::CubeMap& continents() const;  // empty before the first update
    // The map itself, the owner's object (null before the first update).
    const std::shared_ptr<const noise::CubeMap>& sharedContinents() const { return map_; }

    // terrainHeight, terrainHeightGrad, terrainNormal with this field's shape and map.
    // Throw std::logic_error before the first update().
    float height(glm::vec3 unitDirection) const;
    float heightGrad(glm::vec3 unitDirection, glm::vec3& gradient) const;
    glm::vec3 normal(glm::vec3 unitDirection, float planetRadius) const;

private:
    const noise::CubeMap& map() const;

    std::shared_ptr<Continents> source_;
    std::shared_ptr<const noise::CubeMap> map_;
    TerrainParams params_;
    TerrainShape shape_{};
};

// Height of the ground the camera stands on, m above sea level, under a world
// position: the terrain, or the mean sea surface (0; waves and ocean.sea_level_m
// are not counted) when the world has an ocean (field.params().ocean).
double surfaceHeightM(const HeightField& field, const glm::dvec3& position);

// Rise over run of a surface with this normal; 0 flat, 1 at 45 deg. GLSL: terrainSlope.
float terrainSlope(glm::vec3 normal, glm::vec3 up);

// Latitude of a direction, rad. GLSL: terrainLatitude.
float terrainLatitude(glm::vec3 unitDirection);

// Snow line at a latitude (rad), m above sea level. GLSL: terrainSnowLine.
float terrainSnowLine(float latitude);

// Material at a point (rule in shaders/terrain/height.glsl). GLSL: terrainMaterial.
Material terrainMaterial(float height, float slope, float latitude);

// Smooth blend weight of a material at a point; all materials' weights sum to 1.
// GLSL: terrainMaterialWeight.
float terrainMaterialWeight(Material material, float height, float slope, float latitude);

// The share of a footprint with these height and slope spreads (FootprintSpread) that a
// material covers; spreads 0 give terrainMaterialWeight. GLSL: terrainMaterialWeightSpread.
float terrainMaterialWeightSpread(Material material, float height, float slope, float latitude, float heightSpreadM,
                                  float slopeSpread);

// The moments of one mountain octave's value and gradient that the footprint filter assumes
// (GLSL TERRAIN_FBM_OCTAVE_* and TERRAIN_RIDGED_OCTAVE_*), for tests to re-measure.
struct OctaveMoments {
    float fbmMean, fbmVariance, fbmGradientMs, ridgedMean, ridgedVariance, ridgedGradientMs;
};
OctaveMoments mountainOctaveMoments();

// The rule's thresholds (GLSL constants of the same meaning), for tests and UI.
struct MaterialThresholds {
    float beachDepthM, beachHeightM, rockSlope, blendHeightM, blendSnowM, blendSlope;
};
MaterialThresholds materialThresholds();

}  // namespace planet::terrain
