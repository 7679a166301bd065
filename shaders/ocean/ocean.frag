// Ocean shading, forward into the HDR target after the atmosphere pass (Michelic §6:
// "shading accounts for the underwater terrain and atmosphere reflections"):
//   - Fresnel reflection (Schlick, F0 = 0.02 for water; Elek Eq. 18 is a cruder fit of
//     the same curve) of the sky along the reflected ray, from the atmosphere tables;
//   - sun glitter: the sun's irradiance through the atmosphere (Elek Eq. 17) times a
//     Gaussian slope distribution whose variance is the slopes of the waves too small for
//     the pixel plus the ripples finer than any wave (Cox & Munk 1954; the reflectance form of
//     Bruneton, Neyret & Holzschuch 2010, "Real-time realistic ocean lighting");
//   - the water body: the seabed already lit by the atmosphere pass, seen through
//     exp(-extinction * path) of water, over the light scattered up by deep water;
//   - aerial perspective between camera and surface, from the same tables.
// The seabed's radiance is read from a copy of the HDR target and its depth from a copy of
// the G-buffer depth (a pass cannot sample what it renders into). It already carries the
// air's aerial perspective to the seabed, so it is not attenuated by the air again:
//   L = (1-F) T_w L_behind + T_air (F L_sky(R) + L_glitter + (1-F)(1-T_w) L_deep)
//       + (1 - (1-F) T_w) L_inscatter
// Where the water is thinner than SHORE_FADE_M the result fades into the seabed, so the
// shoreline is soft and the two surfaces never fight for depth.
//
// Far away the depth buffer cannot tell land from sea: both meshes are chords of the sphere
// that sag below it by (edge length)^2 / 8r between vertices (a kilometre from space), more
// than the height of a coastal plain. There the sea floor's height from the terrain's own
// height function decides (terrain/height.glsl, the continents map): the sea is pulled
// towards the camera by the sag (gl_FragDepth) so that sagging coastal land cannot hide it,
// is discarded where the terrain stands above it, and its water path comes from the depth
// below the surface. Near the camera the sag is far below a millimetre and nothing changes.
#include "common/frame_uniforms.glsl"
#include "common/constants.glsl"
#include "terrain/grid.glsl"
#include "atmosphere/definitions.glsl"
#include "atmosphere/uniforms.glsl"
#include "atmosphere/functions.glsl"
#include "atmosphere/rendering.glsl"
#include "ocean/gerstner.glsl"
#include "ocean/ocean_waves.glsl"
#include "ocean/water.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"

in vec3 tePosition;
in vec3 teDirection;
in vec3 teOffset;

layout(binding = 0) uniform sampler2D seabedDepth;      // copy of the G-buffer depth (reversed-Z)
layout(binding = 1) uniform sampler2D seabedRadiance;   // copy of the HDR target
layout(binding = 4) uniform sampler2D transmittance_texture;
layout(binding = 5) uniform sampler3D scattering_texture;
layout(binding = 6) uniform sampler3D single_mie_scattering_texture;
layout(binding = 7) uniform sampler2D irradiance_texture;

uniform bool uCameraUnderwater;  // the camera is below the mean sea surface
// Slope variance of the ripples shorter than any wave of the set (src/ocean/ocean_gpu.h:
// Cox & Munk's total for the wind less what the waves carry).
uniform float uSubgridSlopeVariance;

layout(std140, binding = 2) uniform TerrainBlock {
    TerrainShape terrainShape;
};
layout(binding = 10) uniform samplerCube uContinents;
uniform float uSeaLevel;          // m above the planet radius
uniform float uMaxWaveHeight;     // m: the sum of the amplitudes
uniform float uCoarsestEdgePixels;  // the larger of the terrain's and the ocean's target edge

layout(location = 0) out vec4 outRadiance;
layout(depth_greater) out float gl_FragDepth;  // reversed-Z: only ever moved towards the camera

const float SHORE_FADE_M = 0.5;  // water path over which the sea fades in at the shore

void main() {
    AtmosphereParameters atmosphere = atmosphereParameters();
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float surfaceDistance = length(tePosition);
    vec3 view = tePosition / surfaceDistance;  // camera -> surface
    vec3 up = normalize(teDirection);
    vec3 sun = frame.sunDirection.xyz;

    // A pixel's footprint on the sea: its size at this distance, stretched along the view by
    // 1 / cos(incidence) (the long axis, so grazing views do not alias into sparkle; what it
    // drops becomes glitter roughness).
    float pixelAngle = radiansPerPixel();
    float footprint = surfaceDistance * pixelAngle / max(abs(dot(view, up)), 0.02);
    float waterDepth = uSeaLevel - terrainHeight(up, terrainShape, uContinents);  // below the mean surface
    float slopeVariance;
    vec3 normal = oceanNormal(up, teOffset, footprint, waterDepth, slopeVariance);
    // Seen from below only when the camera is under the sea: not from gl_FrontFacing, which
    // also flips on the far side of steep crests at grazing views, where the sea is seen from above.
    if (uCameraUnderwater) normal = -normal;
    // A normal that faces away from the viewer (grazing views of steep waves) is bent back
    // just enough to face it: the reflection stays above the surface.
    float cosView = dot(normal, -view);
    if (cosView < 0.01) normal = normalize(normal + view * (cosView - 0.01));
    cosView = max(dot(normal, -view), 0.01);

    // How far the meshes may sag below the sphere here (see above), m, and what that means
    // along this ray.
    float edge = surfaceDistance * pixelAngle * uCoarsestEdgePixels;
    float sag = edge * edge / (8.0 * frame.planetCenterFromCamera.w);
    float cosIncidence = max(abs(dot(view, up)), 0.05);
    // Land: near the camera only where no crest can reach (waves may run up a beach, and the
    // depth test is exact there); where the meshes sag, wherever the terrain is above the sea.
    float farness = smoothstep(0.05, 0.5, sag);
    if (waterDepth < -uMaxWaveHeight * (1.0 - farness)) discard;
    vec3 forward = -vec3(frame.worldFromView[2]);
    float pulled = max(dot(tePosition, forward) - 2.0 * sag / cosIncidence * dot(view, forward), frame.camera.x);
    gl_FragDepth = depthFromViewDistance(pulled);

    // Water between the surface and the seabed along this pixel's ray: from the depth
    // buffer near the camera, from the depth below the surface where the meshes sag.
    float seabed = texelFetch(seabedDepth, pixel, 0).r;
    float seabedDistance = seabed > 0.0 ? viewDistanceFromDepth(seabed) / max(dot(view, forward), 1e-6) : 1e30;
    float meshPath = max(seabedDistance - surfaceDistance, 0.0);
    float depthPath = max(waterDepth, 0.0) / cosIncidence;
    float waterPath = mix(meshPath, depthPath, farness);
    vec3 behind = texelFetch(seabedRadiance, pixel, 0).rgb;

    // Air: camera and surface point in km from the planet centre (the camera's radius formed in double).
    vec3 camera = cameraFromPlanetCentreKm();
    vec3 point = camera + tePosition / M_PER_KM;
    vec3 airTransmittance;
    vec3 inscatter = GetSkyRadianceToPointAlongRay(atmosphere, transmittance_texture, scattering_texture,
                                                   single_mie_scattering_texture, camera, view,
                                                   surfaceDistance / M_PER_KM, sun, airTransmittance);

    if (uCameraUnderwater) {  // under water, looking up at the surface: the water body only
        vec3 waterTransmittance = waterTransmittanceAlong(surfaceDistance);
        vec3 skyIrradiance;
        vec3 sunIrradiance = GetSunAndSkyIrradiance(atmosphere, transmittance_texture, irradiance_texture, point, up,
                                                    sun, skyIrradiance);
        float fresnel = waterFresnel(cosView);
        outRadiance = vec4((1.0 - fresnel) * waterTransmittance * behind +
                               (1.0 - waterTransmittance) * deepWaterRadiance(sunIrradiance + skyIrradiance),
                           1.0);
        return;
    }

    float fresnel = waterFresnel(cosView);
    vec3 reflected = reflect(view, normal);
    reflected = normalize(reflected + up * max(0.0, 0.01 - dot(reflected, up)));  // keep it above the horizon
    vec3 skyTransmittance;
    vec3 sky = GetSkyRadiance(atmosphere, transmittance_texture, scattering_texture, single_mie_scattering_texture,
                              point, reflected, sun, skyTransmittance);
    vec3 skyIrradiance;
    vec3 sunIrradiance = GetSunAndSkyIrradiance(atmosphere, transmittance_texture, irradiance_texture, point, up, sun,
                                                skyIrradiance);
    // The sun's irradiance on a surface facing it: through the atmosphere, not yet weighted by a normal.
    vec3 sunAtSurface = atmosphere.solar_irradiance *
                        GetTransmittanceToSun(atmosphere, transmittance_texture, length(point), dot(point, sun) / length(point));
    vec3 glitter = dot(up, sun) > 0.0
                       ? sunAtSurface * sunGlitter(normal, -view, sun, slopeVariance + uSubgridSlopeVariance)
                       : vec3(0.0);

    vec3 waterTransmittance = waterTransmittanceAlong(waterPath);
    vec3 deep = deepWaterRadiance(sunIrradiance + skyIrradiance);
    vec3 surface = fresnel * sky + glitter + (1.0 - fresnel) * (1.0 - waterTransmittance) * deep;
    vec3 radiance = (1.0 - fresnel) * waterTransmittance * behind + airTransmittance * surface +
                    (1.0 - (1.0 - fresnel) * waterTransmittance) * inscatter;
    float coverage = smoothstep(0.0, SHORE_FADE_M, waterPath);
    outRadiance = vec4(min(mix(behind, radiance, coverage), vec3(6.0e4)), 1.0);
}
