// The surface light's stencil, marked in one pass before its lighting programs run
// (src/render/renderer.cpp, drawSurfaceLight), each kept off the others' pixels by the early stencil test:
//  - 1 (with uMarkDark): the sea floor's dark depths (ocean/water.glsl, SEA_FLOOR_DARK_DEPTH_M) and the
//    pixels where no ground was drawn. The lighting program then runs only where the stencil is clear,
//    and its SEA_FLOOR_DARK program only on these, to write the dark depths' distance and no light, and
//    to discard where nothing was drawn: what the lighting program gives them (render/surface_light.frag),
//    with the same expression for the depth (render/surface_point.glsl's depthBelowSeaAt). Two texel
//    reads a pixel, where an `if` in the lighting program left a software renderer shading every pixel
//    of the sea floor, masked (issue 15: at `orbit` half the ground, at `sea` nearly all of it), and its
//    discard left it shading the pixels with no ground (the sea floor the terrain left out under the sea,
//    terrain/terrain.tesc; the sky in the ground's rectangle).
//  - SUN_CLEAR_MARK (src/render/renderer.cpp's kSunClearOfClouds) on the other ground pixels whose way to
//    the sun surely meets no cloud, where the clouds' shadow is 1 and the surface light's program without
//    it (SUN_CLEAR_OF_CLOUDS) lights them the same: a software renderer runs the shadow's code for every
//    pixel, masked, and its clear sky check's two cube map reads took a third of the surface light's time
//    at `ground`. Which pixels, the CPU says for the whole frame (Renderer::clearSkyDepth, uClearDepth):
//    those nearer than a distance within which every ground point's way to the sun stays in the clear sky
//    around the camera (the clear sky map's angle at the camera's direction: within it the weather's
//    coverage is 0, and so is every density the shadow's samples or its far field would find, whose
//    transmittance is then exactly 1). Here that is one depth compare, since a per-pixel test of the
//    point's own way cost more than the shadow's code it spared (surface point, the layer's intervals:
//    11 ms at `ground`, 1280x720 on llvmpipe).
// Built with STENCIL_EXPORT 1 where the GL has ARB_shader_stencil_export (Mesa's llvmpipe does): one pass, the
// value the fragment's own (as two full-screen passes the marks cost 7.5 and 5 ms at `ground`: the cost is the
// pass, not its two texel reads). Without it, a pass per mark: uOnlyMark names the one this pass keeps, and the
// renderer's stencil reference is its value. Discards the pixels it leaves unmarked; writes no colour.
#ifndef STENCIL_EXPORT
#define STENCIL_EXPORT 0
#endif
#if STENCIL_EXPORT
#extension GL_ARB_shader_stencil_export : require
#endif
#include "common/frame_uniforms.glsl"
#include "common/gbuffer.glsl"
#include "atmosphere/interface.glsl"
#include "ocean/water.glsl"

layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gDepth;
#include "render/surface_point.glsl"

// The reversed-Z depth nearer than which the way to the sun is clear (nearer is larger; 1: no pixel, as
// no depth is above it), and whether the dark depths and the pixels with no ground are marked (1) or not.
layout(location = 0) uniform float uClearDepth;
layout(location = 1) uniform int uMarkDark;
layout(location = 2) uniform int uOnlyMark;  // without STENCIL_EXPORT: the mark this pass keeps
const int DARK_MARK = 1;
const int SUN_CLEAR_MARK = 0x40;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(gDepth, pixel, 0).r;
    bool dark = depth <= 0.0 || depthBelowSeaAt(texelFetch(gNormal, pixel, 0).w) >= SEA_FLOOR_DARK_DEPTH_M;
    int mark = uMarkDark != 0 && dark ? DARK_MARK : depth > uClearDepth ? SUN_CLEAR_MARK : 0;
#if STENCIL_EXPORT
    if (mark == 0) discard;
    gl_FragStencilRefARB = mark;
#else
    if (mark != uOnlyMark) discard;
#endif
}
