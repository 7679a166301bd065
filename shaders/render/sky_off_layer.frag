// Marks in the stencil (the top bit, src/render/renderer.cpp's drawSkyTemporalSplit) the pixels
// whose ray never enters the cloud layer, in a frame where only the clock ran (the camera and the
// sun stood): from under the layer, a ray whose surface point is under its bottom too (the chord
// between two points inside the bottom sphere stays inside it); from above it, a ray whose closest
// approach to the planet's centre, up to its surface point or into space, stays above its top. The
// clock moved nothing such a ray sees (the wind moves only the clouds; the surface's own radiance is
// this frame's, the sea's waves too), so render/sky_temporal.frag's still program rebuilds those
// pixels, the general one the rest (the `ground` view with the explorer's clock on: the general
// reconstruction over every pixel cost 124 ms, 81-90 with the meadow split off; docs/PERFORMANCE.md,
// twenty-third). Discards the others; writes no colour.
#include "common/frame_uniforms.glsl"
#include "atmosphere/definitions.glsl"  // Length, Number: cloud_model.glsl's types
#include "clouds/cloud_model.glsl"
#include "clouds/cloud_block.glsl"

in vec2 vNdc;
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;

// km: room for the float the points are formed in (the shell is widened by it).
const float OFF_LAYER_MARGIN_KM = 0.01;

// Whether the ray from `camera` (km from the planet centre) along `dir` to its surface point
// (`distanceM` m away; 0: none, into space) has no part inside the cloud layer: the march's own
// intervals (clouds/cloud_model.glsl's CloudLayerIntervals) on the shell widened by the margin, so
// a pixel marked here is one the march would have found no layer for. From inside the layer every
// ray has a part there.
bool rayMissesTheLayer(vec3 camera, vec3 dir, float distanceM) {
    float r = length(camera);
    float toEnd = distanceM > 0.0 ? distanceM / M_PER_KM : 1.0e30;  // km
    vec2 first;
    vec2 second;
    return CloudLayerIntervals(r, dot(camera, dir) / r, toEnd, clouds.bottomRadius - OFF_LAYER_MARGIN_KM,
                               clouds.topRadius + OFF_LAYER_MARGIN_KM, first, second) == 0;
}

void main() {
    float distance = texelFetch(surfaceDistance, ivec2(gl_FragCoord.xy), 0).r;  // m, 0: none
    if (!rayMissesTheLayer(cameraFromPlanetCentreKm(), worldRayFromNdc(vNdc), distance)) discard;
}
