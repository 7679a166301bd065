// TerrainBlock: the terrain's parameters as the shaders read them (BLOCK_TERRAIN), C++
// mirror of shaders/terrain/terrain_block.glsl (std140, offsets static_asserted). Read by
// every terrain stage and by the ocean (the sea floor's height).
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "terrain/height.h"

namespace planet::terrain {

struct TerrainBlock {
    TerrainShape shape;               // the height field (terrain/height.glsl)
    glm::vec3 lowlandAlbedo;          // preset planet.albedo
    float targetEdgePixels;           // px
    int hasOcean;                     // 1: water below sea level
    int shadows;                      // 1: the terrain casts shadows (terrain/terrain_shadow.glsl)
    float minReliefSlope;             // preset terrain.min_relief_slope (terrain/terrain.tesc)
    int lightShafts;                  // 1: the terrain's shadows in the air (atmosphere/interface.glsl)
    // The sea floor's dark depths not drawn where the sea is drawn over them from above (issue 15;
    // src/ocean/land_cull.h, darkFloorContinentThreshold): a patch is dropped where its centre's
    // continent value plus continentLipschitz times its angular radius is below patchDarkContinent,
    // or, where its centre is dark, the same bound over its 4x4 parts (terrain/patch_continents.glsl).
    // Set each frame by the renderer after the ocean's prepare (TerrainPass::setDarkFloorCulling).
    float patchDarkContinent;
    float continentLipschitz;         // per radian, the ocean's (src/ocean/land_cull.h)
    int darkFloorCulling;             // 0: off (no sea drawn, the camera under it, tests)
    // The largest patch radius (rad) the continents' maxima bound (src/terrain/continent_bound.h):
    // the patch's bound is also the pyramid's over it; 0 (culling off): not read.
    float continentMaxRadius;
};
static_assert(offsetof(TerrainBlock, lowlandAlbedo) == 48 && offsetof(TerrainBlock, targetEdgePixels) == 60 &&
                  offsetof(TerrainBlock, hasOcean) == 64 &&
                  offsetof(TerrainBlock, shadows) == 68 && offsetof(TerrainBlock, minReliefSlope) == 72 &&
                  offsetof(TerrainBlock, lightShafts) == 76 && offsetof(TerrainBlock, patchDarkContinent) == 80 &&
                  offsetof(TerrainBlock, darkFloorCulling) == 88 &&
                  offsetof(TerrainBlock, continentMaxRadius) == 92 && sizeof(TerrainBlock) == 96,
              "TerrainBlock must match std140 (shaders/terrain/terrain_block.glsl)");

inline TerrainBlock makeTerrainBlock(const Scene& scene) {
    TerrainBlock b{};
    b.shape = makeTerrainShape(scene.terrain);
    b.lowlandAlbedo = glm::vec3(scene.planet.albedo);
    b.targetEdgePixels = static_cast<float>(scene.terrain.target_edge_px);
    b.minReliefSlope = static_cast<float>(scene.terrain.min_relief_slope);
    b.hasOcean = scene.terrain.ocean ? 1 : 0;
    b.shadows = scene.terrain.shadows ? 1 : 0;
    b.lightShafts = scene.terrain.light_shafts ? 1 : 0;
    return b;
}

}  // namespace planet::terrain
