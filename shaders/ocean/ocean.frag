// Ocean shading: the radiance leaving the sea surface towards the camera, with no air in it
// (the sky pass adds the air between, as for the land), into the surface radiance and
// distance targets, drawn over the sea floor's own surface radiance (Michelic §6: "shading
// accounts for the underwater terrain and atmosphere reflections"):
//   - Fresnel reflection (Schlick, F0 = 0.02 for water; Elek Eq. 18 is a cruder fit of
//     the same curve) of the sky and the clouds along the reflected ray: the clear sky per
//     pixel here; the clouds' change to it, the sky pass's own march (clouds/cloud_march.glsl)
//     with one atmosphere slice per crossing of the layer and a 32nd of its cloud steps, is
//     added by the sea reflection pass (ocean/sea_reflection.frag: marched at one pixel of
//     each 2x2 block along that pixel's reflected ray, which this pass writes with the weight
//     the change takes in its radiance); seen from high up, from the grid's points instead
//     (ocean/cloud_reflection.glsl, OCEAN_FLAT_MIRROR);
//     and of the terrain where the reflected ray meets it on screen (Michelic §6: "screen-
//     space reflections of the terrain"; ocean/screen_space_reflections.glsl), seen through
//     the air between, faded into the sky's reflection where the search is unsure: searched
//     by the terrain reflection pass (ocean/terrain_reflection.comp) at the pixels where
//     this pass finds that land may lie within the reflected ray's reach, from what it
//     leaves in its sea sky reflection target (the sky reflected there and its weight);
//   - sun glitter: the sun's irradiance at the surface (Elek Eq. 17, with the sun's
//     visibility) times a Gaussian slope distribution whose variance is the slopes of the
//     waves too small for the pixel plus the ripples finer than any wave (Cox & Munk 1954;
//     the reflectance form of Bruneton, Neyret & Holzschuch 2010);
//   - the water body: the sea floor's surface radiance seen through exp(-extinction * path)
//     of water, over the light scattered up by deep water:
//   R_G = (1-F) T_w R_floor + F L_sky(R) + L_glitter + (1-F)(1-T_w) L_deep
// The sea floor's radiance and depth are read from copies taken before this pass (a pass
// cannot sample what it renders into). Where the water is thinner than SHORE_FADE_M the
// result fades into the sea floor's, so the shoreline is soft and the two surfaces never
// fight for depth. Seen from below (camera under water) the surface passes on the sky above
// it, (1-F) L_sky; the water between the camera and the surface is the sky pass's.
//
// Far away the depth buffer cannot tell land from sea: both meshes are chords of the sphere
// that sag below it by (edge length)^2 / 8r between vertices (a kilometre from space), more
// than the height of a coastal plain. There the sea floor's height from the terrain's own
// height function decides (terrain/height.glsl, the continents map): the sea is pulled
// towards the camera by the sag (gl_FragDepth) so that sagging coastal land cannot hide it,
// is discarded where the terrain stands above it, and its water path comes from the depth
// below the surface. Near the camera the sag is far below a millimetre and nothing changes.
#include "common/frame_uniforms.glsl"
#define SUN_VISIBILITY_TERRAIN 1  // the terrain's shadows on the water (terrain/terrain_shadow.glsl)
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "terrain/grid.glsl"
#include "ocean/ocean_block.glsl"
#include "ocean/edge_target.glsl"
#include "ocean/sea_sphere.glsl"
#include "ocean/gerstner.glsl"
#include "ocean/ocean_waves.glsl"
#include "ocean/water.glsl"
#include "ocean/cloud_reflection.glsl"
#if OCEAN_FLAT_MIRROR
#include "ocean/grid_reflection_points.glsl"
#endif
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/terrain_block.glsl"
#include "ocean/screen_space_reflections.glsl"
#include "render/sample_spacing.glsl"
#include "render/block_samples.glsl"

in vec3 tePosition;
in vec3 teDirection;
in vec3 teOffset;
in vec2 teGridPoint;  // the place on the grid in point indices, for the grid's reflection (ocean/grid_reflection_points.glsl)

layout(binding = UNIT_SEABED_DEPTH) uniform sampler2D seabedDepth;         // copy of the G-buffer depth (reversed-Z)
layout(binding = UNIT_SEABED_RADIANCE) uniform sampler2D seabedRadiance;   // copy of the surface radiance
layout(binding = UNIT_TERRAIN_SHADOW) uniform sampler2D terrainShadowSamples;  // g: the sea surface's (render/terrain_shadow.frag)
#include "render/terrain_shadow_samples.glsl"
#include "ocean/sea_terrain_shadow.glsl"

layout(location = 0) out vec4 outSurfaceRadiance;
layout(location = 1) out float outSurfaceDistance;
// The reflected ray and the reflection's weight in this pixel's radiance, coverage x Fresnel
// (0 where it reflects nothing: from below, no sea), for the passes that change what the
// pixel reflects: the terrain reflection pass (which lowers the weight to the sky's share
// beside the terrain) and the sea reflection pass (the clouds' change, times that weight).
layout(location = 2) out vec4 outSeaReflection;
// Where the terrain may be reflected instead of the sky (land may lie within the reflected
// ray's reach): the sky this pixel reflected (with the clouds' change, as a flat mirror) and
// the sea's own distance along the view ray, m, for the terrain reflection pass; 0 elsewhere.
layout(location = 3) out vec4 outSeaSkyReflection;

layout(depth_greater) out float gl_FragDepth;  // reversed-Z: only ever moved towards the camera

#ifndef UNDER_WATER
#define UNDER_WATER 0
#endif

const float SHORE_FADE_M = 0.5;  // water path over which the sea fades in at the shore
// Off (0), no foam where the waves break at the shore (tests compare the two).
#define OCEAN_FOAM 1
// 1: the terrain's shadow on the water from the terrain shadow's samples of the sea's surface
// where they agree (render/terrain_shadow_samples.glsl), marched otherwise (after this pass:
// ocean/sea_terrain_shadow.glsl); 0: marched at every pixel where land may be within reach
// (tests compare the two).
#define OCEAN_TERRAIN_SHADOW_FROM_SAMPLES 1

// The sky the sea reflects along `reflected` from `point` (km from the planet centre; this
// fragment): the clear sky, with the clouds' change from the grid's points where the sea is a
// flat mirror to every pixel (else the sea reflection pass adds it); all of it from the grid's
// points where the sea is a smooth mirror (no pixel resolves a wave: every fragment's normal is
// the sphere's, its mirror ray the grid's, interpolated). The terrain reflected in its place is
// the terrain reflection pass's.
vec3 reflectedSky(vec3 point, vec3 reflected, vec3 sun) {
#if OCEAN_SMOOTH_MIRROR
    return gridReflectionAt(teGridPoint);
#else
    vec3 clearTransmittance;
    vec3 radiance = SkyRadiance(point, reflected, sun, clearTransmittance);
#if OCEAN_FLAT_MIRROR
    radiance += gridReflectionAt(teGridPoint);
#endif
    return radiance;
#endif
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    outSeaReflection = vec4(0.0);
    outSeaSkyReflection = vec4(0.0);
    // The surface's step from this pixel to the next, taken before any discard (derivatives
    // need the whole quad): how far the water's depth changes across the pixel (the shore's
    // coverage below).
    vec3 stepX = dFdx(tePosition);
    vec3 stepY = dFdy(tePosition);
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
    float farness = smoothstep(0.05, 0.5, sag);
    float seaDistance = surfaceDistance;
    float sphereDistance = seaSphereDistance(view);
    if (farness > 0.0 && sphereDistance > 0.0) {
        seaDistance = mix(surfaceDistance, sphereDistance, farness);
        up = normalize(mix(up, normalize(cameraFromPlanetCentreKm() * M_PER_KM + view * sphereDistance), farness));
    }
    vec3 sun = frame.sunDirection;

    // A pixel's footprint on the sea: its size at this distance, stretched along the view by
    // 1 / cos(incidence) (the long axis, so grazing views do not alias into sparkle; what it
    // drops becomes glitter roughness).
    // What is not seen is not shaded (issue 15), with tests that give the same pixels as
    // shading it would: ground surely above the highest crest (the continent value alone,
    // src/ocean/land_cull.h) is land, and a fragment no nearer than the terrain behind it
    // fails the depth test (the depth only grows from the seabed copy's).
    if (ocean.landCulling != 0 && continentValue(up, uContinents) >= ocean.landContinent) discard;
    float pixelAngle = radiansPerPixel();
    // What the sag means along this ray.
    float cosIncidence = max(abs(dot(view, up)), 0.05);
    vec3 forward = -vec3(frame.worldFromView[2]);
    float pulled = max(dot(tePosition, forward) - 2.0 * sag / cosIncidence * dot(view, forward), frame.nearPlane);
    float fragmentDepth = depthFromViewDistance(pulled);
    float seabed = texelFetch(seabedDepth, pixel, 0).r;
    float forwardCos = max(dot(view, forward), 1e-6);
    float seabedDistance = seabed > 0.0 ? viewDistanceFromDepth(seabed) / forwardCos : 1e30;
    float footprint = seaDistance * pixelAngle / max(abs(dot(view, up)), 0.02);
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
    float slopeVariance;
    float foam;  // the share of the surface under foam where the waves break
    vec3 normal = oceanNormalAndFoam(up, teOffset, footprint, waterDepth,
                                     OCEAN_FOAM != 0 ? ocean.maxWaveHeight / 0.39 : 0.0, slopeVariance, foam);
    // Seen from below only when the camera is under the sea (frame.cameraDepthBelowSea > 0: the
    // program built with UNDER_WATER 1, src/ocean/ocean_pass.cpp): not from gl_FrontFacing, which
    // also flips on the far side of steep crests at grazing views, where the sea is seen from
    // above. A program rather than an if: a software renderer runs both sides of an if for every
    // pixel.
    const bool fromBelow = UNDER_WATER != 0;
    if (fromBelow) normal = -normal;
    // A normal that faces away from the viewer (grazing views of steep waves) is bent back
    // just enough to face it: the reflection stays above the surface.
    float cosView = dot(normal, -view);
    if (cosView < 0.01) normal = normalize(normal + view * (cosView - 0.01));
    cosView = max(dot(normal, -view), 0.01);

    // Water between the surface and the seabed along this pixel's ray: from the depth
    // buffer near the camera, from the depth below the surface where the meshes sag.
    float depthPath = max(waterDepth, 0.0) / cosIncidence;
    // (With no floor drawn behind, the depth's path: the terrain leaves out the dark depths where
    // the sea covers them, terrain/terrain.tesc, and its chords may sag off the limb. A path of
    // 1e30 m here cancelled in the mix below where farness is 1 and left no water at all. Taking
    // at least SEA_FLOOR_DARK_DEPTH_M / cosIncidence where the floor was left out, for a grazing ray
    // that enters the sea over the shelf, changed the `beach` frame by up to 0.08 %: not kept.)
    float meshPath = seabed > 0.0 ? max(seabedDistance - surfaceDistance, 0.0) : depthPath;
    float waterPath = mix(meshPath, depthPath, farness);
    vec3 behind = texelFetch(seabedRadiance, pixel, 0).rgb;

    vec3 point = cameraFromPlanetCentreKm() + view * (seaDistance / M_PER_KM);  // km from the planet centre
    outSurfaceDistance = behindLand ? seabedDistance : seaDistance;  // mostly the land's pixel
    float fresnel = waterFresnel(cosView);
    if (fromBelow) {  // the sky above, through the surface; the water below is the sky pass's
        vec3 skyTransmittance;
        vec3 above = SkyRadiance(point, view, sun, skyTransmittance) + skyTransmittance * SunDiscRadiance(view, sun);
        outSurfaceRadiance = vec4(min((1.0 - fresnel) * above, vec3(MAX_HDR_RADIANCE)), 1.0);
        return;
    }

    vec3 reflected = SeaReflectedRay(view, normal, up);
    vec3 sky = reflectedSky(point, reflected, sun);
    // The reflection's weight in the pixel, for the passes that change what it reflects: the
    // sea reflection pass (the clouds' change, but as a flat mirror, which has it) and the
    // terrain reflection pass, which searches the terrain where it may be reflected instead.
    outSeaReflection = vec4(reflected, coverage * fresnel);
    if (terrainMayBeReflected(up, reflected, ocean.seaLevel, seaDistance, pixelAngle))
        outSeaSkyReflection = vec4(sky, seaDistance);
    // The sun's visibility from the water's surface (the clouds' shadows and the terrain's, the
    // march starting at sea level, not on the sea floor), formed once for the light into the
    // water and the glitter.
    float sunVisibility = 1.0;
    bool marchLater = false;  // the terrain's shadow marched by ocean/sea_terrain_shadow.comp
    float meanClearance = 1.0;  // the samples' mean clearance (rad), where no march can be had
    float radius = atmosphereUniforms.sunAngularRadius;
    if (dot(up, sun) > 0.0) {
        sunVisibility = CloudSunTransmittance(point, sun, CLOUD_SHADOW_MAX_KM);
        // The terrain's march only where it may find land and the samples around the pixel do
        // not agree (a shadow's edge, the shore), and not here: the pixel is shaded as lit by the
        // terrain and listed (ocean/sea_terrain_shadow.glsl), since a software renderer runs a
        // march's first turn for every pixel here, listed or not (README "Programs, not branches").
        bool mayReach = terrainShadowMayReachSea(up, sun, ocean.seaLevel, frame.planetRadius / M_PER_KM,
                                                 ocean.continentLipschitz, ocean.continentSampleSlackRad, terrainShape,
                                                 uContinents);
        float clearance = 1.0;  // rad: lit, where no land is within reach
        // (Without shadows, or built without them, the march finds the sun clear.)
        marchLater = SUN_VISIBILITY_TERRAIN != 0 && mayReach && terrainShadows != 0;
#if SUN_VISIBILITY_TERRAIN
        bool agree = terrainClearanceFromSamples(terrainShadowSamples, pixel, 1, radius, clearance, meanClearance);
        if (OCEAN_TERRAIN_SHADOW_FROM_SAMPLES != 0 && terrainShadows != 0 && agree) marchLater = false;
#endif
        if (!marchLater) sunVisibility *= terrainShadowDiscShare(clearance, radius);
    }
    vec3 skyIrradiance;
    vec3 sunIrradiance = SunAndSkyIrradianceUnshadowed(point, up, sun, skyIrradiance) * sunVisibility;
    // The sun's irradiance on a surface facing it: through the atmosphere, not yet weighted by a normal.
    vec3 glitter = dot(up, sun) > 0.0
                       ? SunIrradianceUnshadowed(point, sun) * sunVisibility *
                             sunGlitter(normal, -view, sun, slopeVariance + ocean.subgridSlopeVariance)
                       : vec3(0.0);

    vec3 waterTransmittance = waterTransmittanceAlong(waterPath);
    vec3 deep = deepWaterRadiance(sunIrradiance + skyIrradiance);
    vec3 surface = (1.0 - fresnel) * waterTransmittance * behind + fresnel * sky + glitter +
                   (1.0 - fresnel) * (1.0 - waterTransmittance) * deep;
    surface = mix(surface, foamRadiance(sunIrradiance + skyIrradiance), foam);
    vec3 radiance = mix(behind, surface, coverage);
    if (marchLater) {
        // What of the radiance the sun's light carries (each term linear in it): the glitter, the
        // light scattered up, the foam. The march after this pass takes away the share of it that
        // the terrain hides from the lit radiance kept here, or where it is most of the radiance
        // (a bright glitter, which would swamp what stays in full shadow in the half-float target)
        // adds the share it leaves to the rest kept here.
        vec3 sunShare = coverage * ((1.0 - foam) * (glitter + (1.0 - fresnel) * (1.0 - waterTransmittance) *
                                                               deepWaterRadiance(sunIrradiance)) +
                                    foam * foamRadiance(sunIrradiance));
        bool keepRest = dot(sunShare, vec3(1.0)) > 0.5 * dot(radiance, vec3(1.0));
        // At a shore fragment behind the land's edge (its pixel keeps the land's distance) or past
        // the list's capacity, the samples' mean visibility instead.
        bool listed = !behindLand && listSeaTerrainShadow(pixel, seaDistance, sunShare, keepRest);
        if (!listed)
            radiance -= sunShare * (1.0 - terrainShadowDiscShare(meanClearance, radius));
        else if (keepRest)
            radiance = max(radiance - sunShare, vec3(0.0));
    }
    outSurfaceRadiance = vec4(min(radiance, vec3(MAX_HDR_RADIANCE)), 1.0);
}
