// Interleaved gradient noise (Jimenez 2014): a march start that differs in every pixel of a
// 3x3 block, so the steps' banding turns into fine, evenly spread noise. (Included by
// render/sky_air.glsl and render/sparse_pattern.glsl, either or both.)
#ifndef GRADIENT_NOISE_GLSL
#define GRADIENT_NOISE_GLSL
float interleavedGradientNoise(ivec2 pixel) {
    vec2 p = vec2(pixel) + 0.5;
    return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715))));
}
#endif
