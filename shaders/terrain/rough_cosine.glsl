// The clamped cosine of a surface whose normals spread about their mean (Toksvig 2005, LEAN
// mapping, Olano & Baker 2010, in spirit): a pixel that covers many detail facets receives
// the mean of max(0, n.l) over them, not max(0, mean n . l). With the facets' n.l spread
// normally about mu with standard deviation sigma:
//
//   E[max(0, mu + sigma X)] = mu Phi(mu / sigma) + sigma phi(mu / sigma),  X ~ N(0, 1)
//
// (Phi, phi: the standard normal's distribution and density). It is max(0, mu) as sigma -> 0,
// above it everywhere else, and sigma / sqrt(2 pi) at mu = 0: slopes turned just away from the
// sun still catch light on the facets that face it. Written in the GLSL subset C++ compiles
// (STYLE habit 1): terrain/detail_texture.cpp includes it and tests/test_ground_detail.cpp
// checks it against a Monte Carlo mean.

// erf(x) for x >= 0, Abramowitz & Stegun 7.1.26: absolute error under 1.5e-7.
float erfNonNegative(float x) {
    float t = 1.0f / (1.0f + 0.3275911f * x);
    float poly = t * (0.254829592f + t * (-0.284496736f + t * (1.421413741f + t * (-1.453152027f + t * 1.061405429f))));
    return 1.0f - poly * exp(-x * x);
}

// The standard normal distribution function Phi(x).
float standardNormalCdf(float x) {
    float e = erfNonNegative(abs(x) * 0.70710678f);
    return 0.5f + 0.5f * (x >= 0.0f ? e : -e);
}

// E[max(0, mu + sigma X)] for X ~ N(0, 1): the mean clamped cosine of facets whose n.l has
// mean mu and standard deviation sigma (>= 0).
float expectedClampedCosine(float mu, float sigma) {
    if (sigma < 1.0e-5f) return max(mu, 0.0f);
    float x = mu / sigma;
    return mu * standardNormalCdf(x) + sigma * 0.39894228f * exp(-0.5f * x * x);
}
