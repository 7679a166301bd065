// Ocean tessellation control (Michelic §3-4): culls patches outside a widened frustum,
// counting the highest crests and lowest troughs, and sets levels from each edge's size
// on screen; an edge's level depends on its two end points only, so neighbours agree.
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"

layout(vertices = 4) out;
in vec2 vGrid[];
out vec2 tcGrid[];

uniform float uMaxWaveHeight;      // m: the sum of the amplitudes
uniform float uTargetEdgePixels;
const float FRUSTUM_WIDENING = 1.2;
const float MAX_LEVEL = 64.0;

float edgeLevel(vec3 a, vec3 b) {
    float pixelsPerRadian = frame.viewport.y / (2.0 * atan(1.0 / frame.clipFromView[1][1]));
    float angle = length(a - b) / max(min(length(a), length(b)), 1e-3);
    return clamp(angle * pixelsPerRadian / uTargetEdgePixels, 1.0, MAX_LEVEL);
}

bool outsideFrustum(vec3 corners[8]) {
    for (int plane = 0; plane < 4; ++plane) {
        bool allOutside = true;
        for (int i = 0; i < 8; ++i) {
            vec4 c = frame.clipFromView * (frame.viewFromWorld * vec4(corners[i], 1.0));
            float coordinate = plane < 2 ? c.x : c.y;
            float side = (plane % 2 == 0) ? coordinate : -coordinate;
            if (side <= FRUSTUM_WIDENING * c.w) allOutside = false;
        }
        if (allOutside) return true;
    }
    return false;
}

void main() {
    tcGrid[gl_InvocationID] = vGrid[gl_InvocationID];
    if (gl_InvocationID != 0) return;
    vec3 mean[4];
    vec3 corners[8];
    for (int i = 0; i < 4; ++i) {
        dvec3 d = gridDirection(vGrid[i]);
        mean[i] = cameraRelative(d, uPlanetRadius);
        corners[i] = cameraRelative(d, uPlanetRadius - double(uMaxWaveHeight));
        corners[i + 4] = cameraRelative(d, uPlanetRadius + double(uMaxWaveHeight));
    }
    if (outsideFrustum(corners)) {
        gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = 0.0;
        gl_TessLevelInner[0] = gl_TessLevelInner[1] = 0.0;
        return;
    }
    gl_TessLevelOuter[0] = edgeLevel(mean[0], mean[3]);
    gl_TessLevelOuter[1] = edgeLevel(mean[0], mean[1]);
    gl_TessLevelOuter[2] = edgeLevel(mean[1], mean[2]);
    gl_TessLevelOuter[3] = edgeLevel(mean[3], mean[2]);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
    gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
}
