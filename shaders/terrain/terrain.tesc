// Terrain tessellation control (Michelic §3): culls patches outside a slightly widened view
// frustum, counting the lowest sea floor and the highest possible terrain, and sets
// tessellation levels from each edge's size on screen (grid/tessellation.glsl).
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "grid/tessellation.glsl"

layout(vertices = 4) out;
in vec2 vGrid[];
out vec2 tcGrid[];

uniform float uMaxTerrainHeight;    // m above sea level
uniform float uMinTerrainHeight;    // m, the deepest sea floor (<= 0)
uniform float uTargetEdgePixels;    // wanted triangle edge length on screen

void main() {
    tcGrid[gl_InvocationID] = vGrid[gl_InvocationID];
    if (gl_InvocationID != 0) return;

    vec3 seaLevel[4];
    vec3 corners[8];
    for (int i = 0; i < 4; ++i) {
        dvec3 d = gridDirection(vGrid[i]);
        seaLevel[i] = cameraRelative(d, uPlanetRadius);
        corners[i] = cameraRelative(d, uPlanetRadius + double(uMinTerrainHeight));
        corners[i + 4] = cameraRelative(d, uPlanetRadius + double(uMaxTerrainHeight));
    }
    if (outsideFrustum(corners)) {
        cullPatch();
        return;
    }
    setQuadLevels(seaLevel, uTargetEdgePixels);
}
