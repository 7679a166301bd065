// The reflection at each point of the ocean's grid (ocean/grid_reflection.glsl), where the sea is
// a flat or smooth mirror (built with OCEAN_FLAT_MIRROR or OCEAN_SMOOTH_MIRROR, as the ocean's
// program): one invocation per point.
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/cloud_reflection.glsl"
#include "ocean/grid_reflection.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(std430, binding = BUFFER_OCEAN_GRID_POINTS) readonly buffer OceanGridPoints {
    vec2 oceanGridPoints[];  // the grid mesh's vertex buffer
};
layout(binding = IMAGE_OCEAN_GRID_REFLECTION, rgba32f) uniform writeonly image2D oceanGridReflection;  // texel (i, j): point j N + i

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(oceanGridPoints.length())) return;
    int n = grid.pointsPerSide;
    imageStore(oceanGridReflection, ivec2(int(i) % n, int(i) / n), vec4(GridReflection(oceanGridPoints[i]), 0.0));
}
