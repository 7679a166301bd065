// Terrain tessellation evaluation: grid coordinate -> direction on the sphere
// (grid.glsl, Michelic Eq. 1-4) -> height from the shared height function (baked
// continents, Michelic §6, plus mountain noise) -> camera-relative position formed
// in double, then rotated and projected.
// Below sea level this is the sea floor; the ocean pass draws the water over it.
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"

layout(quads, fractional_odd_spacing, ccw) in;
in vec2 tcGrid[];
in ivec2 tcPoint[];
out vec3 teDirection;   // unit direction from the planet centre
out float teHeight;     // m above sea level (negative: under water)
out vec3 tePointFromCamera;  // m, world axes: the camera-relative position (formed in double)

#include "terrain/terrain_block.glsl"

void main() {
    vec2 uv = gl_TessCoord.xy;
    vec2 g = patchGridCoordinate(tcGrid[0], tcGrid[1], tcGrid[2], tcGrid[3], tcPoint[0], tcPoint[2], uv);
    dvec3 direction = gridDirection(g);
    float height = terrainHeight(vec3(direction), terrainShape, uContinents);
    vec3 position = cameraRelative(direction, gridSphereRadius() + double(height));
    teDirection = vec3(direction);
    teHeight = height;
    tePointFromCamera = position;
    gl_Position = frame.clipFromView * (frame.viewFromWorld * vec4(position, 1.0));
}
