// Ocean tessellation control (Michelic §3-4): culls patches outside a widened frustum,
// counting the highest crests and lowest troughs, and sets levels from each edge's size on
// screen (grid/tessellation.glsl).
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "grid/tessellation.glsl"
#include "ocean/ocean_block.glsl"

layout(vertices = 4) out;
in vec2 vGrid[];
out vec2 tcGrid[];


void main() {
    tcGrid[gl_InvocationID] = vGrid[gl_InvocationID];
    if (gl_InvocationID != 0) return;
    vec3 mean[4];
    vec3 corners[8];
    for (int i = 0; i < 4; ++i) {
        dvec3 d = gridDirection(vGrid[i]);
        mean[i] = cameraRelative(d, gridSphereRadius());
        corners[i] = cameraRelative(d, gridSphereRadius() - double(ocean.maxWaveHeight));
        corners[i + 4] = cameraRelative(d, gridSphereRadius() + double(ocean.maxWaveHeight));
    }
    if (outsideFrustum(corners)) {
        cullPatch();
        return;
    }
    setQuadLevels(mean, ocean.targetEdgePixels);
}
