// 3D Worley (cellular) noise, F1, optionally tiling; shared by GLSL and C++.
//
// Written in the GLSL subset that is also C++, like simplex.glsl (see there): noise/noise.cpp
// compiles this same text with GLM's float and integer types.
//
// Worley, "A cellular texture basis function" (SIGGRAPH 1996): one feature point per unit
// lattice cell, placed uniformly in the cell by a hash of the cell's integer coordinates;
// F1(p) is the distance from p to the nearest feature point. The hash is pcg3d (Jarzynski
// and Olano, "Hash functions for GPU rendering", JCGT 2020), pure 32-bit unsigned integer
// arithmetic, so GLSL and C++ place every feature point identically. Only the 3 x 3 x 3
// cells around p are searched, the usual approximation: a feature two cells away can
// rarely be nearer (tests/test_noise.cpp measures how rarely against a 5 x 5 x 5 search).
//
// Tiling: with period P > 0 (an integer number of cells), cell coordinates are wrapped
// modulo P before hashing, so F1(p + P e) = F1(p) for every axis e; this is what a baked,
// tiling density volume needs (P cells across the volume). P <= 0: no tiling.
//
// Streams: `stream` (a uint) is added to the wrapped cell, times large odd constants, before
// hashing, so each stream places its own, unrelated feature points (stream 0 is the plain
// hash of the cell). Bakes give every octave and every noise its own stream, so octaves
// whose periods nest (P, 2P, 4P) do not repeat each other's points. perlin.glsl hashes its
// lattice with the same noiseLatticeHash.
//
// Units: p in cells; F1 in cells, in [0, sqrt(3)] (in practice below about 1.2).

#ifndef OUT
#define OUT(x) out x
#endif

// pcg3d: a 32-bit hash of 3 integers to 3 well-mixed integers.
uvec3 noisePcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

// i mod period in [0, period), exact for |i| < 2^24 (GLSL's % is undefined for negatives).
int noiseWrap(int i, int period) {
    int r = i - period * int(floor(float(i) / float(period)));
    if (r < 0) r += period;
    if (r >= period) r -= period;
    return r;
}

// The hash of lattice cell `cell` in `stream`, the cell wrapped modulo period first when
// period > 0 (so cells one period apart hash alike).
uvec3 noiseLatticeHash(ivec3 cell, int period, uint stream) {
    ivec3 wrapped = cell;
    if (period > 0) wrapped = ivec3(noiseWrap(cell.x, period), noiseWrap(cell.y, period), noiseWrap(cell.z, period));
    return noisePcg3d(uvec3(wrapped) + stream * uvec3(2654435769u, 2246822519u, 3266489917u));
}

// Where the feature point of lattice cell `cell` lies inside it, in [0, 1)^3; period and
// stream as in worleyF1.
vec3 worleyFeatureOffset(ivec3 cell, int period, uint stream) {
    uvec3 h = noiseLatticeHash(cell, period, stream);
    return vec3(h >> 8u) * (1.0f / 16777216.0f);  // 24 bits: exact in float
}

// The feature point of cell `cell`, in [cell, cell + 1)^3.
vec3 worleyFeaturePoint(ivec3 cell, int period, uint stream) {
    return vec3(cell) + worleyFeatureOffset(cell, period, stream);
}

// F1 distance at p (cells); tiles with `period` cells when period > 0; feature points of `stream`.
float worleyF1(vec3 p, int period, uint stream) {
    vec3 cellOrigin = floor(p);
    ivec3 cell = ivec3(cellOrigin);
    vec3 local = p - cellOrigin;  // in [0, 1]^3; offsets from the cell's origin keep small numbers small
    float nearest2 = 1.0e9f;
    for (int dz = -1; dz <= 1; dz++) {
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                ivec3 neighbour = ivec3(dx, dy, dz);
                vec3 d = vec3(neighbour) + worleyFeatureOffset(cell + neighbour, period, stream) - local;
                nearest2 = min(nearest2, dot(d, d));
            }
        }
    }
    return sqrt(nearest2);
}

float worleyNoise(vec3 p) { return worleyF1(p, 0, 0u); }

// Tiling F1; period: cells per tile, a positive integer (rounded to the nearest).
float worleyNoiseTiled(vec3 p, float period) { return worleyF1(p, int(floor(period + 0.5f)), 0u); }
