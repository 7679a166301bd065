// The wave set on the GPU and the sums over it (GLSL only; the per-wave terms are the
// shared gerstner.glsl). The records come longest first (ocean/ocean_gpu.h), so each sum
// stops at the first wave its sampling cannot carry. Include after terrain/grid.glsl (the
// camera), ocean/ocean_block.glsl (count, fade) and ocean/gerstner.glsl.
layout(std430, binding = BUFFER_OCEAN_WAVES) readonly buffer OceanWaves {
    OceanWave oceanWaves[];
};

// A wave breaks when its height 2A reaches about 0.78 times the water depth (the breaker
// index of a solitary wave; McCowan 1894): each wave's amplitude is held to 0.39 x depth,
// so the big waves die out towards the shore while ripples run up to it, and the surface
// meets the beach at still water instead of troughs cutting into the sand. waterDepth below
// the mean surface, m (large in open water).
float oceanShoaling(float amplitude, float waterDepth) {
    return clamp(0.39 * waterDepth / max(amplitude, 1e-6), 0.0, 1.0);
}

// v - v_c: the point's unit direction minus the camera's, formed in double (gerstner.glsl).
vec3 oceanDirectionOffset(dvec3 direction) { return vec3(direction - normalize(gridCameraPosition())); }

// Michelic Eq. 8 without its v r term: the displacement from the sea sphere at unit
// direction v, keeping the waves a surface sampled every `footprint` metres can carry,
// each held to what the water depth below the mean surface allows (oceanShoaling).
vec3 oceanDisplacement(vec3 v, vec3 dv, float footprint, float waterDepth) {
    vec3 displacement = vec3(0.0);
    for (int i = 0; i < ocean.waveCount; ++i) {
        OceanWave w = oceanWaves[i];
        float lod = gerstnerLod(w, footprint);
        if (lod <= 0.0) break;  // sorted longest first: the rest are shorter still
        vec3 travel;
        float oneMinusAbsCos;
        float phase = gerstnerPhase(w, dv, travel, oneMinusAbsCos);
        float q = gerstnerSteepness(w, oneMinusAbsCos, ocean.fadeStart, ocean.fadeEnd);
        float a = w.shape.x * lod * oceanShoaling(w.shape.x, waterDepth);
        displacement += v * (a * sin(phase)) + travel * (q * a * cos(phase));
    }
    return displacement;
}

// Foam where the waves break (the surf at the shore). Shoreward of the depth where it starts
// to break, A / 0.39, a wave keeps the energy (0.39 d)^2 (oceanShoaling), so it spends
// d(0.39 d)^2 / dd = 2 x 0.39^2 d per metre of depth: most at its breaking line, none at the
// waterline (what is left has broken already). Relative to its energy A^2 that is s (the
// share oceanShoaling keeps); the foam's cover is the waves' energy-weighted s where they
// break (ocean/waves.h, foamCover, is its CPU twin), laid on each breaking wave's crests,
// ((1 + sin phase) / 2)^4, and for waves the pixel cannot resolve on the mean of that,
// 35/128: from afar a lighter band along the break, near foam lines on the crests running in.
const float OCEAN_FOAM_CREST_MEAN = 35.0 / 128.0;

// How far oceanNormalAndFoam's normal at `footprint` may lean from the vertical, as a tangent: each
// wave the footprint resolves moves it sideways by lod A k cos(phase) along its travel (a unit
// tangent) and shortens its vertical part by lod Q' A k sin(phase) (Q' <= |Q|; shoaling only lowers
// A), so tan(tilt) <= sum lod A k / (1 - sum lod |Q| A k). 1e30 (any tilt) where that sum reaches 1.
float oceanNormalTiltBound(float footprint) {
    float sideways = 0.0;
    float shortened = 0.0;
    for (int i = 0; i < ocean.waveCount; ++i) {
        OceanWave w = oceanWaves[i];
        float lod = gerstnerLod(w, footprint);
        if (lod <= 0.0) break;  // sorted longest first: the rest are shorter still
        float ak = lod * w.shape.x * w.scale.x;
        sideways += ak;
        shortened += abs(w.shape.y) * ak;
    }
    return shortened < 1.0 ? sideways / (1.0 - shortened) : 1.0e30;
}

// Michelic Eq. 10's normal from the waves a pixel of `footprint` metres resolves; the
// slopes of the waves it cannot resolve go into slopeVariance instead (the mean square
// slope of a sine of amplitude A and wavenumber k is (A k)^2 / 2), which widens the sun's
// glitter as a rougher sea does. foam: the cover above, from the same phases (0 in water
// deeper than every wave's breaking depth, `breakingDepth`).
vec3 oceanNormalAndFoam(vec3 v, vec3 dv, float footprint, float waterDepth, float breakingDepth,
                        out float slopeVariance, out float foam) {
    vec3 normal = v;
    slopeVariance = 0.0;
    float energy = 0.0;
    foam = 0.0;
    int i = 0;
    for (; i < ocean.waveCount; ++i) {
        OceanWave w = oceanWaves[i];
        float lod = gerstnerLod(w, footprint);
        if (lod <= 0.0) {  // sorted longest first: this and the rest only roughen (short: no shoaling)
            slopeVariance += w.scale.z;
            break;
        }
        float kept = oceanShoaling(w.shape.x, waterDepth);
        float ak = w.shape.x * w.scale.x * kept;
        slopeVariance += (1.0 - lod) * 0.5 * ak * ak;
        vec3 travel;
        float oneMinusAbsCos;
        float phase = gerstnerPhase(w, dv, travel, oneMinusAbsCos);
        float q = gerstnerSteepness(w, oneMinusAbsCos, ocean.fadeStart, ocean.fadeEnd);
        normal -= v * (lod * q * ak * sin(phase)) + travel * (lod * ak * cos(phase));
        energy += w.shape.x * w.shape.x;
        if (kept < 1.0) {  // breaking: its foam on its crests
            float crest = 0.5 + 0.5 * sin(phase);
            foam += w.shape.x * w.shape.x * kept * mix(OCEAN_FOAM_CREST_MEAN, crest * crest * crest * crest, lod);
        }
    }
    // The waves too short to resolve: their energy and their foam's mean, where any may break
    // (a loop of one turn or none: the open sea skips it).
    for (int shallow = 0; shallow < (waterDepth < breakingDepth ? 1 : 0); ++shallow) {
        for (; i < ocean.waveCount; ++i) {
            float a = oceanWaves[i].shape.x;
            float kept = oceanShoaling(a, waterDepth);
            energy += a * a;
            if (kept < 1.0) foam += a * a * kept * OCEAN_FOAM_CREST_MEAN;
        }
        foam = energy > 0.0 ? foam / energy : 0.0;
    }
    if (!(waterDepth < breakingDepth)) foam = 0.0;  // no wave breaks here (or the foam is off)
    return normalize(normal);
}

vec3 oceanNormal(vec3 v, vec3 dv, float footprint, float waterDepth, out float slopeVariance) {
    float foam;
    return oceanNormalAndFoam(v, dv, footprint, waterDepth, 0.0, slopeVariance, foam);
}
