// Noise probe: every shared noise function at a list of points, for comparing the GPU
// with the same GLSL compiled as C++ (tests/test_noise.cpp). One invocation per point.
//
// Input per point (std430, 1 vec4): position xyz, w unused.
// Output per point (4 vec4):
//   [0] simplexNoise, simplexNoiseGrad's gradient xyz
//   [1] fbm, fbmGrad's gradient xyz        (octaves, lacunarity, gain from the uniforms)
//   [2] ridgedFbm, worleyNoise, worleyNoiseTiled(period), perlinNoiseTiled(period)
//   [3] perlinFbmTiled(period, octaves, gain, stream 7), worleyF1(period, stream 7), 0, 0
#include "noise/simplex.glsl"
#include "noise/worley.glsl"
#include "noise/perlin.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(location = 0) uniform int pointCount;
layout(location = 1) uniform int octaves;
layout(location = 2) uniform float lacunarity;
layout(location = 3) uniform float gain;
layout(location = 4) uniform float period;  // cells per tile for the tiled noises

layout(std430, binding = 0) readonly buffer ProbePoints {
    vec4 points[];
};
layout(std430, binding = 1) writeonly buffer ProbeResults {
    vec4 results[];
};

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= pointCount) return;
    vec3 p = points[i].xyz;
    vec3 gradient;
    float value = simplexNoiseGrad(p, gradient);
    results[4 * i] = vec4(value, gradient);
    vec3 fbmGradient;
    float fbmValue = fbmGrad(p, octaves, lacunarity, gain, fbmGradient);
    results[4 * i + 1] = vec4(fbmValue, fbmGradient);
    results[4 * i + 2] =
        vec4(ridgedFbm(p, octaves, lacunarity, gain), worleyNoise(p), worleyNoiseTiled(p, period), perlinNoiseTiled(p, period));
    int cells = int(floor(period + 0.5));
    results[4 * i + 3] = vec4(perlinFbmTiled(p, period, octaves, gain, 7u), worleyF1(p, cells, 7u), 0.0, 0.0);
}
