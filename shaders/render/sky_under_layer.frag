// Marks in the stencil (bit UNDER_LAYER_STENCIL_BIT, src/render/renderer.cpp) the pixels whose ray
// stays under the cloud layer, in a frame where only the clock ran (the camera and the sun stood):
// the camera and the pixel's surface point both inside the layer's bottom sphere, so the chord
// between them too. The clock moved nothing such a ray sees (the wind moves only the clouds; the
// surface's own radiance is this frame's, the sea's waves too), so render/sky_temporal.frag's still
// program rebuilds those pixels, the general one the rest (the `ground` view with the explorer's
// clock on: the general reconstruction over every pixel cost 126 ms against the still one's 27;
// docs/PERFORMANCE.md, twenty-third). Discards the others; writes no colour.
#include "common/frame_uniforms.glsl"
#include "clouds/cloud_block.glsl"

in vec2 vNdc;
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;

// km: room for the float the points are formed in.
const float UNDER_LAYER_MARGIN_KM = 0.01;

void main() {
    float distance = texelFetch(surfaceDistance, ivec2(gl_FragCoord.xy), 0).r;  // m, 0: none
    vec3 camera = cameraFromPlanetCentreKm();
    vec3 surface = camera + worldRayFromNdc(vNdc) * (distance / M_PER_KM);
    float under = clouds.bottomRadius - UNDER_LAYER_MARGIN_KM;
    if (!(distance > 0.0 && length(camera) < under && length(surface) < under)) discard;
}
