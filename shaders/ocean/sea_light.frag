// Ocean shading: the radiance leaving the sea surface towards the camera, with no air in it
// (the sky pass adds the air between, as for the land), into the surface radiance target,
// over the sea floor's own surface radiance (Michelic §6: "shading
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
// The sea floor's radiance is read from a copy taken before the ocean's mesh is drawn (a pass
// cannot sample what it renders into); the result fades into it by the shore's coverage
// (ocean/ocean.frag). Seen from below (camera under water) the surface passes on the sky above
// it, (1-F) L_sky; the water between the camera and the surface is the sky pass's.
//
// Runs once per pixel where the ocean's mesh left the sea as the nearest surface (the stencil,
// 1 there: ocean/ocean.frag, which also decides the shore's coverage, the water's depth and path
// and the far field's sphere; ocean/sea_surface.glsl), over the whole frame: a software renderer
// shades a 4x4 block of pixels for every triangle touching it, and the mesh's fragments were two
// to three times the sea's pixels.
//
// OPEN_SEA 1: the build for the pixels ocean/ocean.frag marked as the open sea (OceanPass::
// kOpenSeaStencil: no land within reach of the reflected ray or the sun's), where the light's own
// tests find the same: no terrain reflection to list, no terrain shadow, so none of their code
// (a software renderer ran it for every pixel, masked: `orbit`, 1280x720, the light 31 -> 23 ms).
#ifndef OPEN_SEA
#define OPEN_SEA 0
#endif
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
#include "ocean/sea_surface.glsl"

// The stencil's test before the shader runs (it writes no depth and discards nothing, so the
// result is the same; without this a shader that writes memory, as the sea terrain shadow's list
// does, is tested after it ran, and a software renderer then shades every pixel).
layout(early_fragment_tests) in;

layout(binding = UNIT_MESH_SURFACE_0) uniform sampler2D seaSurface0;  // the sea surface's G-buffer (ocean/sea_surface.glsl)
layout(binding = UNIT_MESH_SURFACE_1) uniform sampler2D seaSurface1;
layout(binding = UNIT_MESH_SURFACE_2) uniform sampler2D seaSurface2;

layout(binding = UNIT_SEABED_RADIANCE) uniform sampler2D seabedRadiance;   // copy of the surface radiance
layout(binding = UNIT_TERRAIN_SHADOW) uniform sampler2D terrainShadowSamples;  // g: the sea surface's (render/terrain_shadow.frag)
#include "render/terrain_shadow_samples.glsl"
#include "render/terrain_shadow_list.glsl"
#define PIXEL_LIST_BINDING BUFFER_TERRAIN_REFLECTION_LIST
#include "render/pixel_list.glsl"  // the terrain reflection's (ocean/terrain_reflection.glsl)
#include "render/land_on_screen.glsl"

layout(location = 0) out vec4 outSurfaceRadiance;
// The reflected ray and the reflection's weight in this pixel's radiance, coverage x Fresnel
// (0 where it reflects nothing: from below, no sea), for the passes that change what the
// pixel reflects: the terrain reflection pass (which lowers the weight to the sky's share
// beside the terrain) and the sea reflection pass (the clouds' change, times that weight).
layout(location = 1) out vec4 outSeaReflection;
// Where the terrain may be reflected instead of the sky (land may lie within the reflected
// ray's reach): the sky this pixel reflected (with the clouds' change, as a flat mirror) and
// the sea's own distance along the view ray, m, for the terrain reflection pass; 0 elsewhere.
layout(location = 2) out vec4 outSeaSkyReflection;

#ifndef UNDER_WATER
#define UNDER_WATER 0
#endif

// Off (0), no foam where the waves break at the shore (tests compare the two).
#define OCEAN_FOAM 1
// 1: the terrain's shadow on the water from the terrain shadow's samples of the sea's surface
// where they agree (render/terrain_shadow_samples.glsl), marched otherwise (after this pass:
// render/terrain_shadow_list.glsl); 0: marched at every pixel where land may be within reach
// (tests compare the two).
#define OCEAN_TERRAIN_SHADOW_FROM_SAMPLES 1

// The sky the sea reflects along `reflected` from `point` (km from the planet centre; this
// fragment): the clear sky, with the clouds' change from the grid's points where the sea is a
// flat mirror to every pixel (else the sea reflection pass adds it); all of it from the grid's
// points where the sea is a smooth mirror (no pixel resolves a wave: every fragment's normal is
// the sphere's, its mirror ray the grid's, interpolated). The terrain reflected in its place is
// the terrain reflection pass's.
vec3 reflectedSky(vec3 point, vec3 reflected, vec3 sun, vec2 gridPoint) {
#if OCEAN_SMOOTH_MIRROR
    return gridReflectionAt(gridPoint);
#else
    vec3 clearTransmittance;
    vec3 radiance = SkyRadiance(point, reflected, sun, clearTransmittance);
#if OCEAN_FLAT_MIRROR
    radiance += gridReflectionAt(gridPoint);
#endif
    return radiance;
#endif
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    SeaSurface sea = unpackSeaSurface(texelFetch(seaSurface0, pixel, 0), texelFetch(seaSurface1, pixel, 0),
                                      texelFetch(seaSurface2, pixel, 0));
    vec3 view = pixelRay(pixel);  // camera -> surface: formed as the compute passes after this form it
    vec3 up = sea.up;
    float seaDistance = sea.distance;
    float waterDepth = sea.waterDepth;
    float coverage = sea.coverage;
    bool behindLand = sea.behindLand;
    float pixelAngle = radiansPerPixel();
    float footprint = seaFootprint(seaDistance, pixelAngle, view, up);
    vec3 sun = frame.sunDirection;
    outSeaReflection = vec4(0.0);
    outSeaSkyReflection = vec4(0.0);
    float slopeVariance;
    float foam;  // the share of the surface under foam where the waves break
    vec3 normal = oceanNormalAndFoam(up, sea.offset, footprint, waterDepth,
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

    float waterPath = sea.waterPath;
    vec3 behind = texelFetch(seabedRadiance, pixel, 0).rgb;

    vec3 point = cameraFromPlanetCentreKm() + view * (seaDistance / M_PER_KM);  // km from the planet centre
    float fresnel = waterFresnel(cosView);
    if (fromBelow) {  // the sky above, through the surface; the water below is the sky pass's
        vec3 skyTransmittance;
        vec3 above = SkyRadiance(point, view, sun, skyTransmittance) + skyTransmittance * SunDiscRadiance(view, sun);
        outSurfaceRadiance = vec4(min((1.0 - fresnel) * above, vec3(MAX_HDR_RADIANCE)), 1.0);
        return;
    }

    vec3 reflected = SeaReflectedRay(view, normal, up);
    vec3 sky = reflectedSky(point, reflected, sun, sea.gridPoint);
    // The reflection's weight in the pixel, for the passes that change what it reflects: the
    // sea reflection pass (the clouds' change, but as a flat mirror, which has it) and the
    // terrain reflection pass, which searches the terrain where it may be reflected instead.
    outSeaReflection = vec4(reflected, coverage * fresnel);
#if OPEN_SEA
    vec2 reachKm = vec2(0.0);  // (the mark's: no land within reach of either)
#else
    // How far the reflected ray (x) and the sun's (y) can still meet land near the pixel, km, both
    // at once (one continent value, one loop of turns).
    vec2 reachKm = terrainReachesBelowLandKm(up, ocean.seaLevel, vec2(dot(reflected, up), dot(up, sun)),
                                             vec2(1.0e30, TERRAIN_SHADOW_MAX_KM), frame.planetRadius / M_PER_KM,
                                             ocean.continentLipschitz, ocean.continentSampleSlackRad, terrainShape,
                                             uContinents);
    if (terrainMayBeReflected(reachKm.x * M_PER_KM, seaDistance, pixelAngle)) {
        outSeaSkyReflection = vec4(sky, seaDistance);
        if (landOnScreen != 0u || TERRAIN_REFLECTION_SEARCH_ALL != 0) listPixel(pixel);
    }
#endif
    // The sun's visibility from the water's surface (the clouds' shadows and the terrain's, the
    // march starting at sea level, not on the sea floor), formed once for the light into the
    // water and the glitter.
    float sunVisibility = 1.0;
    bool marchLater = false;  // the terrain's shadow marched by render/terrain_shadow_list.comp
    float meanClearance = 1.0;  // the samples' mean clearance (rad), where no march can be had
    float radius = atmosphereUniforms.sunAngularRadius;
    // Lit while any of the sun's disc is above the horizon: the sun's irradiance fades out over its
    // disc there (atmosphere/functions.glsl, SunAboveHorizonFraction); cut at its centre, the
    // glitter stopped at half its brightness, a hard line along the terminator seen from orbit.
    bool sunUp = dot(up, sun) > -radius;
    if (sunUp) {
        sunVisibility = CloudSunTransmittance(point, sun, CLOUD_SHADOW_MAX_KM);
        // The terrain's march only where it may find land and the samples around the pixel do
        // not agree (a shadow's edge, the shore), and not here: the pixel is shaded as lit by the
        // terrain and listed (render/terrain_shadow_list.glsl), since a software renderer runs a
        // march's first turn for every pixel here, listed or not (README "Programs, not branches").
        bool mayReach = OPEN_SEA == 0 && terrainShadowMayReachSeaWithin(reachKm.y, ocean.seaLevel, ocean.continentLipschitz);
        float clearance = 1.0;  // rad: lit, where no land is within reach
        // (Without shadows, or built without them, the march finds the sun clear.)
        marchLater = SUN_VISIBILITY_TERRAIN != 0 && mayReach && terrainShadows != 0;
#if SUN_VISIBILITY_TERRAIN
        // (Where no land is within reach the pixel is lit, whatever the samples around it found: they
        // lie at other points, whose reach may hold land.)
        bool agree = mayReach && terrainClearanceFromSamples(terrainShadowSamples, pixel, 1, radius, clearance,
                                                             meanClearance);
        if (OCEAN_TERRAIN_SHADOW_FROM_SAMPLES != 0 && terrainShadows != 0 && agree) marchLater = false;
#endif
        if (!marchLater) sunVisibility *= terrainShadowDiscShare(clearance, radius);
    }
    vec3 skyIrradiance;
    vec3 sunIrradiance = SunAndSkyIrradianceUnshadowed(point, up, sun, skyIrradiance) * sunVisibility;
    // The sun's irradiance on a surface facing it: through the atmosphere, not yet weighted by a normal.
    vec3 glitter = sunUp
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
        bool listed = !behindLand && listTerrainShadow(pixel, seaDistance, sunShare, keepRest);
        if (!listed)
            radiance -= sunShare * (1.0 - terrainShadowDiscShare(meanClearance, radius));
        else if (keepRest)
            radiance = max(radiance - sunShare, vec3(0.0));
    }
    outSurfaceRadiance = vec4(min(radiance, vec3(MAX_HDR_RADIANCE)), 1.0);
}
