// Marks in the surface light's stencil (the bit src/render/renderer.cpp's kSunClearOfClouds) the
// ground pixels whose way to the sun surely meets no cloud, where the clouds' shadow is 1 and the
// surface light's program without it (SUN_CLEAR_OF_CLOUDS) lights them the same: a software renderer
// runs the shadow's code for every pixel, masked, and its clear sky check's two cube map reads took a
// third of the surface light's time at `ground`. Which pixels, the CPU says for the whole frame
// (Renderer::clearSkyDepth): those nearer than a distance within which every ground point's way to
// the sun stays in the clear sky around the camera (the clear sky map's angle at the camera's
// direction: within it the weather's coverage is 0, and so is every density the shadow's samples or
// its far field would find, whose transmittance is then exactly 1). Here that is one depth compare,
// since a per-pixel test of the point's own way cost more than the shadow's code it spared (surface
// point, the layer's intervals: 11 ms at `ground`, 1280x720 on llvmpipe). Discards the rest; writes
// no colour. The renderer's stencil test keeps it to the ground that is not the sea floor's dark depths.
#include "common/bindings.glsl"

layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gDepth;
// The reversed-Z depth of that distance (nearer is larger; 0 where nothing was drawn).
layout(location = 0) uniform float uClearDepth;

void main() {
    if (texelFetch(gDepth, ivec2(gl_FragCoord.xy), 0).r <= uClearDepth) discard;
}
