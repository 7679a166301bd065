// Ocean: one vertex per grid point of its own projected grid; tessellation does the rest. The
// point's index (i, j) goes along, for the evaluation stage's reading of the grid's reflection
// between the points (ocean/grid_reflection_points.glsl) where the sea is a flat or smooth mirror.
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"

layout(location = 0) in vec2 gridCoordinate;
out vec2 vGrid;
out ivec2 vPoint;

void main() {
    vGrid = gridCoordinate;
    vPoint = ivec2(gl_VertexID % grid.pointsPerSide, gl_VertexID / grid.pointsPerSide);
}
