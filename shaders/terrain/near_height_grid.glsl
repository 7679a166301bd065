// The height field near the camera on a grid (src/terrain/near_height_grid.h): terrainHeightNearGrad
// (terrain/height.glsl, every mountain octave with its gradient) evaluated once at the grid's points
// by terrain/near_height_grid.comp, and read back bilinearly by the ground's material where it would
// otherwise evaluate it at every pixel (terrain/ground_material.frag: a third of its time at `ground`).
// The grid lies on the plane tangent to the planet at its origin, a point of the sphere of the
// planet's radius, seen from the planet's centre (gnomonic: a direction d is at x = R (d.east) /
// (d.up), y = R (d.north) / (d.up)); it stays put in the world until the camera has moved far from
// its origin, so what it says of a place does not change while the camera moves near it.
// Include after common/bindings.glsl.

layout(std140, binding = BLOCK_TERRAIN_NEAR_GRID) uniform NearHeightGridBlock {
    vec4 nearGridOrigin;  // xyz: the grid's origin from the camera (m, world axes, formed in double); w: the spacing, m
    vec4 nearGridEast;    // xyz: the unit east at the origin (the grid's x); w: the planet's radius, m
    vec4 nearGridNorth;   // xyz: the unit north there (the grid's y); w: the grid's points per side, N
    vec4 nearGridUp;      // xyz: the unit up at the origin; w: unused
};

// The grid's plane coordinates (m) of point (i, j): (i - (N - 1) / 2, j - (N - 1) / 2) spacings.
vec2 nearGridPlaneAt(ivec2 point) { return (vec2(point) - 0.5 * (nearGridNorth.w - 1.0)) * nearGridOrigin.w; }

// The point of the planet-radius sphere at plane coordinates `plane` (m), from the grid's origin (m,
// world axes): R (d - up) with d = (R up + v) / |R up + v|, v the plane offset, written without
// subtracting numbers of planet size (R - |R up + v| = -|v|^2 / (R + |R up + v|)).
vec3 nearGridPointFromOrigin(vec2 plane) {
    float radius = nearGridEast.w;
    vec3 v = nearGridEast.xyz * plane.x + nearGridNorth.xyz * plane.y;
    float along = sqrt(radius * radius + dot(v, v));
    return (radius / along) * (v - nearGridUp.xyz * (dot(v, v) / (radius + along)));
}

// The plane coordinates (m) of the direction of the point at `pointFromCamera` (m, world axes): with
// q the point from the origin, the point is (R + h) d and q = (R + h) d - R up, so d.east / d.up =
// q.east / (R + q.up).
vec2 nearGridPlaneOf(vec3 pointFromCamera) {
    vec3 q = pointFromCamera - nearGridOrigin.xyz;
    float radius = nearGridEast.w;
    return radius * vec2(dot(q, nearGridEast.xyz), dot(q, nearGridNorth.xyz)) / (radius + dot(q, nearGridUp.xyz));
}

#ifdef NEAR_GRID_SAMPLER
// The height's slope along the grid's plane (m per m, x and y) at a grid point of plane coordinates
// `plane` whose gradient (per unit of direction, world axes) is `gradient`: the gradient times the
// change of the point's direction d = (R up + v) / L per metre of v, (axis - d (d.axis)) / L.
vec2 nearGridPlaneSlope(vec2 plane, vec3 gradient) {
    float radius = nearGridEast.w;
    vec3 v = nearGridEast.xyz * plane.x + nearGridNorth.xyz * plane.y;
    float along = sqrt(radius * radius + dot(v, v));
    vec3 d = (nearGridUp.xyz * radius + v) / along;
    float radial = dot(gradient, d);
    return vec2(dot(gradient, nearGridEast.xyz) - radial * dot(d, nearGridEast.xyz),
                dot(gradient, nearGridNorth.xyz) - radial * dot(d, nearGridNorth.xyz)) / along;
}

// Cubic Hermite between values a and b with slopes sa and sb (per unit of f) at f in [0, 1].
float nearGridHermite(float a, float sa, float b, float sb, float f) {
    float f2 = f * f;
    float f3 = f2 * f;
    return a * (2.0 * f3 - 3.0 * f2 + 1.0) + sa * (f3 - 2.0 * f2 + f) + b * (-2.0 * f3 + 3.0 * f2) + sb * (f3 - f2);
}

// The height (m) and its gradient (per unit of direction, world axes) at the point at
// `pointFromCamera`, from the grid's four points around it (fetched: the weights are the float's on
// every GPU), clamped to the grid's edge. The height cubic (Hermite, from the points' heights and
// slopes: along x, then along y with the y slopes taken linearly along x), the gradient bilinear.
// Bilinear heights were off by centimetres, and where the view ray runs a tenth as steep as the
// ground or less, the Newton step put the ground's detail tens of centimetres from where the field
// puts it (6.8 % per pixel on average at `ground`); the cubic with the points 9.9 m apart: 0.028 %
// (tests/test_near_height_grid.cpp).
float nearGridHeightGrad(vec3 pointFromCamera, OUT(vec3) gradient) {
    float n = nearGridNorth.w;
    float spacing = nearGridOrigin.w;
    vec2 at = clamp(nearGridPlaneOf(pointFromCamera) / spacing + 0.5 * (n - 1.0), vec2(0.0), vec2(n - 1.001));
    ivec2 corner = ivec2(floor(at));
    vec2 f = at - vec2(corner);
    vec4 t00 = texelFetch(NEAR_GRID_SAMPLER, corner, 0);
    vec4 t10 = texelFetch(NEAR_GRID_SAMPLER, corner + ivec2(1, 0), 0);
    vec4 t01 = texelFetch(NEAR_GRID_SAMPLER, corner + ivec2(0, 1), 0);
    vec4 t11 = texelFetch(NEAR_GRID_SAMPLER, corner + ivec2(1, 1), 0);
    vec2 p00 = nearGridPlaneAt(corner);
    vec2 s00 = spacing * nearGridPlaneSlope(p00, t00.yzw);  // slopes per spacing
    vec2 s10 = spacing * nearGridPlaneSlope(p00 + vec2(spacing, 0.0), t10.yzw);
    vec2 s01 = spacing * nearGridPlaneSlope(p00 + vec2(0.0, spacing), t01.yzw);
    vec2 s11 = spacing * nearGridPlaneSlope(p00 + vec2(spacing), t11.yzw);
    float bottom = nearGridHermite(t00.x, s00.x, t10.x, s10.x, f.x);
    float top = nearGridHermite(t01.x, s01.x, t11.x, s11.x, f.x);
    float height = nearGridHermite(bottom, mix(s00.y, s10.y, f.x), top, mix(s01.y, s11.y, f.x), f.y);
    gradient = mix(mix(t00.yzw, t10.yzw, f.x), mix(t01.yzw, t11.yzw, f.x), f.y);
    return height;
}
#endif
