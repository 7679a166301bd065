// Terrain: one vertex per grid point. Its direction (grid.glsl, in double) and height
// (height.glsl) are evaluated here, once per grid point, for the control stage's culling and
// levels (terrain.tesc): a grid point is a corner of up to four patches, and the control
// stage used to evaluate all four corners of every patch itself. The evaluation stage
// (terrain.tese) still evaluates its own points, the corners included, so the mesh is what
// it was, bit for bit.
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/terrain_block.glsl"

layout(location = 0) in vec2 gridCoordinate;
out vec2 vGrid;
out ivec2 vPoint;  // the point's indices (i, j): a stride's patch (terrain.tesc, terrain.tese)
out vec3 vGround;  // m, camera-relative (world axes): the point on the terrain
out vec3 vLow;     // m, camera-relative: the lowest sea floor below it
out vec3 vHigh;    // m, camera-relative: the highest possible terrain above it
out float vSlope;  // the ground's slope there, rise over run: how much relief the edges from it can show

void main() {
    vGrid = gridCoordinate;
    vPoint = ivec2(gl_VertexID % grid.pointsPerSide, gl_VertexID / grid.pointsPerSide);
    dvec3 d = gridDirection(gridCoordinate);
    vec3 gradient;
    float height = terrainHeightGrad(vec3(d), terrainShape, uContinents, gradient);
    vSlope = length(gradient - dot(gradient, vec3(d)) * vec3(d)) / (frame.planetRadius + height);
    vGround = cameraRelative(d, gridSphereRadius() + double(height));
    vLow = cameraRelative(d, gridSphereRadius() - double(terrainShape.oceanDepth));
    vHigh = cameraRelative(d, gridSphereRadius() + double(terrainShape.maxHeight));
}
