// 3D simplex noise with its analytic gradient, fBm and ridged fBm, shared by GLSL and C++.
//
// This file is written in the subset of GLSL that is also C++ (STYLE habit 1): shaders
// include it as GLSL, and noise/noise.cpp includes the very same text into
// namespace planet::noise::glsl with GLM's float types, so the CPU evaluates what the GPU
// runs, in single precision on both sides. The subset: plain float / vec3 / vec4,
// literals with an `f` suffix (GLM has no vec * double), no swizzles beyond single
// components (.x .y .z .w), OUT(x) for out parameters.
//
// The noise is Ashima Arts' / Stefan Gustavson's texture-free simplex noise ("Efficient
// computational noise in GLSL", McEwan, Sheets, Gustavson, Richardson; JGT 2012, and
// webgl-noise's noise3Dgrad.glsl): the simplex lattice of Perlin 2001, corners hashed
// by the permutation polynomial (34 x^2 + x) mod 289, gradients picked on a 7 x 7 grid
// folded onto an octahedron, radial kernel (0.5 - |x|^2)^4 (radius^2 0.5, so the noise
// and its gradient are continuous across simplex boundaries). Changes from the original,
// all so that GLSL float and C++ float pick the same lattice hashes and gradients even
// where the GPU fuses or reorders arithmetic:
//   - every modulo of an integer-valued float is corrected to lie exactly in [0, m)
//     (x * (1/289) can round k*289 to just below k);
//   - the gradient grid is computed in integers scaled by 14, so the octahedron fold's
//     h <= 0 test is exact (in the original, h lands on 0 +- rounding for some corners);
//   - corner order from explicit comparisons with fixed tie-breaking (the original's
//     step() ordering yields an invalid simplex when x0.x == x0.y == x0.z);
//   - exact normalisation of the gradients (inversesqrt) instead of a Taylor estimate.
// Hashing is exact for lattice coordinates |i| < 2^24; the noise repeats every 289
// lattice cells. Precision: x0 = p - i loses float digits as |p| grows (about 1e-4
// relative to the noise's feature size at |p| ~ 1000).
//
// Value range: [-1, 1]. SIMPLEX_NOISE_SCALE was found by maximising |noise| numerically
// (tests/test_noise.cpp checks the bound and that values beyond +-0.8 are reached).

#ifndef OUT
#define OUT(x) out x
#endif

// Makes the noise's extremes just under +-1 (measured maximum of the unscaled sum: see above).
const float SIMPLEX_NOISE_SCALE = 105.0f;

// x mod m for integer-valued x (|x| < 2^24) and integer m, exactly in [0, m).
vec4 noiseModExact(vec4 x, float m) {
    vec4 r = x - m * floor(x * (1.0f / m));
    return r - m * step(m, r) + m * (1.0f - step(0.0f, r));
}

vec3 noiseModExact(vec3 x, float m) {
    vec3 r = x - m * floor(x * (1.0f / m));
    return r - m * step(m, r) + m * (1.0f - step(0.0f, r));
}

// The permutation polynomial (34 x^2 + x) mod 289 on integers in [0, 579): exact in float
// (the largest intermediate, 11.4e6, is below 2^24).
vec4 noisePermute(vec4 x) { return noiseModExact((x * 34.0f + 1.0f) * x, 289.0f); }

// Simplex noise in the lattice cell `i` (skewed integer coordinates, any integers below
// 2^24) at offset x0 from the cell's origin (unskewed, the point minus the origin).
float simplexNoiseGradInCell(vec3 i, vec3 x0, OUT(vec3) gradient) {
    // Which of the 6 simplices of the cell: walk along the largest offset first.
    // Ties broken as x before y before z, so exactly one axis is largest and one smallest.
    float xy = step(x0.y, x0.x);  // x0.x >= x0.y
    float yz = step(x0.z, x0.y);  // x0.y >= x0.z
    float xz = step(x0.z, x0.x);  // x0.x >= x0.z
    vec3 i1 = vec3(xy * xz, (1.0f - xy) * yz, (1.0f - xz) * (1.0f - yz));
    vec3 i2 = 1.0f - vec3((1.0f - xy) * (1.0f - xz), xy * (1.0f - yz), xz * yz);

    // Offsets from the other three corners (unskewed).
    vec3 x1 = x0 - i1 + (1.0f / 6.0f);
    vec3 x2 = x0 - i2 + (2.0f / 6.0f);
    vec3 x3 = x0 - 0.5f;

    // Hash the four corners: permute(permute(permute(z) + y) + x), all in [0, 289).
    i = noiseModExact(i, 289.0f);
    vec4 h = noisePermute(i.z + vec4(0.0f, i1.z, i2.z, 1.0f));
    h = noisePermute(h + i.y + vec4(0.0f, i1.y, i2.y, 1.0f));
    h = noisePermute(h + i.x + vec4(0.0f, i1.x, i2.x, 1.0f));

    // Gradients: h mod 49 picks a point of a 7 x 7 grid over [-1, 1]^2, folded onto the
    // octahedron |x| + |y| + |z| = 1. Grid coordinates scaled by 14: gx, gy odd in
    // [-13, 11], gz = 14 - |gx| - |gy|, all exact.
    vec4 j = noiseModExact(h, 49.0f);
    vec4 gyIndex = noiseModExact(j, 7.0f);
    vec4 gxIndex = floor((j - gyIndex) * (1.0f / 7.0f) + 0.5f);
    vec4 gx = 4.0f * gxIndex - 13.0f;
    vec4 gy = 4.0f * gyIndex - 13.0f;
    vec4 gz = 14.0f - abs(gx) - abs(gy);
    vec4 fold = step(gz, vec4(0.0f));  // 1 below the equator: fold into the lower half
    gx = gx - 14.0f * fold * sign(gx);
    gy = gy - 14.0f * fold * sign(gy);
    vec4 norm = inversesqrt(gx * gx + gy * gy + gz * gz);
    vec3 g0 = vec3(gx.x, gy.x, gz.x) * norm.x;
    vec3 g1 = vec3(gx.y, gy.y, gz.y) * norm.y;
    vec3 g2 = vec3(gx.z, gy.z, gz.z) * norm.z;
    vec3 g3 = vec3(gx.w, gy.w, gz.w) * norm.w;

    // Sum of kernels m^4 (g . x), m = max(0.5 - |x|^2, 0), and its derivative
    // m^4 g - 8 m^3 (g . x) x.
    vec4 m = max(0.5f - vec4(dot(x0, x0), dot(x1, x1), dot(x2, x2), dot(x3, x3)), 0.0f);
    vec4 m2 = m * m;
    vec4 m4 = m2 * m2;
    vec4 gDotX = vec4(dot(g0, x0), dot(g1, x1), dot(g2, x2), dot(g3, x3));
    vec4 m3GDotX = m2 * m * gDotX;
    gradient = SIMPLEX_NOISE_SCALE *
               (m4.x * g0 + m4.y * g1 + m4.z * g2 + m4.w * g3 -
                8.0f * (m3GDotX.x * x0 + m3GDotX.y * x1 + m3GDotX.z * x2 + m3GDotX.w * x3));
    return SIMPLEX_NOISE_SCALE * dot(m4, gDotX);
}

// Simplex noise at p (lattice spacing 1), in [-1, 1]; gradient = d noise / d p.
float simplexNoiseGrad(vec3 p, OUT(vec3) gradient) {
    // Skew to the cubic lattice, find the cell, unskew its origin (F3 = 1/3, G3 = 1/6).
    vec3 i = floor(p + (p.x + p.y + p.z) * (1.0f / 3.0f));
    vec3 x0 = p - i + (i.x + i.y + i.z) * (1.0f / 6.0f);
    return simplexNoiseGradInCell(i, x0, gradient);
}

// The same noise at the point `lattice` + q, where `lattice` is a lattice point (skewed
// integer coordinates, e.g. reduced modulo 289) and q the offset from it (unskewed, small):
// a point far from the origin given without the float rounding of its large coordinates
// (the caller forms lattice and q in double; terrain/height.glsl's near field).
float simplexNoiseGradFrom(vec3 lattice, vec3 q, OUT(vec3) gradient) {
    vec3 i = floor(q + (q.x + q.y + q.z) * (1.0f / 3.0f));
    vec3 x0 = q - i + (i.x + i.y + i.z) * (1.0f / 6.0f);
    return simplexNoiseGradInCell(lattice + i, x0, gradient);
}

float simplexNoise(vec3 p) {
    vec3 unused;
    return simplexNoiseGrad(p, unused);
}

// Fractal Brownian motion: sum over octaves k = 0 .. octaves-1 of gain^k noise(lacunarity^k p),
// divided by the sum of the amplitudes, so it stays in [-1, 1] and 1 octave is simplexNoise(p).
// octaves is clamped to [1, 10]; lacunarity > 1 (typically 2), gain in (0, 1) (typically 0.5).
float fbmGrad(vec3 p, int octaves, float lacunarity, float gain, OUT(vec3) gradient) {
    int count = clamp(octaves, 1, 10);
    float sum = 0.0f;
    float total = 0.0f;
    float amplitude = 1.0f;
    float frequency = 1.0f;
    gradient = vec3(0.0f);
    for (int k = 0; k < 10; k++) {
        if (k >= count) break;
        vec3 g;
        sum += amplitude * simplexNoiseGrad(p * frequency, g);
        gradient += (amplitude * frequency) * g;
        total += amplitude;
        frequency *= lacunarity;
        amplitude *= gain;
    }
    gradient /= total;
    return sum / total;
}

float fbm(vec3 p, int octaves, float lacunarity, float gain) {
    vec3 unused;
    return fbmGrad(p, octaves, lacunarity, gain, unused);
}

// Ridged fBm: the same octave sum of (1 - |noise|)^2, sharp crests where the noise
// crosses zero; normalised the same way, so in [0, 1].
float ridgedFbm(vec3 p, int octaves, float lacunarity, float gain) {
    int count = clamp(octaves, 1, 10);
    float sum = 0.0f;
    float total = 0.0f;
    float amplitude = 1.0f;
    float frequency = 1.0f;
    for (int k = 0; k < 10; k++) {
        if (k >= count) break;
        float ridge = 1.0f - abs(simplexNoise(p * frequency));
        sum += amplitude * ridge * ridge;
        total += amplitude;
        frequency *= lacunarity;
        amplitude *= gain;
    }
    return sum / total;
}
