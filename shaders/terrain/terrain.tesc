// Terrain tessellation control (Michelic §3): culls patches outside a slightly widened view
// frustum, counting the lowest sea floor and the highest possible terrain, and sets
// tessellation levels from each edge's size on screen (grid/tessellation.glsl), measured
// between the corners on the terrain itself: on a mountain the ground is near the camera
// even when the sea-level sphere is kilometres below it.
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "grid/tessellation.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"

layout(vertices = 4) out;
in vec2 vGrid[];
out vec2 tcGrid[];

#include "terrain/terrain_block.glsl"

void main() {
    tcGrid[gl_InvocationID] = vGrid[gl_InvocationID];
    if (gl_InvocationID != 0) return;

    vec3 ground[4];
    vec3 corners[8];
    for (int i = 0; i < 4; ++i) {
        dvec3 d = gridDirection(vGrid[i]);
        ground[i] = cameraRelative(d, gridSphereRadius() + double(terrainHeight(vec3(d), terrainShape, uContinents)));
        corners[i] = cameraRelative(d, gridSphereRadius() - double(terrainShape.oceanDepth));
        corners[i + 4] = cameraRelative(d, gridSphereRadius() + double(terrainShape.maxHeight));
    }
    if (outsideFrustum(corners)) {
        cullPatch();
        return;
    }
    setQuadLevels(ground, terrainTargetEdgePixels);
}
