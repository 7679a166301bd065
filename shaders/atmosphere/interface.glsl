// The atmosphere as every shader that draws sees it (after Bruneton's kAtmosphereShader):
// the tables declared once at the units of common/bindings.glsl, the parameter block, and
// a handful of functions that take positions (km, relative to the planet centre) and
// directions only. Callers never name a texture, a unit or a table layout.
//
//   SkyRadiance                 light scattered towards the camera along a ray to space
//                               or the ground, and the ray's transmittance
//   SkyRadianceToPoint          the same up to a point at a given distance (aerial
//                               perspective: Elek Eq. 19-20, Sperlhofer Eq. 4-18)
//   SkyRadianceAt,              both for a camera given by its unit up and its altitude
//   SkyRadianceToPointAt        above the bottom radius (km, formed apart, e.g. in double on
//                               the CPU): a float position of planet size resolves half a
//                               metre, so from a few metres up the sky below the horizon
//                               (and aerial perspective near the ground) needs these
//   TransmittanceToPoint        transmittance alone along the same segment
//   SunIrradianceAtPoint        the solar irradiance arriving at a point, through the air and
//                               times the sun's visibility there (Elek Eq. 17)
//   SunAndSkyIrradiance         what lights a surface with a normal: the direct sun
//                               (visibility included) and the sky (Elek Eq. 17, 20)
//   SunDiscRadiance             the limb-darkened disc, before the atmosphere
//   SunVisibility               the hook through which shadows enter surfaces: the fraction
//                               of the sun seen from a point: the clouds' transmittance
//                               towards the sun (clouds/cloud_density.glsl) times the
//                               terrain's (terrain/terrain_shadow.glsl, preset
//                               terrain.shadows) in programs that define
//                               SUN_VISIBILITY_TERRAIN before including this file (the
//                               surface light, the sea); every sun irradiance above uses it.
//                               The others (the sky passes' sea surface above a diver, the
//                               probes) and the cloud march do not pay for the march:
//                               software renderers run it even in a branch not taken.
//                               TerrainSunVisibilityAbove starts the terrain's march at a
//                               height (the sea's surface over the sea floor); the
//                               *Unshadowed irradiances leave the visibility out for a
//                               caller that forms it once for several terms (the sea).
//   SunShadowLength             the hook through which they enter the in-scattering: how much
//                               of a view segment lies in the terrain's shadow (Bruneton's
//                               shadow_length: light shafts, preset terrain.light_shafts) in
//                               programs built with LIGHT_SHAFTS_TERRAIN 1 (the sky passes'
//                               variant for a preset with light shafts on: compiled in, the
//                               code doubled the sky pass on llvmpipe even with its loops at
//                               no turns), else 0; SkyRadianceToPoint takes it off the
//                               segment's far end, SkyRadiance off the near end of a ray to space.
//
// Bruneton's 4D table or Elek's 3D table (preset atmosphere.elek_3d_table) is chosen here,
// at compile time: a program including this file is built once with ELEK_TABLE 0 and once
// with ELEK_TABLE 1 (src/render/atmosphere_program.h), because software renderers run
// both sides of even a uniform branch. Transmittance and irradiance are the same in both.
#include "common/bindings.glsl"
#include "common/constants.glsl"
#include "atmosphere/definitions.glsl"
#include "atmosphere/uniforms.glsl"
#include "atmosphere/functions.glsl"
#include "atmosphere/elek_table.glsl"
#include "atmosphere/rendering.glsl"
#include "clouds/cloud_model.glsl"
#include "clouds/cloud_block.glsl"
#include "clouds/cloud_density.glsl"
// Included whether or not the program takes the terrain's shadows: includes are expanded
// (once per program) before the preprocessor runs, so one inside an #if would be swallowed
// and skipped where the program includes it again. Unused, they cost nothing.
#include "common/frame_uniforms.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"
#include "terrain/terrain_block.glsl"
#include "terrain/terrain_shadow.glsl"
#ifndef SUN_VISIBILITY_TERRAIN
#define SUN_VISIBILITY_TERRAIN 0
#endif
#ifndef LIGHT_SHAFTS_TERRAIN
#define LIGHT_SHAFTS_TERRAIN 0
#endif
// The pixel (centre, as gl_FragCoord.xy) whose light shafts are marched: their jitter's seed. A
// compute shader that marches pixels (render/sky_refine.comp) defines it as its own variable.
#ifndef SHAFT_PIXEL
#define SHAFT_PIXEL gl_FragCoord.xy
#endif

#ifndef ELEK_TABLE
#define ELEK_TABLE 0
#endif

layout(binding = UNIT_TRANSMITTANCE) uniform sampler2D transmittance_texture;
layout(binding = UNIT_IRRADIANCE) uniform sampler2D irradiance_texture;
#if ELEK_TABLE
layout(binding = UNIT_ELEK_SCATTERING) uniform sampler3D scattering_texture;
layout(binding = UNIT_ELEK_SINGLE_MIE) uniform sampler3D single_mie_scattering_texture;
#else
layout(binding = UNIT_SCATTERING) uniform sampler3D scattering_texture;
layout(binding = UNIT_SINGLE_MIE) uniform sampler3D single_mie_scattering_texture;
#endif
const bool USE_ELEK_TABLE = ELEK_TABLE != 0;

const float LIMB_DARKENING_U = 0.6;     // linear law I(mu) = 1 - u (1 - mu), visible light
const float MAX_HDR_RADIANCE = 6.0e4;   // below the largest half float (65504)

// The longest way through the cloud layer a shadow ray samples, km: a sun near the horizon
// crosses hundreds of km of layer; beyond this the clouds' shadow is taken as the samples say.
const float CLOUD_SHADOW_MAX_KM = 100.0;

// The share of the sun's disc the terrain leaves visible from the ground under `point` (km
// from the planet centre): a march over the height field (terrain/terrain_shadow.glsl), at
// the resolution of the pixel's footprint on the ground (from the frame's camera; shadows
// shorter than a pixel are not marched). 1 when the preset's terrain.shadows is off, or the
// program did not ask for SUN_VISIBILITY_TERRAIN.
// TerrainSunVisibilityAbove: from `startM` metres above sea level where the ground is lower
// (the sea's surface: its light is shadowed from there, not from the sea floor).
// TerrainShadowClearance: the march's smallest clearance angle instead (rad, 1 where none was
// marched; terrain_shadow.glsl's terrainShadowClearanceAbove), from the ground.
float TerrainShadowClearanceAbove(vec3 point, float startM, vec3 sun) {
#if SUN_VISIBILITY_TERRAIN
    float footprintKm = distance(point, cameraFromPlanetCentreKm()) * radiansPerPixel();
    int samples = terrainShadows != 0 ? TERRAIN_SHADOW_SAMPLES : 0;  // from the uniform: see terrainSunVisibility
    return terrainShadowClearanceAbove(point, startM, sun, frame.planetRadius / M_PER_KM,
                                       atmosphereUniforms.sunAngularRadius, footprintKm, samples, terrainShape,
                                       uContinents);
#else
    return 1.0;
#endif
}
float TerrainShadowClearance(vec3 point, vec3 sun) { return TerrainShadowClearanceAbove(point, -1.0e9, sun); }
float TerrainSunVisibilityAbove(vec3 point, float startM, vec3 sun) {
#if SUN_VISIBILITY_TERRAIN
    return terrainShadowDiscShare(TerrainShadowClearanceAbove(point, startM, sun), atmosphereUniforms.sunAngularRadius);
#else
    return 1.0;
#endif
}
float TerrainSunVisibility(vec3 point, vec3 sun) { return TerrainSunVisibilityAbove(point, -1.0e9, sun); }

// The fraction of the sun's disc seen from `point` (km from the planet centre) on a surface:
// the clouds' transmittance towards the sun (Michelic §6 takes one density sample
// mid-layer; here clouds.sunSamples samples over the sun ray's way through the layer, so
// thin and thick clouds and a low sun shade differently) times the terrain's visibility,
// so the shadows of both darken the ground together.
float SunVisibility(vec3 point, vec3 sun) {
    return CloudSunTransmittance(point, sun, CLOUD_SHADOW_MAX_KM) * TerrainSunVisibility(point, sun);
}
// Light shafts: the terrain's shadow in the air, sampled at this many points along the part of a
// view segment the terrain can shadow (below its highest height), at most this long (km): a
// sample's march starts at its own height and resolves shadows as long as the samples' spacing.
const int LIGHT_SHAFT_SAMPLES = 8;
const float LIGHT_SHAFT_MAX_KM = 60.0;

// km of the segment from `camera` along the unit `viewRay` for `distance` km (< 0: to where it
// leaves the terrain's reach; 0: an empty segment) that the terrain keeps the sun from: LIGHT_SHAFT_SAMPLES points,
// jittered per pixel and frame (the temporal march and the stills' samples average them),
// each weighted by the share of the sun's disc it does not see. 0 where the preset's
// terrain.light_shafts or terrain.shadows is off (a loop of no turns), or the program did not
// ask for LIGHT_SHAFTS_TERRAIN. Where the shadowed length lies along the segment is not kept:
// Bruneton's shadow_length puts it at one end (see SkyRadianceToPoint and SkyRadiance).
float SunShadowLength(vec3 camera, vec3 viewRay, float distance, vec3 sun) {
#if LIGHT_SHAFTS_TERRAIN
    int samples = terrainLightShafts != 0 && terrainShadows != 0 && distance != 0.0 ? LIGHT_SHAFT_SAMPLES : 0;
    // The march's own count from the uniform too, not the constant (see terrainSunVisibility:
    // a constant trip count is unrolled, and compiling 26 inlined height fields takes minutes).
    int march = terrainShadows != 0 ? TERRAIN_SHADOW_SAMPLES : 0;
    float planetKm = frame.planetRadius / M_PER_KM;
    float reachKm = planetKm + terrainShape.maxHeight * 0.001;  // nothing above casts or takes a shadow
    float r = length(camera);
    float rmu = dot(camera, viewRay);
    float discriminant = rmu * rmu - (r - reachKm) * (r + reachKm);
    float root = sqrt(max(discriminant, 0.0));
    float enter = max(-rmu - root, 0.0);
    float leave = -rmu + root;
    if (distance > 0.0) leave = min(leave, distance);
    leave = min(leave, enter + LIGHT_SHAFT_MAX_KM);
    if (discriminant <= 0.0 || leave <= enter) samples = 0;
    float spacing = (leave - enter) / float(LIGHT_SHAFT_SAMPLES);
    float jitter = fract(fract(52.9829189 * fract(dot(SHAFT_PIXEL, vec2(0.06711056, 0.00583715)))) +
                         0.6180340 * float(frame.frameIndex % 64));
    float shadowed = 0.0;
    for (int i = 0; i < samples; ++i) {
        vec3 point = camera + viewRay * (enter + (float(i) + jitter) * spacing);
        float heightM = (length(point) - planetKm) * 1000.0;
        shadowed += 1.0 - terrainSunVisibilityAbove(point, heightM, sun, planetKm, atmosphereUniforms.sunAngularRadius,
                                                    spacing, march, terrainShape, uContinents);
    }
    return shadowed * spacing;
#else
    return 0.0;
#endif
}

// The sky along a ray to space from `shadowLength` km along it on, times the transmittance up
// to there: with light shafts, the shadowed length SunShadowLength finds is taken off the ray's
// near end (Bruneton's GetSkyRadiance with a shadow_length; the whole ray's transmittance kept).
vec3 SkyRadianceBeyond(vec3 camera, vec3 viewRay, vec3 sun, float shadowLength) {
    AtmosphereParameters atmosphere = atmosphereParameters();
    ViewRay ray = ViewRayInAtmosphere(atmosphere, camera, viewRay, viewRay);
    if (!ray.inside) return vec3(0.0);
    // From where the ray enters the air (a camera in space: ray.skipped km on).
    vec3 unused;
    vec3 beyond = GetSkyRadianceFrom(atmosphere, USE_ELEK_TABLE, transmittance_texture, scattering_texture,
                                     single_mie_scattering_texture, camera + viewRay * (ray.skipped + shadowLength),
                                     viewRay, sun, unused);
    return beyond * GetTransmittanceRho2(atmosphere, transmittance_texture, ray.rho2, ray.r * ray.mu, shadowLength,
                                         RayIntersectsGroundRho2(ray.rho2, ray.r * ray.mu));
}

// A view ray from a viewpoint given by its unit `up` and its `altitudeKm` above the bottom
// radius (`byAltitude`: exact from centimetres above the ground, where a float position's
// radius is rounded to half a metre) or else by its `position` (km from the planet centre):
// the parameters of Bruneton's lookups, chosen by value, so that a caller that may start its
// ray either way makes one lookup, not one in each branch (a software renderer runs both sides
// of an if for every pixel: the air alone cost 40 % more that way, issue 15).
ViewRay AirRay(vec3 up, float altitudeKm, bool byAltitude, vec3 position, vec3 viewRay, vec3 sun) {
    AtmosphereParameters atmosphere = atmosphereParameters();
    return byAltitude ? ViewRayInAtmosphereAt(atmosphere, up, altitudeKm, viewRay, sun)
                      : ViewRayInAtmosphere(atmosphere, position, viewRay, sun);
}

// The sky along `ray` (AirRay) to space from the viewpoint `camera` (km from the planet
// centre; where light shafts start). A loop of one turn or none rather than an if (see
// SunShadowLength): without light shafts nothing of it runs.
vec3 SkyRadianceOfRay(ViewRay ray, vec3 camera, vec3 viewRay, vec3 sun, out vec3 transmittance) {
    vec3 inscatter = GetSkyRadianceOfRay(atmosphereParameters(), USE_ELEK_TABLE, transmittance_texture,
                                         scattering_texture, single_mie_scattering_texture, ray, transmittance);
    float shadowLength = SunShadowLength(camera, viewRay, -1.0, sun);
    for (int i = 0; i < (shadowLength > 0.0 ? 1 : 0); ++i)
        inscatter = SkyRadianceBeyond(camera, viewRay, sun, shadowLength);
    return inscatter;
}

// The air along `ray` (AirRay) from `camera` to `distance` km along the unit `viewRay` (ray
// and distance rather than the point, so a point 2 m away stays exact in float).
vec3 SkyRadianceToPointOfRay(ViewRay ray, vec3 camera, vec3 viewRay, float distance, vec3 sun,
                             out vec3 transmittance) {
    return GetSkyRadianceToPointOfRay(atmosphereParameters(), USE_ELEK_TABLE, transmittance_texture,
                                      scattering_texture, single_mie_scattering_texture, ray, distance,
                                      SunShadowLength(camera, viewRay, distance, sun), transmittance);
}

// The same by position, and by up and altitude.
vec3 SkyRadiance(vec3 camera, vec3 viewRay, vec3 sun, out vec3 transmittance) {
    return SkyRadianceOfRay(AirRay(camera, 0.0, false, camera, viewRay, sun), camera, viewRay, sun, transmittance);
}
vec3 SkyRadianceToPoint(vec3 camera, vec3 viewRay, float distance, vec3 sun, out vec3 transmittance) {
    return SkyRadianceToPointOfRay(AirRay(camera, 0.0, false, camera, viewRay, sun), camera, viewRay, distance, sun,
                                   transmittance);
}
vec3 SkyRadianceAt(vec3 up, float altitudeKm, vec3 viewRay, vec3 sun, out vec3 transmittance) {
    vec3 camera = up * (atmosphereUniforms.bottomRadius + altitudeKm);
    return SkyRadianceOfRay(AirRay(up, altitudeKm, true, camera, viewRay, sun), camera, viewRay, sun, transmittance);
}
vec3 SkyRadianceToPointAt(vec3 up, float altitudeKm, vec3 viewRay, float distance, vec3 sun,
                          out vec3 transmittance) {
    vec3 camera = up * (atmosphereUniforms.bottomRadius + altitudeKm);
    return SkyRadianceToPointOfRay(AirRay(up, altitudeKm, true, camera, viewRay, sun), camera, viewRay, distance, sun,
                                   transmittance);
}

vec3 TransmittanceToPoint(vec3 camera, vec3 viewRay, float distance) {
    AtmosphereParameters atmosphere = atmosphereParameters();
    ViewRay ray = ViewRayInAtmosphere(atmosphere, camera, viewRay, viewRay);
    if (!ray.inside) return vec3(1.0);
    float d = max(distance - ray.skipped, 0.0);
    return GetTransmittanceRho2(atmosphere, transmittance_texture, ray.rho2, ray.r * ray.mu, d,
                                RayIntersectsGroundRho2(ray.rho2, ray.r * ray.mu));
}

// The sun's irradiance at `point` on a surface facing it, through the atmosphere; the
// Unshadowed forms leave out SunVisibility, for a caller that forms it once for several terms.
vec3 SunIrradianceUnshadowed(vec3 point, vec3 sun) {
    AtmosphereParameters atmosphere = atmosphereParameters();
    float r = length(point);
    return atmosphere.solar_irradiance * GetTransmittanceToSun(atmosphere, transmittance_texture, r, dot(point, sun) / r);
}
vec3 SunIrradianceAtPoint(vec3 point, vec3 sun) { return SunIrradianceUnshadowed(point, sun) * SunVisibility(point, sun); }

vec3 SunAndSkyIrradianceUnshadowed(vec3 point, vec3 normal, vec3 sun, out vec3 skyIrradiance) {
    return GetSunAndSkyIrradiance(atmosphereParameters(), transmittance_texture, irradiance_texture, point, normal, sun,
                                  skyIrradiance);
}
// The visibility only where the sun lights the surface at all (a slope facing away from it
// pays no shadow march).
vec3 SunAndSkyIrradiance(vec3 point, vec3 normal, vec3 sun, out vec3 skyIrradiance) {
    vec3 sunIrradiance = SunAndSkyIrradianceUnshadowed(point, normal, sun, skyIrradiance);
    return dot(normal, sun) > 0.0 ? sunIrradiance * SunVisibility(point, sun) : sunIrradiance;
}

// Sun disc radiance towards `dir`, before the atmosphere. Normalised so the disc delivers
// the solar irradiance: the mean of the linear law over the disc is 1 - u / 3. Angles from
// |dir x sun| stay precise for a 0.27 deg disc.
vec3 SunDiscRadiance(vec3 dir, vec3 sun) {
    float angularRadius = atmosphereUniforms.sunAngularRadius;
    if (dot(dir, sun) <= 0.0) return vec3(0.0);
    float angle = asin(min(length(cross(dir, sun)), 1.0));
    if (angle >= angularRadius) return vec3(0.0);
    float x = angle / angularRadius;
    float mu = sqrt(1.0 - x * x);
    float discSolidAngle = PI * angularRadius * angularRadius;
    vec3 radiance = atmosphereUniforms.solarIrradiance / discSolidAngle * (1.0 - LIMB_DARKENING_U * (1.0 - mu)) /
                    (1.0 - LIMB_DARKENING_U / 3.0);
    return min(radiance, vec3(MAX_HDR_RADIANCE));  // a tiny disc must not overflow the RGBA16F target
}
