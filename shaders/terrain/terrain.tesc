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

// The most the terrain's chords may sag below the sphere, m. The G-buffer is formed at the mesh's
// point, so a chord's sag moves what a pixel shows sideways (sag x tan of the incidence); at
// the grid's cells that was under a kilometre, and with the grid's stride from space
// (src/grid/grid_stride.h) patches of 8 cells at level 1 sagged 38 km at 160x90 and the land came
// out 2.3 % darker. With segments under 1 km of sag, stride 8 against stride 1 there: mean
// luminance +0.01 %, mean relative error 0.02 %.
const float TERRAIN_MAX_SAG_M = 1000.0;
in vec2 vGrid[];
in ivec2 vPoint[];
in vec3 vGround[];
in vec3 vLow[];
in vec3 vHigh[];
out vec2 tcGrid[];
out ivec2 tcPoint[];

#include "terrain/terrain_block.glsl"

// A stride's patch edge (src/grid/grid_stride.h) spans several cells, and the tessellator splits
// it evenly in grid coordinates, which the projection (Eq. 2-4) does not map evenly onto the
// sphere: near the grid's edge, at the horizon, its cells grow fast. So the edge takes as many
// segments per cell as its neediest cell would ask for on its own (on the sea-level sphere: the
// heights matter to a level far less than to a patch's corners), and each segment is no worse
// than a stride-1 cell's; the end-to-end chord under-counted them, and the limb from orbit
// receded by a pixel at 160x90. Depends on the edge's grid points only: neighbours agree.
float strideEdgeLevel(ivec2 a, ivec2 b) {
    int cells = max(abs(b.x - a.x), abs(b.y - a.y));
    double radius = gridSphereRadius();
    float need = 0.0;
    vec3 previous = gridLinePoint(a, b, 0, cells, radius);
    for (int c = 1; c <= cells; ++c) {
        vec3 next = gridLinePoint(a, b, c, cells, radius);
        need = max(need, edgeSegments(previous, next, terrainTargetEdgePixels, TERRAIN_MAX_SAG_M));
        need = max(need, limbCellSegments(previous, next));
        previous = next;
    }
    return clamp(need * float(cells), 1.0, MAX_TESSELLATION_LEVEL);
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
    if (outsideFrustum(corners)) {
        cullPatch();
        return;
    }
    if (grid.stride == 1) {
        setQuadLevels(ground, terrainTargetEdgePixels, TERRAIN_MAX_SAG_M);
        return;
    }
    setQuadLevelsFromEdges(strideEdgeLevel(vPoint[0], vPoint[3]), strideEdgeLevel(vPoint[0], vPoint[1]),
                           strideEdgeLevel(vPoint[1], vPoint[2]), strideEdgeLevel(vPoint[3], vPoint[2]));
}
