// The terrain's detail texture: a small tiling height field baked procedurally at start-up
// (no image files), sampled tri-planar by terrain/ground_material.frag for the detail normals and the
// materials' colour variation at ground level (Michelic §6: "a three-planar projected normal
// map to get detail normals"; Sperlhofer 4.4: normal mapping and multi-texturing).
//
// Each channel is a sum of waves cos(2 pi (k . uv) + phase) with integer wave vectors k, so
// the texture tiles exactly, and its derivatives are exact sums of sines, not finite
// differences. Texel (u, v) in [0, 1)^2 of a size x size image:
//   x, y  dh/du, dh/dv of the height field h (per unit of texture coordinate)
//   z     h itself: zero mean, unit standard deviation (the shading's fine variation)
//   w     a second, independent field with a redder spectrum (patches: dry and lush grass)
// Amplitudes fall as 1/|k| (the slopes' spectrum is flat: every scale adds as much relief),
// so mip levels, which average texels, average slopes and heights linearly: a far pixel's
// detail is the mean of what a closer one shows, and fades to flat without a visible line.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gl/handle.h"

namespace planet::terrain {

struct DetailTexture {
    int size = 0;
    std::vector<glm::vec4> texels;  // row-major, size x size
    float fineScale = 1.0f;         // what the fine field's waves were scaled by to unit spread
    // Per mip level (0 = the full size, as glGenerateMipmap's 2x2 box averages make them): the
    // variance of the slope (x^2 + y^2, per unit of texture coordinate, squared) that the
    // level's averaging removed: level 0's mean square less the level's (0 at level 0; the
    // whole variance at the 1x1 level, whose mean slope is 0). What the shader's filter
    // takes from the normal and hands to the lighting (terrain/detail.glsl).
    std::vector<float> lostSlopeVariance;
};

// Bakes the detail texture (size a power of two >= 16; deterministic for a seed).
DetailTexture bakeDetailTexture(int size = 256, std::uint32_t seed = 7);

// The height h (channel z) at texture coordinate uv, evaluated from the waves directly
// (any uv, it repeats with period 1): what the texels sample, for tests.
float detailHeightAt(const DetailTexture& texture, glm::vec2 uv);

// E[max(0, mu + sigma X)], X ~ N(0, 1): shaders/terrain/rough_cosine.glsl compiled as C++.
float expectedClampedCosine(float mu, float sigma);

// The two tri-planar projections the detail takes at a point with vertical `up` (a unit
// vector): each a pair of world axes (a, b) that are its texture's (u, v), and its weight
// (w0 + w1 = 1). shaders/terrain/detail_planes.glsl compiled as C++.
struct DetailPlanes {
    glm::vec3 a0, b0, a1, b1;
    float w0, w1;
};
DetailPlanes detailPlanes(glm::vec3 up);

// The GL texture: RGBA16F, full mip chain, GL_REPEAT, trilinear (isotropic: see the .cpp).
gl::Texture makeDetailGlTexture(const DetailTexture& texture);

}  // namespace planet::terrain
