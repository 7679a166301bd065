// The ocean mesh's fragments: which pixels show the sea and where its water is, into the sea
// surface's G-buffer (ocean/sea_surface.glsl), the surface distance target and the depth, with
// the stencil marked (OceanPass::kSeaStencil) where the sea is the nearest surface. The water's light is
// ocean/sea_light.frag's, once per such pixel over the whole frame: a software renderer shades a
// 4x4 block for every triangle that touches it, two to three times the pixels (see there).
//
// Far away the depth buffer cannot tell land from sea: both meshes are chords of the sphere
// that sag below it by (edge length)^2 / 8r between vertices (a kilometre from space), more
// than the height of a coastal plain. There the sea floor's height from the terrain's own
// height function decides (terrain/height.glsl, the continents map): the sea is pulled
// towards the camera by the sag (gl_FragDepth) so that sagging coastal land cannot hide it,
// is discarded where the terrain stands above it, and its water path comes from the depth
// below the surface. Near the camera the sag is far below a millimetre and nothing changes.
// Where the water is thinner than SHORE_FADE_M the sea fades into the floor (its coverage), so
// the shoreline is soft and the two surfaces never fight for depth.
//
// The far field's build (OCEAN_FAR_FIELD) built with STENCIL_EXPORT 1, where the GL has
// ARB_shader_stencil_export: each sea pixel gives its own stencil value, OceanPass::kOpenSeaStencil
// where no land lies within reach of the water's reflected ray or its sun ray (openSea, below),
// OceanPass::kSeaStencil elsewhere. The water's light then runs its OPEN_SEA build on the first
// (ocean/sea_light.frag), without the terrain reflection's and shadow's code, which a software
// renderer ran in every pixel, masked. (Not the mesh's build: near the sea its fragments are two to
// three per pixel, and the reflected rays' rise is bounded by every wave the pixel resolves.)
#ifndef STENCIL_EXPORT
#define STENCIL_EXPORT 0
#endif
#if STENCIL_EXPORT
#extension GL_ARB_shader_stencil_export : require
#endif
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "ocean/ocean_block.glsl"
#include "ocean/edge_target.glsl"
#include "ocean/sea_sphere.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/terrain_block.glsl"
#include "ocean/sea_surface.glsl"
#if STENCIL_EXPORT
#include "ocean/gerstner.glsl"
#include "ocean/ocean_waves.glsl"
#include "terrain/terrain_shadow.glsl"
#include "ocean/terrain_reflection_reach.glsl"
#endif

// OCEAN_FAR_FIELD 1: the build for a camera so high that every sea pixel is in the far field
// (src/ocean/far_field.h), drawn over the ground sphere's rectangle instead of the mesh: each
// pixel's point is where its ray meets the sphere, which the mesh's fragments take there anyway
// (farness 1, below), once per pixel rather than once per triangle's 4x4 blocks, and with no
// vertex or tessellation work. What differs from the mesh's: the depth is the sphere's point's
// pulled by the sag (not the chord's), the direction offset is formed in float (no wave shows),
// and the place on the grid is the pixel's own (terrain/grid.glsl's gridPointOf), not one
// interpolated across a triangle (tests/test_ocean_far_field.cpp: the frames agree to 0.02 % on
// average).
#ifndef OCEAN_FAR_FIELD
#define OCEAN_FAR_FIELD 0
#endif

#if !OCEAN_FAR_FIELD
in vec3 tePosition;
in vec3 teDirection;
in vec3 teOffset;
in vec2 teGridPoint;  // the place on the grid in point indices, for the grid's reflection (ocean/grid_reflection_points.glsl)
#endif

layout(binding = UNIT_SEABED_DEPTH) uniform sampler2D seabedDepth;  // copy of the G-buffer depth (reversed-Z)

layout(location = 0) out float outSurfaceDistance;
layout(location = 1) out vec4 outSeaSurface0;
layout(location = 2) out vec4 outSeaSurface1;
layout(location = 3) out vec4 outSeaSurface2;

layout(depth_greater) out float gl_FragDepth;  // reversed-Z: only ever moved towards the camera

const float SHORE_FADE_M = 0.5;  // water path over which the sea fades in at the shore

#if STENCIL_EXPORT
// The stencil values (src/ocean/ocean_pass.h): both hold kSeaStencil's bits, so a test of those
// bits alone finds every sea pixel.
const int SEA_STENCIL = 3;
const int OPEN_SEA_STENCIL = 7;
// How much lower than the sea the reaches below the land are taken from, m: the light forms its
// own from the same values in another program, whose sums may round otherwise (a few ulp of heights
// of kilometres, a millimetre); this keeps every pixel marked open one that the light finds open.
const float OPEN_SEA_MARGIN_M = 0.05;

// The least sine of elevation that the light's reflected ray (ocean/sea_light.frag) may have at the
// sea pixel along `view` with footprint `footprint`: the view's reflection in a normal that leans
// at most `tilt` (oceanNormalTiltBound, at a footprint a little smaller, which resolves no fewer
// waves) rises at least (view's elevation - 2 tilt). Below 0.02 the light may turn a normal facing
// away from the camera towards it (cosView < 0.01), and only ocean/cloud_reflection.glsl's
// SeaReflectedRay's clamp holds: a level ray.
float reflectedRiseBound(vec3 view, vec3 up, float footprint) {
    // sin(elevation - 2 tilt) from tan(tilt) = t: cos 2 tilt = (1 - t^2) / (1 + t^2), sin 2 tilt = 2t / (1 + t^2)
    // (no wave resolved, t = 0: the view's own elevation, exactly).
    float t = min(oceanNormalTiltBound(0.99 * footprint), 1.0e3);
    float sinElevation = clamp(-dot(view, up), 0.0, 1.0);
    float cosElevation = sqrt(1.0 - sinElevation * sinElevation);
    float rise = (sinElevation * (1.0 - t * t) - cosElevation * 2.0 * t) / (1.0 + t * t);
    return rise >= 0.02 ? rise : 0.0;
}

// Whether the water's light at the sea pixel along `view`, `seaDistance` away, at `up` (continent
// value `e`) surely finds no land within reach of its reflected ray (terrainMayBeReflected false)
// nor of its sun ray (no terrain shadow can fall here): the light's own tests, with reaches no
// shorter than its own (for a reflected ray rising no more than reflectedRiseBound, from a little
// below the sea; terrainReachBelowHeightKm falls as a ray rises) and the pixel's share of the reach
// rounded up.
bool openSea(vec3 view, vec3 up, float e, float seaDistance, float footprint, float pixelAngle) {
    vec2 reachKm = terrainReachesBelowLandKmAt(e, ocean.seaLevel - OPEN_SEA_MARGIN_M,
                                               vec2(reflectedRiseBound(view, up, footprint), dot(up, frame.sunDirection)),
                                               vec2(1.0e30, TERRAIN_SHADOW_MAX_KM), frame.planetRadius / M_PER_KM,
                                               ocean.continentLipschitz, ocean.continentSampleSlackRad, terrainShape);
    return !terrainShadowMayReachSeaWithin(reachKm.y, ocean.seaLevel, ocean.continentLipschitz) &&
           !terrainMayBeReflected(reachKm.x * M_PER_KM * 1.001, seaDistance * 0.999, pixelAngle);
}
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
#if OCEAN_FAR_FIELD
    // The sphere's point on the pixel's ray; a ray past the limb takes the horizon's distance, only
    // for its neighbours' derivatives (it is discarded below).
    vec3 view = pixelRay(pixel);
    float sphereDistance = seaSphereDistance(view);
    float aboveSea = -frame.cameraDepthBelowSea;
    float horizon = sqrt(max(aboveSea * (2.0 * (frame.planetRadius + ocean.seaLevel) + aboveSea), 0.0));
    vec3 tePosition = view * (sphereDistance > 0.0 ? sphereDistance : horizon);
#endif
    // The surface's step from this pixel to the next, taken before any discard (derivatives
    // need the whole quad): how far the water's depth changes across the pixel (the shore's
    // coverage below).
    vec3 stepX = dFdx(tePosition);
    vec3 stepY = dFdy(tePosition);
#if OCEAN_FAR_FIELD
    if (sphereDistance <= 0.0) discard;
    float surfaceDistance = sphereDistance;
    vec3 up = normalize(cameraFromPlanetCentreKm() * M_PER_KM + tePosition);
    vec3 teOffset = up - frame.cameraUp;  // v - v_c (the mesh's is formed in double: no wave shows here)
    float sag = meshSagM(surfaceDistance, max(ocean.coarsestEdgePixels, oceanEdgeTargetPixels(surfaceDistance)));
    float farness = 1.0;
    float seaDistance = surfaceDistance;
#else
    float surfaceDistance = length(tePosition);
    vec3 view = tePosition / surfaceDistance;  // camera -> surface
    vec3 up = normalize(teDirection);
    // How far the meshes may sag below the sphere here (see above; the sea's own edges aim at
    // ocean/edge_target.glsl's target), m, and how far that makes this the far field.
    // There (from space with the grid's larger patches, src/grid/grid_stride.h, kilometres of
    // sag) no wave shows: the pixel shows the mean surface where its ray meets the sphere, so its
    // point, its vertical and the distance the air is taken over are the sphere's, not the
    // chord's. The mesh still decides which pixels are sea, and their depth. Near the camera,
    // where the sag is nothing, the mesh's point (with its waves) stays.
    float sag = meshSagM(surfaceDistance, max(ocean.coarsestEdgePixels, oceanEdgeTargetPixels(surfaceDistance)));
    float farness = smoothstep(OCEAN_NEAR_FIELD_SAG_M, OCEAN_FAR_FIELD_SAG_M, sag);
    float seaDistance = surfaceDistance;
    float sphereDistance = seaSphereDistance(view);
    if (farness > 0.0 && sphereDistance > 0.0) {
        seaDistance = mix(surfaceDistance, sphereDistance, farness);
        up = normalize(mix(up, normalize(cameraFromPlanetCentreKm() * M_PER_KM + view * sphereDistance), farness));
    }
#endif

    // What is not seen is not shaded (issue 15), with tests that give the same pixels as
    // shading it would: ground surely above the highest crest (the continent value alone,
    // src/ocean/land_cull.h) is land, and a fragment no nearer than the terrain behind it
    // fails the depth test (the depth only grows from the seabed copy's).
    float continent = continentValue(up, uContinents);
    if (ocean.landCulling != 0 && continent >= ocean.landContinent) discard;
    float pixelAngle = radiansPerPixel();
    // What the sag means along this ray.
    float cosIncidence = max(abs(dot(view, up)), 0.05);
    vec3 forward = -vec3(frame.worldFromView[2]);
    float pulled = max(dot(tePosition, forward) - 2.0 * sag / cosIncidence * dot(view, forward), frame.nearPlane);
    float fragmentDepth = depthFromViewDistance(pulled);
    float seabed = texelFetch(seabedDepth, pixel, 0).r;
    float forwardCos = max(dot(view, forward), 1e-6);
    float seabedDistance = seabed > 0.0 ? viewDistanceFromDepth(seabed) / forwardCos : 1e30;
    // A pixel's footprint on the sea: its size at this distance, stretched along the view by
    // 1 / cos(incidence) (the long axis; ocean/sea_light.frag takes the same).
    float footprint = seaFootprint(seaDistance, pixelAngle, view, up);
    // Behind the land the depth test would drop this fragment, unless the land is the shore
    // itself, within this pixel's footprint in front of the water (its coverage below).
    bool behindLand = seabed > 0.0 && !(fragmentDepth > seabed);
    if (behindLand && surfaceDistance - seabedDistance > footprint) discard;

    vec3 heightGradient;
    float waterDepth = ocean.seaLevel - terrainHeightGrad(up, terrainShape, uContinents, heightGradient);
    // The shore's coverage of the pixel: the water's depth d along the local vertical (signed:
    // below 0 on land) changes across the pixel by `depthSpread` (the terrain's slope along
    // the pixel's steps); the share of the pixel under water is that of a linear ramp,
    // smoothstep(-spread/2, fade + spread/2, d), which near the camera (spread 0) is the
    // SHORE_FADE_M fade of the water's path and far off the area of the pixel on the wet
    // side of the waterline: an edge anti-aliased analytically, not a staircase of pixels.
    vec3 slope = (heightGradient - dot(heightGradient, up) * up) / frame.planetRadius;  // m per m of ground
    float depthSpread = min(abs(dot(slope, stepX)) + abs(dot(slope, stepY)), 2.0 * length(slope) * footprint);
    // Land: near the camera only where no crest can reach (waves may run up a beach, and the
    // depth test is exact there); where the meshes sag, wherever the terrain is above the sea;
    // less half the pixel's spread, where the pixel still holds some of the water.
    if (waterDepth < -ocean.maxWaveHeight * (1.0 - farness) - 0.5 * depthSpread) discard;
    // The water's path along the ray, signed (below 0: the land is in front), and the spread
    // as a path: the ray descends sin(elevation) per metre.
    float pathSpread = depthSpread / max(abs(dot(view, up)), 1e-4);
    // Where the terrain's mesh drew nothing behind the sea (its chords sag off the limb
    // from far away) there is no floor to fade into: the sea is the only surface there.
    float coverage = 1.0;
    if (seabed > 0.0) {
        float signedPath = mix(seabedDistance - surfaceDistance, waterDepth / cosIncidence, farness);
        coverage = smoothstep(-0.5 * pathSpread, SHORE_FADE_M + 0.5 * pathSpread, signedPath);
    }
    if (behindLand && coverage <= 0.0) discard;  // what the depth test would have done
    // A shore fragment behind the land's is moved just in front of it (the depth only grows).
    gl_FragDepth = behindLand ? uintBitsToFloat(floatBitsToUint(seabed) + 1u) : fragmentDepth;

    // Water between the surface and the seabed along this pixel's ray: from the depth buffer
    // near the camera, from the depth below the surface where the meshes sag.
    float depthPath = max(waterDepth, 0.0) / cosIncidence;
    // (With no floor drawn behind, the depth's path: the terrain leaves out the dark depths where
    // the sea covers them, terrain/terrain.tesc, and its chords may sag off the limb. A path of
    // 1e30 m here cancelled in the mix below where farness is 1 and left no water at all. Taking
    // at least SEA_FLOOR_DARK_DEPTH_M / cosIncidence where the floor was left out, for a grazing ray
    // that enters the sea over the shelf, changed the `beach` frame by up to 0.08 %: not kept.)
    float meshPath = seabed > 0.0 ? max(seabedDistance - surfaceDistance, 0.0) : depthPath;
    outSurfaceDistance = behindLand ? seabedDistance : seaDistance;  // mostly the land's pixel
#if OCEAN_FAR_FIELD
    vec2 teGridPoint = gridPointOf(up);  // only for the pixels that stay
#endif
    SeaSurface surface = SeaSurface(up, waterDepth, teOffset, seaDistance, coverage, behindLand,
                                    mix(meshPath, depthPath, farness), teGridPoint);
    packSeaSurface(surface, outSeaSurface0, outSeaSurface1, outSeaSurface2);
#if STENCIL_EXPORT
    gl_FragStencilRefARB = openSea(view, up, continent, seaDistance, footprint, pixelAngle) ? OPEN_SEA_STENCIL : SEA_STENCIL;
#endif
}
