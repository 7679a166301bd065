// Ground detail: the baked detail texture (terrain/detail_texture.h: slopes in xy, a fine
// height field in z, patches in w) projected along the three world axes (tri-planar, Michelic
// §6: "a three-planar projected normal map to get detail normals"), at two scales (0.5 and 4 m),
// and a world-fixed noise field at the coarse scale (terrain/height.glsl, terrainPatchesNear: no
// period to tile), into per-material detail normals and colour variation (Sperlhofer 4.4: normal
// mapping and multi-texturing, blended per material).
//
// Filtering: every fetch is textureGrad with the derivatives of the detail position, so the
// mip level follows the pixel's footprint: the texture's slopes and heights average to zero
// as a scale's features shrink below a pixel, and the detail fades into the large-scale
// shading with no line at any distance. A scale whose whole period fits in the footprint
// (the coarsest mip, whose mean is 0) is skipped: from orbit the detail costs nothing.
//
// What the filter removes is not lost to the lighting (LEAN / Toksvig in spirit): the
// variance of the slopes under the footprint, the share the mip level averaged away (the
// bake's table per level, uTerrainDetailLostVariance) plus the spread between the taps of
// the anisotropic filter, leaves with the normal (terrain/ground_material.frag writes its spread into the
// G-buffer) and the surface light lights the ground with the expected clamped cosine over
// it (terrain/rough_cosine.glsl). A normal filtered and then lit is not the mean of the lit
// normals: at a 30 degree sun the rock's relief turns facets away from the sun, which a
// far pixel's mean normal does not show.
//
// Positions: where the pixel's ray meets the height field (terrain/ground_material.frag, terrainRayHitNear),
// camera-relative plus the camera modulo TERRAIN_NEAR_WRAP_M (terrain/height.glsl): exact to a
// millimetre near the camera; all periods divide TERRAIN_NEAR_WRAP_M, so the wrap of the
// camera's position is invisible.
// On where the preset's terrain.detail is: the ground material program built with TERRAIN_DETAIL 1 (terrain/ground_material.frag).
const int TERRAIN_DETAIL_SCALES = 3;
const float TERRAIN_DETAIL_PERIOD_M[TERRAIN_DETAIL_SCALES] = float[](0.5, 4.0, 32.0);

// Per material (sea floor, rock, snow, sand, grass): the root-mean-square slope (rise over
// run, both components) the detail adds at each scale. Small on purpose: the lighting is
// linear in slopes this gentle, so the filtered (mean) slope lights a far pixel as its
// facets would on average, and what the filter removed the rough cosine adds back. (The
// first values were given as relief in metres on the belief that the slopes were about
// 4.2 x relief / period; the bake's waves, a quarter to a 32nd of the period, make them
// 59 x relief / period: grass had slopes of 1.4, rock 2.4, and its far pixels, lit from
// averaged normals that steep, were 5 % off their own supersampled mean.)
const vec3 TERRAIN_DETAIL_SLOPE[5] = vec3[](vec3(0.10, 0.15, 0.15), vec3(0.25, 0.35, 0.45), vec3(0.05, 0.08, 0.15),
                                            vec3(0.08, 0.10, 0.10), vec3(0.20, 0.20, 0.15));
// How strongly the fine field (x: finest, y: middle scale) and the patches (z) vary the
// albedo (relative, per unit standard deviation of the field). Linear in the fields, so that
// filtering them filters the colour; a third of the spread keeps clear of the clamp below.
const vec3 TERRAIN_DETAIL_TINT[5] = vec3[](vec3(0.12, 0.10, 0.10), vec3(0.15, 0.15, 0.12), vec3(0.03, 0.04, 0.03),
                                           vec3(0.10, 0.08, 0.08), vec3(0.15, 0.12, 0.15));

// Dry and lush grass: the meadow's albedo moves towards this tint by this much per unit of
// the patches, and away from it where they are negative. Linear and of mean 0, so a far
// pixel, where the filter has averaged the patches away, keeps the near meadow's mean colour.
// (Its first form, a smoothstep of the patches, was neither: the near meadow was a quarter
// dry on average, the far one hardly at all.)
const vec3 TERRAIN_DRY_GRASS_TINT = vec3(1.35, 1.15, 0.6);
const float TERRAIN_DRY_GRASS_PER_PATCH = 0.3;

#include "terrain/detail_planes.glsl"

layout(binding = UNIT_TERRAIN_DETAIL) uniform sampler2D uTerrainDetail;
// Per mip level of uTerrainDetail: the variance of the slope (both components, per unit of
// texture coordinate, squared) that the level's averaging removed from level 0's
// (terrain/detail_texture.h, DetailTexture::lostSlopeVariance; the pass sets it).
const int TERRAIN_DETAIL_LEVELS = 9;  // a 256 x 256 bake: one per mip level (tests/test_terrain_filtering.cpp checks)
uniform float uTerrainDetailLostVariance[TERRAIN_DETAIL_LEVELS];

// The detail texture at one scale, projected tri-planar: the world-space slope of the height
// field (per metre of relief per metre), and the mean of the height (z) and patch (w) channels;
// slopeVariance: the variance of the slope about that mean under the footprint, which the
// filter removed (per metre of relief per metre, squared, both components).
struct DetailSample {
    vec3 slope;
    float height;
    float patches;
    float slopeVariance;
};

// The planes' weights squared: the planes' slopes are independent, so their variances add so.
float planeWeightSquares(DetailPlanes planes) { return planes.w0 * planes.w0 + planes.w1 * planes.w1; }

DetailSample detailAtScaleIsotropic(vec3 p, vec3 dpdx, vec3 dpdy, DetailPlanes planes, float scale) {
    // Each plane's slope (d/du, d/dv per unit of texture coordinate) maps back onto its axes.
    vec4 t0 = textureGrad(uTerrainDetail, vec2(dot(p, planes.a0), dot(p, planes.b0)) * scale,
                          vec2(dot(dpdx, planes.a0), dot(dpdx, planes.b0)) * scale,
                          vec2(dot(dpdy, planes.a0), dot(dpdy, planes.b0)) * scale);
    vec4 t1 = textureGrad(uTerrainDetail, vec2(dot(p, planes.a1), dot(p, planes.b1)) * scale,
                          vec2(dot(dpdx, planes.a1), dot(dpdx, planes.b1)) * scale,
                          vec2(dot(dpdy, planes.a1), dot(dpdy, planes.b1)) * scale);
    DetailSample s;
    s.slope = planes.w0 * (t0.x * planes.a0 + t0.y * planes.b0) + planes.w1 * (t1.x * planes.a1 + t1.y * planes.b1);
    s.height = planes.w0 * t0.z + planes.w1 * t1.z;
    s.patches = planes.w0 * t0.w + planes.w1 * t1.w;
    s.slopeVariance = 0.0;
    return s;
}

// Anisotropic filtering by hand: the footprint of a pixel seen at a grazing angle is long
// along the ray and narrow across it. An isotropic mip level (the GPU's choice from the
// longer side) blurs across the ray too, which a supersampled frame does not (the aliasing
// test measured 6.5 % against 3 % for the mountains). So up to TERRAIN_DETAIL_TAPS samples
// along the long side, each at the level of its share of the long side or of the narrow
// side, whichever is longer. (The GL's own anisotropic filtering took llvmpipe minutes per
// frame at grazing angles.) Two: four cost the `mountains` view a third of the terrain pass
// more, for an aliasing error of 1.98 % instead of 2.3 % at 640x360 against 2560x1440
// (docs/PERFORMANCE.md, 2026-12-05).
const int TERRAIN_DETAIL_TAPS = 2;

DetailSample detailAtScale(vec3 p, vec3 dpdx, vec3 dpdy, DetailPlanes planes, float period) {
    vec3 major = dot(dpdx, dpdx) >= dot(dpdy, dpdy) ? dpdx : dpdy;
    vec3 minor = dot(dpdx, dpdx) >= dot(dpdy, dpdy) ? dpdy : dpdx;
    if (length(minor) >= period)  // the coarsest mip: mean 0, all of the slopes' variance removed
        return DetailSample(vec3(0.0), 0.0, 0.0,
                            uTerrainDetailLostVariance[TERRAIN_DETAIL_LEVELS - 1] * planeWeightSquares(planes) /
                                (period * period));
    float ratio = length(major) / max(length(minor), 1.0e-6);
    int taps = int(clamp(ceil(ratio), 1.0, float(TERRAIN_DETAIL_TAPS)));
    vec3 stepAlong = major / float(taps);
    DetailSample s = DetailSample(vec3(0.0), 0.0, 0.0, 0.0);
    float slopeSquares = 0.0;  // the taps' squared slopes, for the spread between them
    for (int i = 0; i < TERRAIN_DETAIL_TAPS; ++i) {
        if (i >= taps) break;
        vec3 tap = p + stepAlong * (float(i) + 0.5 - 0.5 * float(taps));
        DetailSample t = detailAtScaleIsotropic(tap, stepAlong, minor, planes, 1.0 / period);
        s.slope += t.slope;
        s.height += t.height;
        s.patches += t.patches;
        slopeSquares += dot(t.slope, t.slope);
    }
    float weight = 1.0 / float(taps);
    // The variance removed: within each tap, the table's share at the tap's mip level (the
    // GPU's isotropic level: its footprint's longer side in texels; trilinear between levels),
    // the planes' slopes independent, so their weights enter squared; between the taps, their
    // spread about their mean (the law of total variance).
    float texels = max(length(stepAlong), length(minor)) * float(textureSize(uTerrainDetail, 0).x) / period;
    float level = clamp(log2(max(texels, 1.0)), 0.0, float(TERRAIN_DETAIL_LEVELS - 1));
    int below = min(int(level), TERRAIN_DETAIL_LEVELS - 2);
    float within = mix(uTerrainDetailLostVariance[below], uTerrainDetailLostVariance[below + 1], level - float(below)) *
                   planeWeightSquares(planes);
    float between = max(slopeSquares * weight - dot(s.slope, s.slope) * weight * weight, 0.0);
    s.slopeVariance = (within + between) / (period * period);  // per metre, squared
    s.slope *= weight / period;  // per metre
    s.height *= weight;
    s.patches *= weight;
    return s;
}

// The detail of the ground at p (terrain.tese's detail position, with its screen
// derivatives) for a surface with `normal` and material `weights` (terrainMaterialWeight):
// the normal bent by the materials' relief, and the albedo varied by their tints. The
// projections are weighted by the local vertical `up`, not by the normal: the normal is
// filtered by the footprint, and weights from it would blend other patterns at other
// distances and image sizes (the detail would change as the camera moves). `strength` in
// [0, 1] scales the relief and the tints (the fade towards the near field's range).
// `vegetated`: the lowlands are grass (a world with a sea), with dry and lush patches; a dry
// world's lowlands (terrainLowlandAlbedo: Mars's dust) take the tints alone (the lush side's
// bluer green made grey-blue blotches on Mars). slopeSpread: the standard deviation of the
// detail's slopes about the returned normal under the footprint, per component (rise over
// run), what the filter removed (see the top).
void applyTerrainDetail(vec3 p, vec3 dpdx, vec3 dpdy, vec3 up, float weights[5], float strength, bool vegetated,
                        float field, vec3 fieldGradient, inout vec3 normal, inout vec3 albedo, out float slopeSpread) {
    vec3 slopes = vec3(0.0);
    vec3 tint = vec3(0.0);
    for (int m = 0; m < 5; ++m) {
        slopes += (strength * weights[m]) * TERRAIN_DETAIL_SLOPE[m];
        tint += (strength * weights[m]) * TERRAIN_DETAIL_TINT[m];
    }
    // The relief (m of the unit-spread height field) that gives those slopes: the texture's
    // slopes (per unit of texture coordinate) have the spread of its whole variance, which
    // the 1 x 1 level has removed.
    float textureSlopeRms = sqrt(uTerrainDetailLostVariance[TERRAIN_DETAIL_LEVELS - 1]);
    vec2 relief = slopes.xy * vec2(TERRAIN_DETAIL_PERIOD_M[0], TERRAIN_DETAIL_PERIOD_M[1]) / textureSlopeRms;
    DetailPlanes planes = detailPlanes(up);
    DetailSample fine = detailAtScale(p, dpdx, dpdy, planes, TERRAIN_DETAIL_PERIOD_M[0]);
    DetailSample middle = detailAtScale(p, dpdx, dpdy, planes, TERRAIN_DETAIL_PERIOD_M[1]);
    // The coarse scale is not the texture's: the world-fixed field (terrain/height.glsl,
    // terrainPatchesNear, `field` and its gradient at the pixel), whose value makes the patches and
    // whose slope along the ground the relief, with no period (the texture's 32 m showed as a lattice
    // of blotches from 20 m up). Filtered by fading both as the footprint (the longer side's share per
    // tap, as detailAtScale's, or the narrow side) covers its cells; the slopes' variance the fade
    // removes goes to the lighting, as the texture's levels' does.
    float coarseFootprint = max(0.5 * max(length(dpdx), length(dpdy)), min(length(dpdx), length(dpdy)));
    float kept = 1.0 - smoothstep(0.15, 0.75, coarseFootprint / TERRAIN_PATCH_CELL_M);
    vec3 along = fieldGradient - dot(fieldGradient, up) * up;
    vec3 slope = relief.x * fine.slope + relief.y * middle.slope + (slopes.z * kept / TERRAIN_PATCH_SLOPE_RMS) * along;
    normal = normalize(normal - (slope - dot(slope, normal) * normal));
    float slopeVariance = relief.x * relief.x * fine.slopeVariance + relief.y * relief.y * middle.slopeVariance +
                          slopes.z * slopes.z * (1.0 - kept * kept);
    slopeSpread = sqrt(0.5 * slopeVariance);  // isotropic: half the variance in each component
    float patches = kept * field + 0.5 * middle.patches;
    float variation = tint.x * fine.height + tint.y * middle.height + tint.z * patches;
    albedo *= clamp(1.0 + variation, 0.3, 2.0);
    // Grass: dry, yellower patches among lush ones.
    float dry = vegetated ? weights[TERRAIN_MATERIAL_GRASS] * strength * TERRAIN_DRY_GRASS_PER_PATCH * patches : 0.0;
    albedo *= max(1.0 + dry * (TERRAIN_DRY_GRASS_TINT - 1.0), 0.0);
}
