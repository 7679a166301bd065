// The continents map's values over a patch of a projected grid, bounded (src/ocean/land_cull.h),
// for the control stages that drop a patch where the map says for sure what lies under all of it:
// the ground under the sea's dark depths (terrain/terrain.tesc).
// Include after terrain/grid.glsl and terrain/height.glsl.

layout(binding = UNIT_CONTINENT_MAX) uniform samplerCube uContinentMax;  // src/terrain/continent_bound.h

// The highest the map may be within `radius` (rad) of the unit `centre`: the maxima pyramid's texel
// (nearest) at the level whose texels bound such a cap, (size / 2) s(r) r <= 2^k on level 0's grid
// with the face plane's stretch s(r) = 1 / cos^2(54.7 deg + r) (src/terrain/continent_bound.h's
// continentMaxWithin, its CPU twin, says why); 1e30 where no level does, or past `maxRadius` (the
// block's terrainContinentMaxRadius; 0: not read).
float continentMaxWithin(vec3 centre, float radius, float maxRadius) {
    float c = cos(0.9553166 + radius);
    float texels = 0.5 * float(textureSize(uContinentMax, 0).x) * radius / (c * c);
    float level = max(ceil(log2(max(texels * 1.0001, 1.0))), 0.0);  // (rounded up: a coarser level still bounds)
    if (!(radius <= maxRadius) || level > float(textureQueryLevels(uContinentMax) - 1)) return 1.0e30;
    return textureLod(uContinentMax, centre, level).r;
}

// The lowest and highest value the map may take over the patch whose corners have the grid
// coordinates `g` (0, 1, 2, 3 round it) and whose angular radius is `radius`: the values at the
// centres of its 4x4 parts, less and plus the map's slope bound (`lipschitz`, per radian) times
// 1.5 / 4 of the radius (a part's half-diagonal is a quarter of the patch's where the grid is
// affine across it; the rest is margin for its warp: the parts' centres are placed by straight
// lines between the corners' grid coordinates, not by the warp a stride's patch follows
// (terrain/grid.glsl gridCoordinateAt), about 2 % of the patch off). Where one sample's bound over the whole
// patch is too loose: from orbit the grid's stride makes patches hundreds of kilometres across,
// and the bound's slope is 70 per radian. The highest, where tighter, is the continents' maxima
// over each part (continentMaxWithin, up to `maxRadius`: 0, not read).
void patchContinentRange(vec2 g[4], float radius, float lipschitz, float maxRadius, out float lowest,
                         out float highest) {
    float partRadius = (1.5 / 4.0) * radius;
    float slack = lipschitz * partRadius;
    lowest = 1.0e30;
    highest = -1.0e30;
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            vec2 f = (vec2(i, j) + 0.5) / 4.0;
            vec2 part = mix(mix(g[0], g[1], f.x), mix(g[3], g[2], f.x), f.y);
            vec3 direction = vec3(gridDirection(part));
            float e = continentValue(direction, uContinents);
            lowest = min(lowest, e - slack);
            highest = max(highest, min(e + slack, continentMaxWithin(direction, partRadius, maxRadius)));
        }
    }
}
