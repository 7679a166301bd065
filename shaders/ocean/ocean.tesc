// Ocean tessellation control (Michelic §3-4): culls patches outside a widened frustum,
// counting the highest crests and lowest troughs, and patches entirely over land (every
// fragment of them would be discarded: the ground there is above the highest crest), and
// sets levels from each edge's size on screen (grid/tessellation.glsl), coarser where the
// waves cannot show (below).
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "grid/tessellation.glsl"
#include "ocean/ocean_block.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/terrain_block.glsl"

layout(vertices = 4) out;
in vec2 vGrid[];
in vec3 vGridReflection[];
out vec2 tcGrid[];
out vec3 tcGridReflection[];

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

// Where even the highest crest cannot show (ocean.maxWaveHeight, the sum of the amplitudes, and
// as much again sideways, under WAVE_VISIBLE_PIXELS on screen at the edge's nearer end), the
// mesh only has to follow the sphere, and the edge aims at up to OCEAN_FAR_EDGE_FACTOR times
// ocean.targetEdgePixels (continuously: the factor grows with the distance from where the waves
// fall under a quarter of a pixel). The normals, and so the light, come from the fragments' own
// waves (ocean/ocean.frag); a sphere's chord of 32 pixels at the limb from 400 km sags 0.03 pixel.
// A software renderer shades a 4x4 block of pixels for each triangle that touches it, so 8-pixel
// triangles cost it about three blocks' pixels for one triangle's (orbit, 1280x720: the ocean's
// fragments 158 -> 109 ms with 24-pixel triangles). Depends on the edge's two points only, as
// edgeLevel: neighbouring patches agree.
const float WAVE_VISIBLE_PIXELS = 0.25;
const float OCEAN_FAR_EDGE_FACTOR = 4.0;
float oceanEdgeLevel(vec3 a, vec3 b) {
    float nearest = max(min(length(a), length(b)), 1e-3);
    float wavePixels = 2.0 * ocean.maxWaveHeight / nearest / radiansPerPixel();
    float factor = clamp(WAVE_VISIBLE_PIXELS / max(wavePixels, 1e-9), 1.0, OCEAN_FAR_EDGE_FACTOR);
    return edgeLevel(a, b, ocean.targetEdgePixels * factor);
}

void main() {
    tcGrid[gl_InvocationID] = vGrid[gl_InvocationID];
    tcGridReflection[gl_InvocationID] = vGridReflection[gl_InvocationID];
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
    setQuadLevelsFromEdges(oceanEdgeLevel(mean[0], mean[3]), oceanEdgeLevel(mean[0], mean[1]),
                           oceanEdgeLevel(mean[1], mean[2]), oceanEdgeLevel(mean[3], mean[2]));
}
