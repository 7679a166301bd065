// Terrain tessellation control (Michelic §3): culls patches outside a slightly
// widened view frustum, counting the highest possible terrain, and sets
// tessellation levels from each edge's size on screen. An edge's level depends
// only on its two end points (taken in a fixed order), so neighbouring patches
// agree on shared edges and no cracks open.
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"

layout(vertices = 4) out;
in vec2 vGrid[];
out vec2 tcGrid[];

uniform float uMaxTerrainHeight;    // m
uniform float uTargetEdgePixels;    // wanted triangle edge length on screen
const float FRUSTUM_WIDENING = 1.2; // culling planes 20 % wider than the view
const float MAX_LEVEL = 64.0;

// Level for the edge between two points: its angular size seen from the nearer end.
float edgeLevel(vec3 a, vec3 b) {
    float pixelsPerRadian = frame.viewport.y / (2.0 * atan(1.0 / frame.clipFromView[1][1]));
    float angle = length(a - b) / max(min(length(a), length(b)), 1e-3);
    return clamp(angle * pixelsPerRadian / uTargetEdgePixels, 1.0, MAX_LEVEL);
}

bool outsideFrustum(vec3 corners[8]) {
    // Clip-space plane tests are linear, so they hold for points behind the camera too.
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

    vec3 low[4];
    vec3 corners[8];
    for (int i = 0; i < 4; ++i) {
        dvec3 d = gridDirection(vGrid[i]);
        low[i] = cameraRelative(d, uPlanetRadius);
        corners[i] = low[i];
        corners[i + 4] = cameraRelative(d, uPlanetRadius + double(uMaxTerrainHeight));
    }
    if (outsideFrustum(corners)) {
        gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = 0.0;
        gl_TessLevelInner[0] = gl_TessLevelInner[1] = 0.0;
        return;
    }
    // Patch corners 0 (i, j), 1 (i+1, j), 2 (i+1, j+1), 3 (i, j+1). Quad outer levels:
    // [0] edge u = 0 (0-3), [1] edge v = 0 (0-1), [2] edge u = 1 (1-2), [3] edge v = 1 (3-2).
    gl_TessLevelOuter[0] = edgeLevel(low[0], low[3]);
    gl_TessLevelOuter[1] = edgeLevel(low[0], low[1]);
    gl_TessLevelOuter[2] = edgeLevel(low[1], low[2]);
    gl_TessLevelOuter[3] = edgeLevel(low[3], low[2]);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
    gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
}
