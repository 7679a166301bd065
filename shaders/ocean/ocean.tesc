// Ocean tessellation control (Michelic §3-4): culls patches outside a widened frustum,
// counting the highest crests and lowest troughs, and patches entirely over land (every
// fragment of them would be discarded: the ground there is above the highest crest), and
// sets levels from each edge's size on screen (grid/tessellation.glsl).
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "grid/tessellation.glsl"
#include "ocean/ocean_block.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/terrain_block.glsl"

layout(vertices = 4) out;
in vec2 vGrid[];
in vec3 vCloudReflection[];
out vec2 tcGrid[];
out vec3 tcCloudReflection[];

// Whether the patch lies over land throughout (src/ocean/land_cull.h): the continent value at
// its centre, less the map's steepest slope times the patch's angular radius, above the value
// at which the ground surely stands above the highest crest. The radius is the farthest of the
// corners and the edges' midpoints on the grid (the grid's lines curve between vertices), times
// 1.25 for what lies between them.
bool overLand(dvec3 directions[4]) {
    if (ocean.landCulling == 0) return false;
    vec3 centre = normalize(vec3(directions[0] + directions[1] + directions[2] + directions[3]));
    float chord = 0.0;
    for (int i = 0; i < 4; ++i) {
        chord = max(chord, length(vec3(directions[i]) - centre));
        vec3 mid = vec3(gridDirection(mix(vGrid[i], vGrid[(i + 1) % 4], 0.5)));
        chord = max(chord, length(mid - centre));
    }
    float radius = 1.25 * 2.0 * asin(min(0.5 * chord, 1.0)) + 1e-6;
    float e = continentValue(centre, uContinents);
    return e - ocean.continentLipschitz * radius > ocean.patchLandContinent;
}

void main() {
    tcGrid[gl_InvocationID] = vGrid[gl_InvocationID];
    tcCloudReflection[gl_InvocationID] = vCloudReflection[gl_InvocationID];
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
    if (outsideFrustum(corners) || overLand(directions)) {
        cullPatch();
        return;
    }
    setQuadLevels(mean, ocean.targetEdgePixels);
}
