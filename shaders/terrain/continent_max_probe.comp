// Continents' maxima probe: continentMaxWithin (terrain/patch_continents.glsl), the lookup the
// terrain's control stage makes, at a list of caps, for comparing the GPU with its CPU twin
// (src/terrain/continent_bound.h; tests/test_continent_bound.cpp). One invocation per cap.
// The pyramid's texture on UNIT_CONTINENT_MAX, nearest filtering.
// Input per cap (std430, 1 vec4): unit centre xyz, radius w (rad). Output per cap: the bound.
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/grid.glsl"
layout(binding = UNIT_CONTINENTS) uniform samplerCube uContinents;  // (patchContinentRange's; unused here)
#include "terrain/patch_continents.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(location = 0) uniform int capCount;
layout(location = 1) uniform float maxRadius;  // rad (the terrain block's terrainContinentMaxRadius)

layout(std430, binding = 0) readonly buffer ProbeCaps {
    vec4 caps[];
};
layout(std430, binding = 1) writeonly buffer ProbeBounds {
    float bounds[];
};

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= capCount) return;
    bounds[i] = continentMaxWithin(caps[i].xyz, caps[i].w, maxRadius);
}
