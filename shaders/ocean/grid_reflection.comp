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

// Whether any of the four cells around point (x, y) of the N x N grid may hold a pixel that reads it:
//  - not where every place as far as its farthest neighbour (a cell's farthest corner) is land above
//    the highest crest by the continents' slope bound (the ocean's land culling, src/ocean/land_cull.h,
//    drops the patches and fragments there). From orbit over a continent's interior: its marches
//    were a fifth of the ocean pass.
//  - nor where the cells lie off screen: all of the 3 x 3 points around it more than `margin` outside
//    one of the view's four side planes. A half-space holds the cells' hull; a pixel's point stands off
//    that hull by at most the sag of the chords between: the sphere's above the block, (2 chord)^2 / 8r
//    (the far field's pixels take their place on the grid from the sphere's point), or the mesh's
//    below a patch of `stride` cells, whose triangles carry the place on the grid across (stride x the
//    block's width); and the waves move a pixel's point from its place by at most their summed
//    amplitudes. From orbit the grid reaches behind the camera and past the view's sides: 71 % of its
//    points at 160 x 90 (tests/test_ocean_reflections.cpp).
bool mayBeReadAround(int x, int y, int n) {
    dvec3 directions[9];  // the point's and its eight neighbours' (the centre's is [4])
    for (int k = 0; k < 9; ++k) {
        ivec2 q = clamp(ivec2(x + k % 3 - 1, y + k / 3 - 1), ivec2(0), ivec2(n - 1));
        directions[k] = gridDirection(oceanGridPoints[q.y * n + q.x]);
    }
    vec4 farthestInside = vec4(-1.0e30);  // per side plane of the view (frame.viewSidePlanes), the most any point is inside it, m
    float reach = 0.0;  // rad
    for (int k = 0; k < 9; ++k) {
        float chord = float(length(directions[k] - directions[4]));
        reach = max(reach, 2.0 * asin(min(0.5 * chord, 1.0)));
        vec3 point = cameraRelative(directions[k], gridSphereRadius());
        for (int s = 0; s < 4; ++s)
            farthestInside[s] = max(farthestInside[s], dot(frame.viewSidePlanes[s].xyz, point) + frame.viewSidePlanes[s].w);
    }
    dvec3 centre = directions[4];
    float radius = float(gridSphereRadius());
    float widthM = 2.0 * reach * radius * float(max(grid.stride, 1));
    float margin = widthM * widthM / (8.0 * radius) + ocean.maxWaveHeight;
    if (any(lessThan(farthestInside, vec4(-margin)))) return false;
    if (ocean.landCulling == 0 || !(ocean.continentLipschitz > 0.0)) return true;
    float lowest = continentValue(vec3(centre), uContinents) -
                   ocean.continentLipschitz * (reach + ocean.continentSampleSlackRad);
    return lowest < ocean.landContinent;
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(oceanGridPoints.length())) return;
    int n = grid.pointsPerSide;
    int x = int(i) % n, y = int(i) / n;
    vec3 reflection = vec3(0.0);
    // A loop of one turn or none: a group of points all over land or off screen leaves the march's
    // loops after their first turn (the grid's rows run along the land, so most groups are all one or
    // the other).
    for (int k = 0; k < (mayBeReadAround(x, y, n) ? 1 : 0); ++k) reflection = GridReflection(oceanGridPoints[i]);
    imageStore(oceanGridReflection, ivec2(x, y), vec4(reflection, 0.0));
}
