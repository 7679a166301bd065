// The ground's material into the G-buffer, once per pixel where the terrain's mesh is the nearest
// surface (the stencil; terrain/terrain.frag leaves the fragment's point, direction and steps,
// terrain/mesh_surface.glsl): per-pixel normal from the height field's analytic gradient
// (independent of tessellation), material by height, slope and latitude, albedo per material
// (terrain/height.glsl), all filtered over the pixel's footprint (terrainNormalFiltered,
// terrainMaterialWeightsSpread), then the ground's detail (terrain/detail.glsl): tri-planar
// detail normals and colour variation, mip-filtered by the same footprint.
#include "common/frame_uniforms.glsl"
#include "common/constants.glsl"
#include "common/gbuffer.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/detail.glsl"
#include "terrain/mesh_surface.glsl"

// The stencil's test before the shader runs (it discards nothing and writes no depth).
layout(early_fragment_tests) in;

layout(binding = UNIT_MESH_SURFACE_0) uniform sampler2D meshSurface0;
layout(binding = UNIT_MESH_SURFACE_1) uniform sampler2D meshSurface1;
layout(binding = UNIT_MESH_SURFACE_2) uniform sampler2D meshSurface2;

#include "terrain/terrain_block.glsl"

layout(location = 0) out vec4 outNormal;
layout(location = 1) out vec4 outAlbedo;
layout(location = 2) out vec4 outMaterial;

// Built with TERRAIN_DETAIL 1 for the pixels of the patches that may come within the detail's
// range (the stencil's 2; src/terrain/terrain_pass.cpp); without it the detail's code is not in
// the program at all: behind the block's flag alone, with no pixel entering it, llvmpipe still
// paid a quarter of the pass's fragment work for it (a software renderer runs an if's code for
// every pixel).
#ifndef TERRAIN_DETAIL
#define TERRAIN_DETAIL 0
#endif
// Built with TERRAIN_NEAR_GRID 1 (with the detail, by default): the near field where one evaluation
// serves the normal and the Newton step is read from its grid (terrain/near_height_grid.glsl), not
// evaluated here (every mountain octave's noise with its gradient at every such pixel: 38 of the detail
// program's 112 ms at `ground`, 1280x720 on llvmpipe).
#ifndef TERRAIN_NEAR_GRID
#define TERRAIN_NEAR_GRID 0
#endif
#if TERRAIN_NEAR_GRID
layout(binding = UNIT_TERRAIN_NEAR_GRID) uniform sampler2D nearHeightGrid;
#define NEAR_GRID_SAMPLER nearHeightGrid
#endif
#include "terrain/near_height_grid.glsl"

// Linear albedo per material id (sea floor, rock, snow, sand; grass comes from the preset).
const vec3 MATERIAL_ALBEDO[TERRAIN_MATERIAL_COUNT] =
    vec3[](vec3(0.10, 0.09, 0.07), vec3(0.13, 0.11, 0.09), vec3(0.80, 0.82, 0.86), vec3(0.36, 0.31, 0.21),
           vec3(0.0));  // grass: terrainLowlandAlbedo

// Wet sand: darker from the waterline up to this height above sea level (the waves' run-up),
// by this factor at the water (wet sand reflects about half as much: Lekner & Dorf 1988).
const float TERRAIN_WET_HEIGHT_M = 1.5;
const float TERRAIN_WET_DARKENING = 0.55;

// The lowlands take the preset's albedo; so do a dry world's basins, a little darker.
vec3 materialAlbedo(int material) {
    if (material == TERRAIN_MATERIAL_GRASS) return terrainLowlandAlbedo;
    if (material == TERRAIN_MATERIAL_SEA_FLOOR && terrainHasOcean == 0) return 0.7 * terrainLowlandAlbedo;
    return MATERIAL_ALBEDO[material];
}

// Ground a wave has wet: below TERRAIN_WET_HEIGHT_M where there is a sea, averaged over the
// height's spread under the pixel.
float wetness(float height, float heightSpread) {
    if (terrainHasOcean == 0) return 0.0;
    float band = 0.3 + 2.0 * heightSpread;
    return 1.0 - smoothstep(TERRAIN_WET_HEIGHT_M - band, TERRAIN_WET_HEIGHT_M + band, height);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    TerrainFragment f = unpackTerrainFragment(texelFetch(meshSurface0, pixel, 0), texelFetch(meshSurface1, pixel, 0),
                                              texelFetch(meshSurface2, pixel, 0));
    vec3 pointFromCamera = f.pointFromCamera;
    vec3 up = normalize(f.direction);
    vec3 dpdx = f.stepX;
    vec3 dpdy = f.stepY;
    float footprint = max(length(dpdx), length(dpdy));  // m: the pixel's larger extent on the ground
    // The detail lies on the height field, not on the mesh: the mesh's point is off the true
    // surface by what its interpolation and its float heights missed, which changes with the
    // tessellation (it follows the camera), and the detail would swim and pop with it. Where
    // the finest scale shows (the footprint under its period), the pixel sees the true surface
    // where its ray meets it, one Newton step from the mesh's point (terrainRayHitNearSteps:
    // the step's error is second order in the mesh's centimetres; a second step's height
    // evaluation cost the `mountains` view a tenth of the pass). Farther out the detail takes
    // the mesh's point: only the 4 and 32 m scales show there, each blurred over the footprint
    // by its mip level, and the mesh's error along the ray (its height error over the ray's
    // slope) moves them by part of a footprint: an anchor update changes 73 of 57600 `ground`
    // pixels by more than 5 % (63 with the step everywhere;
    // RenderTest.AnchorUpdatesDoNotPopVisibly), and the step's height evaluation there cost
    // the `mountains` view another tenth. A ray that does not descend (one grazing a ridge)
    // takes it where the mesh's point drops onto the ground. The detail fades out towards the
    // near field's range (placed on the mesh beyond it, it would move with the tessellation).
    float distance = length(pointFromCamera);
    float narrowFootprint = min(length(dpdx), length(dpdy));  // the detail's filter follows it (detail.glsl)
    float strength =
        TERRAIN_DETAIL != 0 ? 1.0 - smoothstep(0.5 * TERRAIN_NEAR_RANGE_M, TERRAIN_NEAR_RANGE_M, distance) : 0.0;
    bool detailShown = strength > 0.0 && narrowFootprint < TERRAIN_DETAIL_PERIOD_M[TERRAIN_DETAIL_SCALES - 1];
    bool newtonStep = detailShown && narrowFootprint < TERRAIN_DETAIL_PERIOD_M[0];
    // Where the footprint shows every mountain octave whole, the filtered field is the field
    // itself (no variance under the pixel), and the Newton step's height evaluation at the mesh's
    // point (the near field's: the same field, exact to float near the camera) serves the normal
    // too: one evaluation instead of two (the `ground` view, 1280x720: a third of the material
    // pass's detail). Loops of one turn or none, not ifs: a software renderer leaves a loop that
    // no pixel of a group enters, but runs both sides of an if.
    bool oneEvaluation = newtonStep && terrainFootprintShowsEveryOctave(terrainShape, footprint, frame.planetRadius);
    float height = 0.0;
    float heightSpread = 0.0;
    float slopeSpread = 0.0;
    vec3 normal = up;
    vec3 hit = pointFromCamera;
    for (int i = 0; i < (oneEvaluation ? 0 : 1); ++i)
        normal = terrainNormalFiltered(up, terrainShape, uContinents, frame.planetRadius, footprint, height,
                                       heightSpread, slopeSpread);
    for (int i = 0; i < (oneEvaluation ? 1 : 0); ++i) {
        vec3 gradient;
#if TERRAIN_NEAR_GRID
        height = nearGridHeightGrad(pointFromCamera, gradient);  // within the detail's reach: on the grid
#else
        height = terrainHeightNearGrad(pointFromCamera, terrainNear, terrainShape, gradient);
#endif
        normal = terrainNormalFromGradient(up, height, gradient, frame.planetRadius);
        terrainRayHitNearStepFrom(pointFromCamera, terrainNear, height, gradient, hit);
    }
    for (int i = 0; i < (newtonStep && !oneEvaluation ? 1 : 0); ++i)
        terrainRayHitNearSteps(pointFromCamera, terrainNear, terrainShape, 1, hit);
    float slope = terrainSlope(normal, up);
    float latitude = terrainLatitude(up);
    float weights[TERRAIN_MATERIAL_COUNT] =
        terrainMaterialWeightsSpread(height, slope, latitude, heightSpread, slopeSpread).weight;
    vec3 albedo = vec3(0.0);
    for (int m = 0; m < TERRAIN_MATERIAL_COUNT; ++m) albedo += weights[m] * materialAlbedo(m);
    albedo *= mix(1.0, TERRAIN_WET_DARKENING, wetness(height, heightSpread));
    float detailSlopeSpread = 0.0;  // what the detail's filter removed, for the surface light
    if (detailShown) {
        vec3 fieldGradient;
        float field = terrainPatchesNear(hit, terrainNear, fieldGradient);
        applyTerrainDetail(hit + terrainXyz(terrainNear.cameraPlace), dpdx, dpdy, up, weights, strength,
                           terrainHasOcean != 0, field, fieldGradient, normal, albedo, detailSlopeSpread);
    }
    outNormal = vec4(normal, height);
    outAlbedo = vec4(albedo, 1.0);
    outMaterial = vec4(float(MATERIAL_GROUND) / 255.0, 1.0, min(detailSlopeSpread, 1.0), 0.0);
}
