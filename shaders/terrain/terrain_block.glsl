// The terrain's parameters for every terrain stage and for the passes that read the sea
// floor (the ocean); mirror of src/terrain/terrain_block.h (std140). Include after
// terrain/height.glsl, which defines TerrainShape.
#include "common/bindings.glsl"

layout(std140, binding = BLOCK_TERRAIN) uniform TerrainBlock {
    TerrainShape terrainShape;      // the height field (terrain/height.glsl): heights, mountains
    vec3 terrainLowlandAlbedo;      // preset planet.albedo: the grass material's albedo
    float terrainTargetEdgePixels;  // triangle edge on screen the tessellation aims for
    int terrainHasOcean;            // 1: water below sea level; 0: dry basins (Mars)
    int terrainShadows;             // 1: the terrain casts shadows (terrain/terrain_shadow.glsl)
    float terrainMinReliefSlope;    // the least relief an edge seen grazing is split for (terrain/terrain.tesc)
    int terrainLightShafts;         // 1: the terrain's shadows in the air (atmosphere/interface.glsl)
    // The sea floor's dark depths not drawn where the sea covers them from above (terrain/
    // terrain.tesc; src/terrain/terrain_block.h): below this continent value, by the map's slope bound.
    float terrainPatchDarkContinent;
    float terrainContinentLipschitz;
    int terrainDarkFloorCulling;    // 0: off
    float terrainContinentMaxRadius;  // rad: the continents' maxima bound patches up to this radius; 0: not read
};
// The height field near the camera, formed in double each frame (terrain/height.glsl
// TerrainNear; C++: terrain::makeTerrainNear).
layout(std140, binding = BLOCK_TERRAIN_NEAR) uniform TerrainNearBlock {
    TerrainNear terrainNear;
};
layout(binding = UNIT_CONTINENTS) uniform samplerCube uContinents;  // noise/continents.h, RGBA32F
