// The ground detail's tri-planar projections (terrain/detail.glsl): which two of the three
// world-axis projections a pixel takes, and their weights. Shared with C++
// (src/terrain/detail_texture.cpp compiles it; tests/test_terrain_filtering.cpp checks it).

// Two of the three tri-planar projections: each a pair of world axes (a, b) that are its
// texture's (u, v), and its weight.
struct DetailPlanes {
    vec3 a0, b0, a1, b1;
    float w0, w1;
};

// The tri-planar projections for the local vertical `up`: the two with the most weight
// (|up|^4, normalised), the third's weight subtracted from theirs. A software renderer runs an
// if's code in every pixel, so a third plane's fetches cost though its weight is 0 (the `beach`
// view, 640x360: a tenth of the terrain pass); the three planes' old rule (those under 2 %
// dropped) changes nothing where the third is under a few per cent, as at every shipped view
// (1e-4 to 3e-3). Subtracting the third's weight makes a plane enter and leave with weight 0
// where the pair changes (two weights equal). Two planes cannot blend continuously everywhere:
// around the 8 directions where all three weights are equal (the cube's corners) the pair turns
// with the direction, gradually a kilometre off on an Earth-sized planet (weights change by 1.4
// a kilometre there, 0.14 at 11 km), at the corner at once. A function of `up` alone: fixed to
// the ground, it does not change as the camera moves.
DetailPlanes detailPlanes(vec3 up) {
    vec3 a = up * up;
    vec3 w = a * a;
    w /= w.x + w.y + w.z;
    // The dropped plane: the least weight (x projects along x onto y and z, and so on).
    int dropped = w.x <= w.y && w.x <= w.z ? 0 : (w.y <= w.z ? 1 : 2);
    // Plane x projects onto (y, z), plane y onto (z, x), plane z onto (x, y). (Fields set one by
    // one: C++ compilers without C++20's parenthesised aggregates compile this file too.)
    const vec3 X = vec3(1.0f, 0.0f, 0.0f), Y = vec3(0.0f, 1.0f, 0.0f), Z = vec3(0.0f, 0.0f, 1.0f);
    DetailPlanes planes;
    planes.a0 = dropped == 0 ? Z : Y;  // the first kept plane: y if x is dropped, else x
    planes.b0 = dropped == 0 ? X : Z;
    planes.w0 = dropped == 0 ? w.y : w.x;
    planes.a1 = dropped == 2 ? Z : X;  // the second: y if z is dropped, else z
    planes.b1 = dropped == 2 ? X : Y;
    planes.w1 = dropped == 2 ? w.y : w.z;
    float third = dropped == 0 ? w.x : (dropped == 1 ? w.y : w.z);
    planes.w0 = max(planes.w0 - third, 0.0f);
    planes.w1 = max(planes.w1 - third, 0.0f);
    float sum = planes.w0 + planes.w1;
    planes.w0 = sum > 0.0f ? planes.w0 / sum : 0.5f;
    planes.w1 = sum > 0.0f ? planes.w1 / sum : 0.5f;
    return planes;
}
