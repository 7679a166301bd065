// Terrain probe: height, normal and material at a list of directions, for comparing the
// GPU with the same GLSL compiled as C++ (tests/test_terrain_height.cpp). One invocation
// per direction.
//
// Shape: uniform block TerrainBlock (std140), the C++ TerrainShape copied as is; the
// continents map (RGBA32F cube map, GL_LINEAR, seamless filtering on) on texture unit 0.
// Input per point (std430, 1 vec4): unit direction xyz, w unused.
// Output per point (3 vec4):
//   [0] terrainHeight (m), terrainNormal xyz
//   [1] terrainSlope of that normal, terrainLatitude (rad), terrainMaterial id,
//       terrainMaterialWeight of that id
//   [2] continentValueGrad: value, gradient xyz
#include "noise/simplex.glsl"
#include "terrain/height.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(location = 0) uniform int pointCount;
layout(location = 1) uniform float planetRadius;  // m

layout(std140, binding = 0) uniform TerrainBlock {
    TerrainShape terrainShape;
};
layout(binding = 0) uniform samplerCube continents;
layout(std430, binding = 0) readonly buffer ProbeDirections {
    vec4 directions[];
};
layout(std430, binding = 1) writeonly buffer ProbeResults {
    vec4 results[];
};

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= pointCount) return;
    vec3 d = directions[i].xyz;
    float height = terrainHeight(d, terrainShape, continents);
    vec3 normal = terrainNormal(d, terrainShape, continents, planetRadius);
    float slope = terrainSlope(normal, d);
    float latitude = terrainLatitude(d);
    int material = terrainMaterial(height, slope, latitude);
    vec3 continentGradient;
    float continent = continentValueGrad(d, continents, continentGradient);
    results[3 * i] = vec4(height, normal);
    results[3 * i + 1] = vec4(slope, latitude, float(material), terrainMaterialWeight(material, height, slope, latitude));
    results[3 * i + 2] = vec4(continent, continentGradient);
}
