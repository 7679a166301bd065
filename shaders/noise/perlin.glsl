// 3D gradient (Perlin) noise that tiles, and its fBm; shared by GLSL and C++.
//
// Written in the GLSL subset that is also C++, like simplex.glsl (see there); noise/noise.cpp
// compiles this same text with GLM's float and integer types. Needs worley.glsl first (its
// pcg3d lattice hash, noiseLatticeHash).
//
// Perlin, "Improving noise" (SIGGRAPH 2002): a gradient at every integer lattice corner,
// picked from the 12 edge directions of the cube, (+-1, +-1, 0) and permutations; the noise
// at p is the trilinear blend, with the quintic fade 6t^5 - 15t^4 + 10t^3 (continuous
// second derivative), of each corner's gradient . (p - corner). The corner's gradient
// comes from pcg3d of its integer coordinates (noiseLatticeHash), so GLSL and C++ pick the
// same one, and the dot products with those gradients are sums of +-components, exact in
// float. Zero at every lattice point.
//
// Tiling: with period P > 0 (cells, an integer), corners are wrapped modulo P before
// hashing, so noise(p + P e) = noise(p) for every axis e (bit for bit where p + P e is exact
// in float). Baked tiling volumes use it with P cells across the volume.
//
// Range: PERLIN_NOISE_SCALE maps the largest value any choice of the 12 gradients can give,
// 1.03635 (at a point (0.5, 0.355, 0.481) of the cell, each corner taking its best gradient;
// found by a grid search refined by pattern search), to just under 1, so the noise is in
// [-1, 1] for certain; values beyond +-0.7 are reached (tests/test_noise.cpp).
//
// Units: p in cells; the noise is dimensionless.

// 1 / 1.03635, rounded down: the bound on |noise| over all gradient choices becomes < 1.
const float PERLIN_NOISE_SCALE = 0.9649f;

// The quintic fade of Perlin 2002 per component: 0 at 0, 1 at 1, first and second derivative 0 at both.
vec3 perlinFade(vec3 t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

// gradient(corner) . d, the gradient one of the 12 cube edges chosen by the corner's hash.
float perlinCorner(ivec3 corner, int period, uint stream, vec3 d) {
    uint k = (noiseLatticeHash(corner, period, stream).x >> 16u) % 12u;
    float u = k < 8u ? d.x : d.y;  // k 0-3: +-x +-y; 4-7: +-x +-z; 8-11: +-y +-z
    float v = k < 4u ? d.y : d.z;
    return ((k & 1u) == 0u ? u : -u) + ((k & 2u) == 0u ? v : -v);
}

// Gradient noise at p, in [-1, 1]; tiles every `period` cells when period > 0; the lattice's
// gradients come from `stream` (see worley.glsl: each stream is an unrelated noise).
float perlinNoiseTiledStream(vec3 p, int period, uint stream) {
    vec3 cellOrigin = floor(p);
    ivec3 c = ivec3(cellOrigin);
    vec3 f = p - cellOrigin;  // in [0, 1]^3
    vec3 w = perlinFade(f);
    float n000 = perlinCorner(c, period, stream, f);
    float n100 = perlinCorner(c + ivec3(1, 0, 0), period, stream, f - vec3(1.0f, 0.0f, 0.0f));
    float n010 = perlinCorner(c + ivec3(0, 1, 0), period, stream, f - vec3(0.0f, 1.0f, 0.0f));
    float n110 = perlinCorner(c + ivec3(1, 1, 0), period, stream, f - vec3(1.0f, 1.0f, 0.0f));
    float n001 = perlinCorner(c + ivec3(0, 0, 1), period, stream, f - vec3(0.0f, 0.0f, 1.0f));
    float n101 = perlinCorner(c + ivec3(1, 0, 1), period, stream, f - vec3(1.0f, 0.0f, 1.0f));
    float n011 = perlinCorner(c + ivec3(0, 1, 1), period, stream, f - vec3(0.0f, 1.0f, 1.0f));
    float n111 = perlinCorner(c + ivec3(1, 1, 1), period, stream, f - vec3(1.0f, 1.0f, 1.0f));
    float y0 = mix(mix(n000, n100, w.x), mix(n010, n110, w.x), w.y);
    float y1 = mix(mix(n001, n101, w.x), mix(n011, n111, w.x), w.y);
    return PERLIN_NOISE_SCALE * mix(y0, y1, w.z);
}

// Tiling gradient noise, stream 0; period: cells per tile, a positive integer (rounded to the
// nearest); 0 or less: no tiling.
float perlinNoiseTiled(vec3 p, float period) { return perlinNoiseTiledStream(p, int(floor(period + 0.5f)), 0u); }

// Tiling fBm: octave k (k = 0 .. octaves-1, octaves clamped to [1, 10]) is
// perlinNoiseTiledStream(2^k p + k s, 2^k period, stream + k) with amplitude gain^k, the sum
// divided by the sum of amplitudes, so it stays in [-1, 1] and 1 octave is perlinNoiseTiled.
// The lacunarity is 2 so that every octave tiles with the same period; each octave has its
// own stream (octaves whose periods nest would otherwise repeat each other's gradients) and
// is shifted by k s, s = (0.3125, 0.6875, 0.1875) cells (exact in float), so that the
// octaves' lattice points, where each is 0, do not coincide. Shifts keep the tiling.
float perlinFbmTiled(vec3 p, float period, int octaves, float gain, uint stream) {
    int count = clamp(octaves, 1, 10);
    int cells = int(floor(period + 0.5f));
    float sum = 0.0f;
    float total = 0.0f;
    float amplitude = 1.0f;
    float frequency = 1.0f;
    for (int k = 0; k < 10; k++) {
        if (k >= count) break;
        vec3 q = p * frequency + float(k) * vec3(0.3125f, 0.6875f, 0.1875f);
        sum += amplitude * perlinNoiseTiledStream(q, cells, stream + uint(k));
        total += amplitude;
        frequency *= 2.0f;
        cells *= 2;
        amplitude *= gain;
    }
    return sum / total;
}
