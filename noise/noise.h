// Noise on the CPU: the very GLSL the shaders run, compiled as C++ in float.
//
// shaders/noise/simplex.glsl, worley.glsl and perlin.glsl are written in the subset of
// GLSL that is also C++ (STYLE habit 1). noise.cpp includes them into
// namespace planet::noise::glsl, with GLM's float vectors standing in for GLSL's, and the
// functions below forward to them. Both sides compute in single precision, so the CPU
// values match the GPU's to float rounding (tests/test_noise.cpp measures the difference
// with shaders/noise/noise_probe.comp; numbers in noise/README.md). The GLSL names are
// given next to each function.
#pragma once

#include <glm/vec3.hpp>
#include <glm/ext/vector_int3.hpp>

namespace planet::noise {

// 3D simplex noise, lattice spacing 1, in [-1, 1]. GLSL: simplexNoise(p).
float simplex(glm::vec3 p);

// Simplex noise and its analytic gradient d noise / d p. GLSL: simplexNoiseGrad(p, gradient).
float simplexGrad(glm::vec3 p, glm::vec3& gradient);

// fBm: sum of gain^k simplex(lacunarity^k p) over octaves in [1, 10] (clamped), divided by
// the sum of amplitudes: in [-1, 1], and octaves = 1 gives simplex(p). GLSL: fbm(...).
float fbm(glm::vec3 p, int octaves, float lacunarity = 2.0f, float gain = 0.5f);

// fBm and its analytic gradient. GLSL: fbmGrad(p, octaves, lacunarity, gain, gradient).
float fbmGrad(glm::vec3 p, int octaves, float lacunarity, float gain, glm::vec3& gradient);

// Ridged fBm: the same sum of (1 - |simplex|)^2, in [0, 1]. GLSL: ridgedFbm(...).
float ridgedFbm(glm::vec3 p, int octaves, float lacunarity = 2.0f, float gain = 0.5f);

// Worley F1: distance from p to the nearest feature point (one per unit cell), in cells.
// period > 0 (an integer number of cells) makes it tile: worley(p + period e) = worley(p).
// Each stream places its own, unrelated feature points (0: the GLSL wrappers' points).
// GLSL: worleyNoise(p), worleyNoiseTiled(p, period), worleyF1(p, int period, stream).
float worley(glm::vec3 p, float period = 0.0f, unsigned stream = 0);

// Tiling 3D gradient (Perlin 2002) noise, quintic fade, in [-1, 1], 0 at integer points;
// period > 0 (cells, an integer) makes it tile: perlinTiled(p + period e) = perlinTiled(p);
// period <= 0: no tiling. Streams as for worley. GLSL: perlinNoiseTiled(p, period),
// perlinNoiseTiledStream(p, int period, stream).
float perlinTiled(glm::vec3 p, float period, unsigned stream = 0);

// fBm of perlinTiled with lacunarity 2 (so every octave tiles with `period`), in [-1, 1]:
// octave k has amplitude gain^k, stream `stream + k` and a fixed shift, the sum is divided by
// the sum of amplitudes; octaves clamped to [1, 10]. GLSL: perlinFbmTiled(p, period,
// octaves, gain, stream).
float perlinFbmTiled(glm::vec3 p, float period, int octaves, float gain = 0.5f, unsigned stream = 0);

// A lattice stream for a seed and a purpose (a 32-bit hash of both): how a *tiling* noise
// takes its seed. An offset of the domain (seedOffset) would only translate a periodic
// noise's tile, not make another one.
unsigned seedStream(int seed, unsigned purpose);

// Offset of the noise domain for a seed and a stream (0: continents, 1: mountains, 2: the
// clouds' weather map, 3: the cloud volume; 0..3 only, as seed * 4 + stream is hashed), so that
// another seed gives another, unrelated field with the same statistics: each component in
// [-32, 32) in steps of 1/256, from a 32-bit integer hash. Exact in float, and small, so
// noise coordinates keep their float precision (see simplex.glsl).
glm::vec3 seedOffset(int seed, unsigned stream);

// The feature point of a lattice cell, in [cell, cell + 1)^3 (for tests and debugging).
// GLSL: worleyFeaturePoint(cell, period, stream) with an int period.
glm::vec3 worleyFeaturePoint(glm::ivec3 cell, float period = 0.0f, unsigned stream = 0);

// Where that feature point lies inside its cell, in [0, 1)^3, exactly as worley() places it
// (for bakes that hash each cell once and run worleyF1's arithmetic over a table).
// GLSL: worleyFeatureOffset(cell, period, stream) with an int period.
glm::vec3 worleyFeatureOffset(glm::ivec3 cell, float period = 0.0f, unsigned stream = 0);

}  // namespace planet::noise
