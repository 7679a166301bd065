// Tessellation control helpers shared by the projected grids (terrain and ocean,
// Michelic §3): levels from an edge's size on screen and its chord's sag, and culling against
// a widened frustum. Include after common/frame_uniforms.glsl and terrain/grid.glsl.
const float MAX_TESSELLATION_LEVEL = 64.0;
#include "grid/constants.glsl"

// Level for the edge between two camera-relative points: its angular size seen from the
// nearer end, in units of targetPixels, and at least enough segments that each one's chord of
// the sphere sags (length^2 / 8r) under MAX_SAG_PIXELS there and under maxSagM. The first sag
// bound binds only far away at a low resolution, where a pixel is tens of kilometres (from
// space at 160x90 the limb's 32-pixel chords of the sea sagged 3.5 pixels: segments of at most
// 8.6 pixels there, 24 from space at 1280x720). Depends on the two points only, so patches
// sharing the edge agree (no cracks).
// Segments for an edge whose size on screen is `sizeRad`, its chord `chord` m long, its nearer end
// `nearest` m away: the size over targetPixels, and the chords' sag bounds.
float segmentsForSize(float sizeRad, float nearest, float chord, float targetPixels, float maxSagM) {
    float sag = min(MAX_SAG_PIXELS * nearest * radiansPerPixel(), maxSagM);
    return max(sizeRad / radiansPerPixel() / targetPixels, chord / sqrt(8.0 * frame.planetRadius * sag));
}
float edgeSegments(vec3 a, vec3 b, float targetPixels, float maxSagM) {  // unclamped
    float nearest = max(min(length(a), length(b)), 1e-3);
    float chord = length(a - b);
    return segmentsForSize(chord / nearest, nearest, chord, targetPixels, maxSagM);
}
float edgeLevel(vec3 a, vec3 b, float targetPixels, float maxSagM) {
    return clamp(edgeSegments(a, b, targetPixels, maxSagM), 1.0, MAX_TESSELLATION_LEVEL);
}

// The same with the edge's size taken as what of it can show on screen: its apparent angle (the
// angle between its ends seen from the camera: an edge pointing away from the camera at a grazing
// view is short on screen however long it is), or, where larger, the relief that segments of it
// could show, `reliefSlope` (rise over run) times its length over the nearer end's distance.
// edgeSegments takes every edge as if seen face on (reliefSlope 1): seen from 2 m above a meadow,
// the ground's edges towards the horizon split into segments a fraction of a pixel high on screen
// (the `ground` view, 1280x720: 192 000 triangles for 460 000 pixels of ground, and llvmpipe's
// tessellator and rasteriser paid for each; the heights themselves were a tenth of it).
// Symmetric in a and b: patches sharing the edge agree.
float edgeSegmentsShown(vec3 a, vec3 b, float targetPixels, float maxSagM, float reliefSlope) {
    float nearest = max(min(length(a), length(b)), 1e-3);
    float chord = length(a - b);
    float apparent = 2.0 * asin(min(0.5 * length(normalize(a) - normalize(b)), 1.0));
    return segmentsForSize(max(apparent, reliefSlope * chord / nearest), nearest, chord, targetPixels, maxSagM);
}

// Segments a grid cell's edge keeps in a stride's patch where the sphere is seen nearly edge-on
// (either end within LIMB_COSINE of it, the view ray against the vertical): one, as each cell
// is a patch of its own at stride 1. There the chords' sag shows as the silhouette itself, and
// under even a quarter of a pixel of it the limb's pixel centres fell outside the planet (from
// orbit at 160x90, 20 of some 160 along the limb; RenderTest.TerrainLeavesNoHolesWhereTheGroundMustBe).
const float LIMB_COSINE = 0.1;
float limbCellSegments(vec3 a, vec3 b) {
    float cosA = abs(dot(normalize(a), normalize(a - frame.planetCenterFromCamera)));
    float cosB = abs(dot(normalize(b), normalize(b - frame.planetCenterFromCamera)));
    return min(cosA, cosB) < LIMB_COSINE ? 1.0 : 0.0;
}

// The camera-relative point on the sphere of radius `radius` at place c of `cells` from grid
// point `a` to grid point `b` (indices; one row or column of the grid).
vec3 gridLinePoint(ivec2 a, ivec2 b, int c, int cells, double radius) {
    return cameraRelative(gridDirection(gridCoordinateAt(mix(vec2(a), vec2(b), float(c) / float(cells)))), radius);
}

// A stride's patch edge (src/grid/grid_stride.h), from grid point `a` to grid point `b`, spans
// several cells, and the tessellator splits it evenly in grid coordinates, which the projection
// (Michelic Eq. 2-4) does not map evenly onto the sphere: near the grid's edge, at the horizon,
// its cells grow fast. So the edge takes as many segments per cell as its neediest cell would ask
// for on its own (edgeSegments on the grid's sphere, `targetPixels` and `maxSagM`, and one at the
// limb: limbCellSegments), and each segment is no worse than a stride-1 cell's; the end-to-end
// chord under-counted them, and the limb from orbit receded by a pixel at 160x90. Depends on the
// edge's grid points only: neighbouring patches agree.
float strideEdgeLevel(ivec2 a, ivec2 b, float targetPixels, float maxSagM) {
    int cells = max(abs(b.x - a.x), abs(b.y - a.y));
    double radius = gridSphereRadius();
    float need = 0.0;
    vec3 previous = gridLinePoint(a, b, 0, cells, radius);
    for (int c = 1; c <= cells; ++c) {
        vec3 next = gridLinePoint(a, b, c, cells, radius);
        need = max(need, edgeSegments(previous, next, targetPixels, maxSagM));
        need = max(need, limbCellSegments(previous, next));
        previous = next;
    }
    return clamp(need * float(cells), 1.0, MAX_TESSELLATION_LEVEL);
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
void setQuadLevels(vec3 p[4], float targetPixels, float maxSagM) {
    setQuadLevelsFromEdges(edgeLevel(p[0], p[3], targetPixels, maxSagM), edgeLevel(p[0], p[1], targetPixels, maxSagM),
                           edgeLevel(p[1], p[2], targetPixels, maxSagM), edgeLevel(p[3], p[2], targetPixels, maxSagM));
}

// How far a patch's surface can bulge out of its corners' shell: the sphere between corners
// `diagonal` apart rises above their chord by about diagonal^2 / 8r (with stride patches
// (grid/grid_stride.h) from space, kilometres; under a metre for a stride-1 patch near the
// ground), so a culling shell is widened by it. m, for the grid sphere's radius in m.
float patchBulgeM(vec3 p[4], float radius) {
    float diagonal = max(length(p[0] - p[2]), length(p[1] - p[3]));
    return diagonal * diagonal / (8.0 * radius);
}

// The shell's outer corners (corners[4..7]) raised by `bulge` m along the vertical.
void raiseOuterCorners(inout vec3 corners[8], float bulge) {
    for (int i = 4; i < 8; ++i) corners[i] += normalize(corners[i] - frame.planetCenterFromCamera) * bulge;
}

void cullPatch() {
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = 0.0;
    gl_TessLevelInner[0] = gl_TessLevelInner[1] = 0.0;
}
