// Ocean: one vertex per grid point of its own projected grid; tessellation does the rest.
// With OCEAN_FLAT_MIRROR (the sea seen from high up), also the clouds' change to the sea's
// reflection along the mean surface's mirror ray at its grid point (ocean/cloud_reflection.glsl),
// formed for every point by ocean/grid_reflection.comp before the draw: the grid's points are a
// fixed number whatever the resolution; with OCEAN_SMOOTH_MIRROR (higher still: no pixel
// resolves a wave) the whole reflected sky there.
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/cloud_reflection.glsl"
#include "ocean/grid_reflection.glsl"

layout(location = 0) in vec2 gridCoordinate;
out vec2 vGrid;
out vec3 vGridReflection;  // dL_C, or L_sky + dL_C with OCEAN_SMOOTH_MIRROR (0 without either: per pixel)

void main() {
    vGrid = gridCoordinate;
    vGridReflection = vec3(0.0);
#if OCEAN_FLAT_MIRROR
    vGridReflection = oceanGridReflection[gl_VertexID].xyz;  // ocean/grid_reflection.comp, this frame's
#endif
}
