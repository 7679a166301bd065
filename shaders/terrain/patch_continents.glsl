// The continents map's values over a patch of a projected grid, bounded (src/ocean/land_cull.h),
// for the control stages that drop a patch where the map says for sure what lies under all of it:
// the ground under the sea's dark depths (terrain/terrain.tesc).
// Include after terrain/grid.glsl and terrain/height.glsl.

// The lowest and highest value the map may take over the patch whose corners have the grid
// coordinates `g` (0, 1, 2, 3 round it) and whose angular radius is `radius`: the values at the
// centres of its 4x4 parts, less and plus the map's slope bound (`lipschitz`, per radian) times
// 1.5 / 4 of the radius (a part's half-diagonal is a quarter of the patch's where the grid is
// affine across it; the rest is margin for its warp: the parts' centres are placed by straight
// lines between the corners' grid coordinates, not by the warp a stride's patch follows
// (terrain/grid.glsl gridCoordinateAt), about 2 % of the patch off). Where one sample's bound over the whole
// patch is too loose: from orbit the grid's stride makes patches hundreds of kilometres across,
// and the bound's slope is 70 per radian.
void patchContinentRange(vec2 g[4], float radius, float lipschitz, out float lowest, out float highest) {
    lowest = 1.0e30;
    highest = -1.0e30;
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            vec2 f = (vec2(i, j) + 0.5) / 4.0;
            vec2 part = mix(mix(g[0], g[1], f.x), mix(g[3], g[2], f.x), f.y);
            float e = continentValue(vec3(gridDirection(part)), uContinents);
            lowest = min(lowest, e);
            highest = max(highest, e);
        }
    }
    float slack = lipschitz * (1.5 / 4.0) * radius;
    lowest -= slack;
    highest += slack;
}
