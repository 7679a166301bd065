// Ocean tessellation evaluation: grid coordinate -> direction on the sea sphere
// (Michelic Eq. 1-4, terrain/grid.glsl; uPlanetRadius is the sea radius here) ->
// spherical Gerstner displacement (Eq. 8) of the waves the vertex spacing can carry, damped
// where the water is too shallow for them (ocean_waves.glsl) ->
// camera-relative position (the sphere point in double, the waves' metres in float).
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "ocean/gerstner.glsl"
#include "ocean/ocean_waves.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"

layout(quads, fractional_odd_spacing, ccw) in;
in vec2 tcGrid[];
out vec3 tePosition;   // camera-relative, m
out vec3 teDirection;  // unit direction of the undisplaced point
out vec3 teOffset;     // teDirection - camera direction (gerstner.glsl's dv)

uniform float uTargetEdgePixels;
uniform float uSeaLevel;  // m above the planet radius
layout(std140, binding = 2) uniform TerrainBlock {
    TerrainShape terrainShape;
};
layout(binding = 10) uniform samplerCube uContinents;

void main() {
    vec2 uv = gl_TessCoord.xy;
    vec2 g = mix(mix(tcGrid[0], tcGrid[1], uv.x), mix(tcGrid[3], tcGrid[2], uv.x), uv.y);
    dvec3 direction = gridDirection(g);
    vec3 sphere = cameraRelative(direction, uPlanetRadius);
    float vertexSpacing = length(sphere) * radiansPerPixel() * uTargetEdgePixels;
    vec3 v = vec3(direction);
    vec3 dv = oceanDirectionOffset(direction);
    float waterDepth = uSeaLevel - terrainHeight(v, terrainShape, uContinents);
    tePosition = sphere + oceanDisplacement(v, dv, vertexSpacing, waterDepth);
    teDirection = v;
    teOffset = dv;
    gl_Position = frame.clipFromView * (frame.viewFromWorld * vec4(tePosition, 1.0));
}
