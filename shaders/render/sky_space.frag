// Space (before the passes "sky" and "sky temporal" where the air does not fill the frame):
// what those passes give a pixel whose ray misses the air's sphere, drawn around the rectangle
// that holds the air (up to four scissored bands: src/render/screen_bound.h's bandsAround), to
// which those passes are scissored: render/sky_medium.glsl's spaceRadiance and spaceSkyMedium,
// exact at once (16 samples' worth: nothing to average). A few instructions a pixel where the
// passes paid for their whole body, masked, on a software renderer.
#include "common/frame_uniforms.glsl"
#include "atmosphere/interface.glsl"
#include "render/sky_medium.glsl"

layout(location = 0) out vec4 outRadiance;
layout(location = 1) out uvec4 outSkyMedium;  // T, S, samples in the history

void main() {
    outRadiance = vec4(spaceRadiance(gl_FragCoord.xy), 1.0);
    outSkyMedium = spaceSkyMedium();
}
