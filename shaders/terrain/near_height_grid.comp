// The near height grid (terrain/near_height_grid.glsl; src/terrain/near_height_grid.h): at each of
// its N x N points, the height field (terrainHeightNearGrad, exact to float near the grid's origin:
// the TerrainNearBlock bound for this dispatch is formed at the origin, not at the camera) and its
// gradient. Run when the grid moves or the terrain changes, not every frame, a slice of its rows at a
// time while the camera roams towards the next grid.
#include "common/bindings.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/terrain_block.glsl"
#include "terrain/near_height_grid.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(binding = IMAGE_TERRAIN_NEAR_GRID, rgba32f) writeonly uniform image2D nearGrid;
// The rows [x, y) this dispatch evaluates (src/terrain/near_height_grid.h: a grid over several frames).
layout(location = 0) uniform ivec2 uRows;

void main() {
    ivec2 point = ivec2(gl_GlobalInvocationID.xy) + ivec2(0, uRows.x);
    if (point.x >= int(nearGridNorth.w) || point.y >= min(uRows.y, int(nearGridNorth.w))) return;
    vec3 gradient;
    float height = terrainHeightNearGrad(nearGridPointFromOrigin(nearGridPlaneAt(point)), terrainNear, terrainShape, gradient);
    imageStore(nearGrid, point, vec4(height, gradient));
}
