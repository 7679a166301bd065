// Ocean tessellation control (Michelic §3-4): culls patches outside a widened frustum,
// counting the highest crests and lowest troughs, and patches entirely over land (every
// fragment of them would be discarded: the ground there is above the highest crest), and
// sets levels from each edge's size on screen (grid/tessellation.glsl), coarser where the
// waves cannot show (below).
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "grid/tessellation.glsl"
#include "ocean/ocean_block.glsl"
#include "ocean/edge_target.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/terrain_block.glsl"

layout(vertices = 4) out;
in vec2 vGrid[];
in ivec2 vPoint[];
out vec2 tcGrid[];
out ivec2 tcPoint[];

// Whether the patch lies over land throughout (src/ocean/land_cull.h): the continent value at
// its centre, less the map's steepest slope times the patch's angular radius (terrain/grid.glsl),
// above the value at which the ground surely stands above the highest crest.
bool overLand(dvec3 directions[4]) {
    if (ocean.landCulling == 0) return false;
    vec2 g[4] = vec2[4](vGrid[0], vGrid[1], vGrid[2], vGrid[3]);
    vec3 centre;
    float radius = patchAngularRadius(g, directions, centre);
    float e = continentValue(centre, uContinents);
    return e - ocean.continentLipschitz * radius > ocean.patchLandContinent;
}

// The edge's level for the target at its nearer end (ocean/edge_target.glsl). Depends on the
// edge's two points only, as edgeLevel: neighbouring patches agree.
// No sag bound in metres: far away ocean.frag takes the sphere itself, not the chord.
const float OCEAN_MAX_SAG_M = 1.0e30;
float oceanEdgeLevel(vec3 a, vec3 b) {
    return edgeLevel(a, b, oceanEdgeTargetPixels(max(min(length(a), length(b)), 1e-3)), OCEAN_MAX_SAG_M);
}

// A stride's patch edge (grid/tessellation.glsl's strideEdgeLevel) at the target of its nearer
// end: the target grows with distance, so no cell along it gets a larger one than its own.
float oceanStrideEdgeLevel(vec3 corners[4], int i, int j) {
    float nearest = max(min(length(corners[i]), length(corners[j])), 1e-3);
    return strideEdgeLevel(vPoint[i], vPoint[j], oceanEdgeTargetPixels(nearest), OCEAN_MAX_SAG_M);
}

void main() {
    tcGrid[gl_InvocationID] = vGrid[gl_InvocationID];
    tcPoint[gl_InvocationID] = vPoint[gl_InvocationID];
    if (gl_InvocationID != 0) return;
    vec3 mean[4];
    vec3 corners[8];
    dvec3 directions[4];
    for (int i = 0; i < 4; ++i) {
        dvec3 d = gridDirection(vGrid[i]);
        directions[i] = d;
        mean[i] = cameraRelative(d, gridSphereRadius());
        corners[i] = cameraRelative(d, gridSphereRadius() - double(ocean.maxWaveHeight));
        corners[i + 4] = cameraRelative(d, gridSphereRadius() + double(ocean.maxWaveHeight));
    }
    raiseOuterCorners(corners, patchBulgeM(mean, float(gridSphereRadius())));
    if (outsideFrustum(corners) || overLand(directions)) {
        cullPatch();
        return;
    }
    if (grid.stride == 1)
        setQuadLevelsFromEdges(oceanEdgeLevel(mean[0], mean[3]), oceanEdgeLevel(mean[0], mean[1]),
                               oceanEdgeLevel(mean[1], mean[2]), oceanEdgeLevel(mean[3], mean[2]));
    else
        setQuadLevelsFromEdges(oceanStrideEdgeLevel(mean, 0, 3), oceanStrideEdgeLevel(mean, 0, 1),
                               oceanStrideEdgeLevel(mean, 1, 2), oceanStrideEdgeLevel(mean, 3, 2));
}
