// Ocean probe: the displacement (Michelic Eq. 8) and normal (Eq. 10) the ocean shaders
// compute, at a list of directions, for comparing the GPU with the double-precision CPU
// reference (tests/test_ocean_gpu.cpp). One invocation per direction, every wave at full
// level of detail, in deep water (no shoaling).
// Input per point (std430, dvec4): direction xyz (unit, double), w unused.
// Output per point (2 vec4): [0] displacement from the sea sphere (m, world axes), w 0;
//                            [1] unit normal xyz, w: slope variance left over (0 here).
#include "terrain/grid.glsl"
#include "ocean/ocean_block.glsl"
#include "ocean/gerstner.glsl"
#include "ocean/ocean_waves.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(location = 0) uniform int pointCount;

layout(std430, binding = BUFFER_PROBE_INPUT) readonly buffer ProbeDirections {
    dvec4 directions[];
};
layout(std430, binding = BUFFER_PROBE_OUTPUT) writeonly buffer ProbeResults {
    vec4 results[];
};

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= pointCount) return;
    dvec3 direction = directions[i].xyz;
    vec3 v = vec3(direction);
    vec3 dv = oceanDirectionOffset(direction);
    float slopeVariance;
    results[2 * i] = vec4(oceanDisplacement(v, dv, 0.0, 1.0e9), 0.0);
    results[2 * i + 1] = vec4(oceanNormal(v, dv, 0.0, 1.0e9, slopeVariance), slopeVariance);
}
