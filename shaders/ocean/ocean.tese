// Ocean tessellation evaluation: grid coordinate -> direction on the sea sphere
// (Michelic Eq. 1-4, terrain/grid.glsl; the grid sphere is the sea here) ->
// spherical Gerstner displacement (Eq. 8) of the waves the vertex spacing can carry, damped
// where the water is too shallow for them (ocean_waves.glsl) ->
// camera-relative position (the sphere point in double, the waves' metres in float).
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "ocean/ocean_block.glsl"
#include "ocean/gerstner.glsl"
#include "ocean/ocean_waves.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"

layout(quads, fractional_odd_spacing, ccw) in;
in vec2 tcGrid[];
in ivec2 tcPoint[];
out vec3 tePosition;   // camera-relative, m
out vec3 teDirection;  // unit direction of the undisplaced point
out vec3 teOffset;     // teDirection - camera direction (gerstner.glsl's dv)
out vec2 teGridPoint;  // the place on the grid in point indices (i, j), for the grid's reflection (ocean/sea_light.frag)

#include "terrain/terrain_block.glsl"

void main() {
    vec2 uv = gl_TessCoord.xy;
    // With a stride the vertex is where the grid's warp puts teGridPoint, so the grid's reflection
    // read there (ocean/sea_light.frag) is the reflection of this very place.
    teGridPoint = patchGridPoint(tcPoint[0], tcPoint[2], uv);
    vec2 g = patchGridCoordinate(tcGrid[0], tcGrid[1], tcGrid[2], tcGrid[3], tcPoint[0], tcPoint[2], uv);
    dvec3 direction = gridDirection(g);
    vec3 sphere = cameraRelative(direction, gridSphereRadius());
    float vertexSpacing = length(sphere) * radiansPerPixel() * ocean.targetEdgePixels;
    vec3 v = vec3(direction);
    vec3 dv = oceanDirectionOffset(direction);
    float waterDepth = ocean.seaLevel - terrainHeight(v, terrainShape, uContinents);
    tePosition = sphere + oceanDisplacement(v, dv, vertexSpacing, waterDepth);
    teDirection = v;
    teOffset = dv;
    gl_Position = frame.clipFromView * (frame.viewFromWorld * vec4(tePosition, 1.0));
}
