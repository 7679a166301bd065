// The reflection at each point of the ocean's grid (ocean/grid_reflection.glsl), where the sea is
// a flat or smooth mirror (built with OCEAN_FLAT_MIRROR or OCEAN_SMOOTH_MIRROR, as the ocean's
// program): one invocation per point.
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/cloud_reflection.glsl"
#include "ocean/grid_reflection.glsl"
#include "ocean/ocean_block.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(std430, binding = BUFFER_OCEAN_GRID_POINTS) readonly buffer OceanGridPoints {
    vec2 oceanGridPoints[];  // the grid mesh's vertex buffer
};
layout(binding = IMAGE_OCEAN_GRID_REFLECTION, rgba32f) uniform writeonly image2D oceanGridReflection;  // texel (i, j): point j N + i

// Whether the sea may lie in any of the four cells around point (x, y) of the N x N grid, the
// only places whose fragments read it: not where every place as far as its farthest neighbour
// (a cell's farthest corner) is land above the highest crest by the continents' slope bound
// (the ocean's land culling, src/ocean/land_cull.h, drops the patches and fragments there).
// From orbit over a continent's interior: its marches are a fifth of the ocean pass.
bool seaMayLieAround(int x, int y, int n) {
    if (ocean.landCulling == 0 || !(ocean.continentLipschitz > 0.0)) return true;
    vec3 centre = vec3(gridDirection(oceanGridPoints[y * n + x]));
    float reach = 0.0;  // rad
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = clamp(ivec2(x + dx, y + dy), ivec2(0), ivec2(n - 1));
            float chord = length(vec3(gridDirection(oceanGridPoints[q.y * n + q.x])) - centre);
            reach = max(reach, 2.0 * asin(min(0.5 * chord, 1.0)));
        }
    float lowest = continentValue(centre, uContinents) -
                   ocean.continentLipschitz * (reach + ocean.continentSampleSlackRad);
    return lowest < ocean.landContinent;
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(oceanGridPoints.length())) return;
    int n = grid.pointsPerSide;
    int x = int(i) % n, y = int(i) / n;
    vec3 reflection = vec3(0.0);
    // A loop of one turn or none: a group of points all over land leaves the march's loops after
    // their first turn (the grid's rows run along the land, so most groups are all one or the other).
    for (int k = 0; k < (seaMayLieAround(x, y, n) ? 1 : 0); ++k) reflection = GridReflection(oceanGridPoints[i]);
    imageStore(oceanGridReflection, ivec2(x, y), vec4(reflection, 0.0));
}
