// The persistent projected grid on the GPU (Michelic Eq. 1-4), mirror of
// src/grid/projected_grid.cpp: grid coordinate g in [-1, 1]^2 -> Eq. 2
// hemisphere pre-displacement shifted by z_s (Eq. 3) -> rotation into the
// world (Eq. 4, carried with the anchor) -> direction from the planet centre
// (Eq. 1). In double precision: the direction feeds positions of planet size
// that are then made camera-relative, and float would round them to half a
// metre (visible steps when standing on a beach).
#include "common/bindings.glsl"
#include "grid/constants.glsl"

// The grid of the pass that draws, uploaded before the frame (src/grid/grid_mesh.h:
// GridBlock, std140: a dvec4 takes 32 bytes).
layout(std140, binding = BLOCK_GRID) uniform GridBlock {
    dvec4 worldFromGridColumns[3];  // Eq. 4's rotation, by column (w unused)
    dvec4 cameraPositionAndRadius;  // xyz: the camera, world frame, m; w: the grid sphere's radius, m
    double zShift;                  // z_s of Eq. 3
    int exponent;                   // n of Eq. 2
    int pointsPerSide;              // N: the grid's points are N x N, index j * N + i
    int stride;                     // cells a patch spans per side (src/grid/grid_stride.h)
} grid;

dmat3 worldFromGrid() {
    return dmat3(grid.worldFromGridColumns[0].xyz, grid.worldFromGridColumns[1].xyz, grid.worldFromGridColumns[2].xyz);
}
dvec3 gridCameraPosition() { return grid.cameraPositionAndRadius.xyz; }
// The sphere the grid lies on: the planet radius for the terrain, the sea's for the ocean.
double gridSphereRadius() { return grid.cameraPositionAndRadius.w; }

double powInt(double x, int n) {
    double result = 1.0;
    for (int i = 0; i < n; ++i) result *= x;
    return result;
}

// Unit direction from the planet centre for grid coordinate g.
dvec3 gridDirection(vec2 g) {
    double gx = double(g.x), gy = double(g.y);
    double hemisphere = (1.0 - powInt(abs(gx), grid.exponent)) * (1.0 - powInt(abs(gy), grid.exponent));  // Eq. 2
    return normalize(worldFromGrid() * dvec3(gx, gy, hemisphere + grid.zShift));                                 // Eq. 4, 1
}

// A patch's centre direction (unit, from the planet centre) and its angular radius, rad, from its
// corners' grid coordinates `g` and directions `d`: the farthest of the corners, the edges'
// midpoints and the centre on the grid (the grid's lines curve between vertices; a stride's patch
// spans several cells), times 1.25 for what lies between them. For the continents map's slope
// bounds over a whole patch (src/ocean/land_cull.h): the sea over land, the ground under the sea.
float patchAngularRadius(vec2 g[4], dvec3 d[4], out vec3 centre) {
    centre = normalize(vec3(d[0] + d[1] + d[2] + d[3]));
    float chord = length(vec3(gridDirection(0.25 * (g[0] + g[1] + g[2] + g[3]))) - centre);
    for (int i = 0; i < 4; ++i) {
        chord = max(chord, length(vec3(d[i]) - centre));
        vec3 mid = vec3(gridDirection(mix(g[i], g[(i + 1) % 4], 0.5)));
        chord = max(chord, length(mid - centre));
    }
    return 1.25 * 2.0 * asin(min(0.5 * chord, 1.0)) + 1e-6;
}

// The grid coordinate of a place on the grid given in point indices (i, j), fractional:
// src/grid/projected_grid.h's gridVertexCoordinate between the points, so a patch of several
// cells (the grids' stride, src/grid/grid_stride.h) puts its vertices where the grid's own
// points and their warp put them (at whole indices, on the points exactly).
vec2 gridCoordinateAt(vec2 index) {
    vec2 g = -1.0 + 2.0 * index / float(grid.pointsPerSide - 1);
    float m = max(abs(g.x), abs(g.y));
    return g * (GRID_CENTRE_DENSITY + (1.0 - GRID_CENTRE_DENSITY) * m * (2.0 - m));
}

// The place on the ocean's grid (exponent OCEAN_GRID_EXPONENT, 4), in point indices, whose
// direction from the planet centre is the unit `direction` (world axes): gridDirection and
// gridCoordinateAt inverted, for a pass that finds its point by the pixel's ray rather than by the
// mesh (ocean/ocean.frag's far field). In the grid's frame the direction is (gx, gy, H(g) + z_s) / s
// for some s > 0 (Eq. 2-4), and s l_z - H(s l) - z_s grows with s from below 0 at z_s / l_z to
// above 0 where H = 1 or where |s l| reaches the grid's edge: bisections keep it bracketed, Newton's
// steps then make it exact to float (4 and 3 reach 2e-4 points over z_s in [0.001, 20] in double;
// 8 and 3 1e-11, 2 ms more of the far field's 21 from orbit at 1280x720; 24 bisections alone 1e-8). Then
// gridCoordinateAt's warp m (c + (1 - c) m (2 - m)) of the largest coordinate G, increasing on
// [0, 1], by Newton from the root of c m + 2 (1 - c) m^2 = G (the warp without its cubic term,
// at or below the root: 3 steps; from G / c it took 6). Only where
// z_s > 0 (the grid seen from above the cap it covers, src/grid/projected_grid.cpp). The exponent
// is a constant and the loops' counts too: a software renderer runs a loop of a uniform's count
// with a mask test per step, and this ran at 20 ms a frame from orbit with the block's exponent.
vec2 gridPointOf(vec3 direction) {
    vec3 l = transpose(mat3(worldFromGrid())) * direction;
    float zs = float(grid.zShift);
    float lz = max(l.z, 1e-20);
    float ax = abs(l.x), ay = abs(l.y);
    float lo = zs / lz, hi = min((1.0 + zs) / lz, 1.0 / max(max(ax, ay), 1e-20));
    for (int i = 0; i < 4; ++i) {
        float s = 0.5 * (lo + hi);
        vec2 g2 = vec2(s * ax, s * ay);
        g2 = min(g2, 1.0);
        g2 *= g2;
        float hemisphere = (1.0 - g2.x * g2.x) * (1.0 - g2.y * g2.y);  // Eq. 2, n = 4
        if (s * lz - hemisphere - zs > 0.0) hi = s;
        else lo = s;
    }
    float s = 0.5 * (lo + hi);
    for (int i = 0; i < 3; ++i) {
        vec2 g = min(vec2(s * ax, s * ay), 1.0);
        vec2 g3 = g * g * g;
        vec2 oneMinus = 1.0 - g3 * g;
        float slope = lz + 4.0 * (g3.x * ax * oneMinus.y + oneMinus.x * g3.y * ay);
        s = clamp(s - (s * lz - oneMinus.x * oneMinus.y - zs) / max(slope, 1e-20), lo, hi);
    }
    vec2 g = s * l.xy;
    const float c = GRID_CENTRE_DENSITY;
    float largest = min(max(abs(g.x), abs(g.y)), 1.0);
    float m = min((sqrt(c * c + 8.0 * (1.0 - c) * largest) - c) / (4.0 * (1.0 - c)), 1.0);
    for (int i = 0; i < 3; ++i)
        m = clamp(m - (m * (c + (1.0 - c) * m * (2.0 - m)) - largest) / (c + (1.0 - c) * m * (4.0 - 3.0 * m)), 0.0, 1.0);
    vec2 unwarped = g / (c + (1.0 - c) * m * (2.0 - m));
    return (unwarped + 1.0) * 0.5 * float(grid.pointsPerSide - 1);
}

// A patch's place at the tessellation coordinate `uv`, in point indices: between its first and
// third corners' grid points (`first`, `third`: tcPoint[0] and [2]).
vec2 patchGridPoint(ivec2 first, ivec2 third, vec2 uv) { return vec2(first) + uv * vec2(third - first); }

// The grid coordinate at `uv` in a patch whose corners have the coordinates g0..g3 and the
// points `first` and `third` (the evaluation stages'): a one-cell patch mixes its corners (as it
// always has); a stride's patch (src/grid/grid_stride.h) follows the grid's warp between its
// points, where the control stages count its levels and where the grid's own points lie.
vec2 patchGridCoordinate(vec2 g0, vec2 g1, vec2 g2, vec2 g3, ivec2 first, ivec2 third, vec2 uv) {
    if (grid.stride == 1) return mix(mix(g0, g1, uv.x), mix(g3, g2, uv.x), uv.y);
    return gridCoordinateAt(patchGridPoint(first, third, uv));
}

// Camera-relative position (m, world axes) of the point at `radius` along a direction.
vec3 cameraRelative(dvec3 direction, double radius) { return vec3(direction * radius - gridCameraPosition()); }
