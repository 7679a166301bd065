// The sea surface's G-buffer: what the ocean's mesh (ocean/ocean.frag) leaves at each pixel where
// the sea is the nearest surface, for its light (ocean/sea_light.frag), which runs once per such
// pixel over the whole frame. Split so because a software renderer shades a 4x4 block of pixels
// for every triangle that touches it: the mesh's fragments cost two to three times the pixels
// they cover (orbit, 1280x720: 983 344 fragment invocations for about 300 000 sea pixels; the
// `sea` view 3.0 million for its 920 000 pixels), so only the cheap part (which pixels are sea,
// where the water is) runs per fragment, and the light, most of the cost, per pixel.
//
// In the mesh surface's three RGBA32F targets (terrain/mesh_surface.glsl; full floats: the
// direction offset carries the waves' phases near the camera, the distances and the water's
// depth are metres that half floats would round):
//   0  up (the vertical the water is shaded with), the water's depth below the mean surface (m)
//   1  the direction offset v - v_c (ocean/gerstner.glsl's dv), the distance to the sea along the
//      view ray (m)
//   2  the share of the pixel under water (negative: a shore fragment behind the land's edge),
//      the water's path along the ray down to the floor (m), the place on the grid in point
//      indices (ocean/grid_reflection_points.glsl)

struct SeaSurface {
    vec3 up;
    float waterDepth;
    vec3 offset;
    float distance;
    float coverage;
    bool behindLand;
    float waterPath;
    vec2 gridPoint;
};

// The targets' three texels for a surface.
void packSeaSurface(SeaSurface s, out vec4 texel0, out vec4 texel1, out vec4 texel2) {
    texel0 = vec4(s.up, s.waterDepth);
    texel1 = vec4(s.offset, s.distance);
    texel2 = vec4(s.behindLand ? -s.coverage : s.coverage, s.waterPath, s.gridPoint);
}

// The surface from its texels. The coverage's sign carries the flag: a shore fragment behind the
// land's edge always has a coverage above 0 (ocean/ocean.frag discards it otherwise), any other
// fragment 0 or more.
SeaSurface unpackSeaSurface(vec4 texel0, vec4 texel1, vec4 texel2) {
    SeaSurface s;
    s.up = texel0.xyz;
    s.waterDepth = texel0.w;
    s.offset = texel1.xyz;
    s.distance = texel1.w;
    s.coverage = abs(texel2.x);
    s.behindLand = texel2.x < 0.0;
    s.waterPath = texel2.y;
    s.gridPoint = texel2.zw;
    return s;
}

// A pixel's footprint on the sea, m: its size at `distance` (pixelAngle: radiansPerPixel()),
// stretched along the view by 1 / cos(incidence) (the long axis, so grazing views do not alias
// into sparkle; what it drops becomes glitter roughness).
float seaFootprint(float distance, float pixelAngle, vec3 view, vec3 up) {
    return distance * pixelAngle / max(abs(dot(view, up)), 0.02);
}
