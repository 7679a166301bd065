// The sea floor's dark depths (ocean/water.glsl, SEA_FLOOR_DARK_DEPTH_M) and the pixels where no
// ground was drawn: the surface light's first draw marks them in its stencil and discards every
// other pixel (src/render/renderer.cpp). Its lighting program then runs only where the stencil is
// clear, and its SEA_FLOOR_DARK program only on the marked pixels, to write the dark depths'
// distance and no light, and to discard where nothing was drawn: what the lighting program gives
// them (render/surface_light.frag), with the same expression for the depth. Two texel reads a
// pixel, where an `if` in the lighting program left a software renderer shading every pixel of
// the sea floor, masked (issue 15: at `orbit` half the ground, at `sea` nearly all of it), and
// its discard left it shading the pixels with no ground (the sea floor the terrain left out
// under the sea, terrain/terrain.tesc; the sky in the ground's rectangle).
#include "common/frame_uniforms.glsl"
#include "common/gbuffer.glsl"
#include "atmosphere/interface.glsl"
#include "ocean/water.glsl"

layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gDepth;
#include "render/surface_point.glsl"

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    bool drawn = texelFetch(gDepth, pixel, 0).r > 0.0;
    if (drawn && depthBelowSeaAt(texelFetch(gNormal, pixel, 0).w) < SEA_FLOOR_DARK_DEPTH_M) discard;
}
