// Tessellation control helpers shared by the projected grids (terrain and ocean,
// Michelic §3): levels from an edge's size on screen, and culling against a widened
// frustum. Include after common/frame_uniforms.glsl.
const float FRUSTUM_WIDENING = 1.2;  // culling planes 20 % wider than the view
const float MAX_TESSELLATION_LEVEL = 64.0;

// Level for the edge between two camera-relative points: its angular size seen from the
// nearer end, in units of targetPixels. Depends on the two points only, so patches sharing
// the edge agree (no cracks).
float edgeLevel(vec3 a, vec3 b, float targetPixels) {
    float angle = length(a - b) / max(min(length(a), length(b)), 1e-3);
    return clamp(angle / radiansPerPixel() / targetPixels, 1.0, MAX_TESSELLATION_LEVEL);
}

// True when all eight camera-relative corners of a patch's bounding shell lie outside one
// plane of the widened frustum. Clip-space plane tests are linear, so they hold for points
// behind the camera too.
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

// Quad outer levels as given (patch corners 0 (i, j), 1 (i+1, j), 2 (i+1, j+1), 3 (i, j+1));
// outer [0] is edge 0-3, [1] 0-1, [2] 1-2, [3] 3-2; the inner levels the larger of each pair.
void setQuadLevelsFromEdges(float edge03, float edge01, float edge12, float edge32) {
    gl_TessLevelOuter[0] = edge03;
    gl_TessLevelOuter[1] = edge01;
    gl_TessLevelOuter[2] = edge12;
    gl_TessLevelOuter[3] = edge32;
    gl_TessLevelInner[0] = max(edge01, edge32);
    gl_TessLevelInner[1] = max(edge03, edge12);
}

// Quad levels from the four corners' sizes on screen.
void setQuadLevels(vec3 p[4], float targetPixels) {
    setQuadLevelsFromEdges(edgeLevel(p[0], p[3], targetPixels), edgeLevel(p[0], p[1], targetPixels),
                           edgeLevel(p[1], p[2], targetPixels), edgeLevel(p[3], p[2], targetPixels));
}

void cullPatch() {
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = 0.0;
    gl_TessLevelInner[0] = gl_TessLevelInner[1] = 0.0;
}
