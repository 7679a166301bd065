// Terrain tessellation control (Michelic §3): culls patches outside a slightly widened view
// frustum, counting the lowest sea floor and the highest possible terrain, and sets
// tessellation levels from each edge's size on screen (grid/tessellation.glsl), measured
// between the corners on the terrain itself: on a mountain the ground is near the camera
// even when the sea-level sphere is kilometres below it. The corners' points come from the
// vertex stage (terrain.vert), which evaluates each grid point's height once; here each
// corner of each patch was evaluated again, four heights per patch for points that four
// patches share (issue 15: 65 % of the pass's time at the ground view on llvmpipe).
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "grid/tessellation.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"  // TerrainShape, TerrainNear: the block's types

layout(vertices = 4) out;

// TERRAIN_MAX_SAG_M: grid/constants.glsl.
in vec2 vGrid[];
in ivec2 vPoint[];
in vec3 vGround[];
in vec3 vLow[];
in vec3 vHigh[];
in float vSlope[];
out vec2 tcGrid[];
out ivec2 tcPoint[];

#include "terrain/terrain_block.glsl"
#include "terrain/patch_continents.glsl"

// The relief an edge's segments can show (grid/tessellation.glsl's edgeSegmentsShown): the steeper
// of its ends' slopes, times TERRAIN_RELIEF_MARGIN for the steeper ground between them (the
// octaves finer than the edge each add as much slope as the coarse ones: lacunarity 2, gain 1/2;
// 2 let a distant range's silhouette slip: RenderTest.MountainSilhouetteMatchesTheCpuHeightField),
// at least the preset's terrain.min_relief_slope, at most 1 (an edge seen face on).
const float TERRAIN_RELIEF_MARGIN = 3.0;
float terrainEdgeLevel(int i, int j) {
    float relief = clamp(TERRAIN_RELIEF_MARGIN * max(vSlope[i], vSlope[j]), terrainMinReliefSlope, 1.0);
    return clamp(edgeSegmentsShown(vGround[i], vGround[j], terrainTargetEdgePixels, TERRAIN_MAX_SAG_M, relief), 1.0,
                 MAX_TESSELLATION_LEVEL);
}

// Whether the patch lies under the sea floor's dark depths throughout, where the sea is drawn over
// it from above (terrainDarkFloorCulling; src/ocean/land_cull.h): its centre's continent value plus
// the map's steepest slope times its angular radius (terrain/grid.glsl), or the map's maxima
// over it (src/terrain/continent_bound.h), below the value under
// which the ground is surely SEA_FLOOR_DARK_DEPTH_M under the sea (ocean/water.glsl). Its light
// through that much water is none, the ocean's water path there comes from the depth below the
// sea, and the passes after the ocean see the sea: not drawing it changes no pixel (tests), and
// spares the terrain, its shadow's samples and the surface light the sea floor seen from orbit.
bool underDarkSea() {
    if (terrainDarkFloorCulling == 0) return false;
    vec2 g[4] = vec2[4](vGrid[0], vGrid[1], vGrid[2], vGrid[3]);
    dvec3 d[4] = dvec3[4](gridDirection(g[0]), gridDirection(g[1]), gridDirection(g[2]), gridDirection(g[3]));
    vec3 centre;
    float radius = patchAngularRadius(g, d, centre);
    float e = continentValue(centre, uContinents);
    // The slope bound, or the continents' maxima over the patch where tighter (from orbit: the
    // slope bound over a patch hundreds of kilometres across says nothing).
    float bound = min(e + terrainContinentLipschitz * radius,
                      continentMaxWithin(centre, radius, terrainContinentMaxRadius));
    // A patch too large for that bound (from orbit) by its 4x4 parts, where its centre is dark
    // itself (terrain/patch_continents.glsl; a loop that other patches do not enter: land, the shelf).
    for (int k = 0; k < (bound >= terrainPatchDarkContinent && e < terrainPatchDarkContinent ? 1 : 0); ++k) {
        float lowest;
        patchContinentRange(g, radius, terrainContinentLipschitz, terrainContinentMaxRadius, lowest, bound);
    }
    return bound < terrainPatchDarkContinent;
}

void main() {
    tcGrid[gl_InvocationID] = vGrid[gl_InvocationID];
    tcPoint[gl_InvocationID] = vPoint[gl_InvocationID];
    if (gl_InvocationID != 0) return;

    vec3 ground[4];
    vec3 corners[8];
    for (int i = 0; i < 4; ++i) {
        ground[i] = vGround[i];
        corners[i] = vLow[i];
        corners[i + 4] = vHigh[i];
    }
    raiseOuterCorners(corners, patchBulgeM(ground, frame.planetRadius));
    if (outsideFrustum(corners) || underDarkSea()) {
        cullPatch();
        return;
    }
    if (grid.stride == 1) {
        setQuadLevelsFromEdges(terrainEdgeLevel(0, 3), terrainEdgeLevel(0, 1), terrainEdgeLevel(1, 2),
                               terrainEdgeLevel(3, 2));
        return;
    }
    float target = terrainTargetEdgePixels;
    setQuadLevelsFromEdges(strideEdgeLevel(vPoint[0], vPoint[3], target, TERRAIN_MAX_SAG_M),
                           strideEdgeLevel(vPoint[0], vPoint[1], target, TERRAIN_MAX_SAG_M),
                           strideEdgeLevel(vPoint[1], vPoint[2], target, TERRAIN_MAX_SAG_M),
                           strideEdgeLevel(vPoint[3], vPoint[2], target, TERRAIN_MAX_SAG_M));
}
