// Lighting and aerial perspective: G-buffer -> linear HDR radiance, applied as
// one post-process over the G-buffer (Sperlhofer ch. 4.6.2), so every surface
// written to it is lit the same way.
//
// Surface: albedo / pi * (sun through the atmosphere + sky irradiance)
// (Elek Eq. 17, 20; Sperlhofer Eq. 2-13), attenuated by the transmittance to
// the camera and plus the light scattered in between (Sperlhofer Eq. 4-18).
// Sky: radiance scattered along the view ray (Sperlhofer Eq. 2-16) plus the
// sun disc with limb darkening, seen through the atmosphere (Elek §4.2.2).
// In-scattering comes from Bruneton's 4D table or, in the variant compiled with
// ELEK_TABLE 1 (preset atmosphere.elek_3d_table), from Elek's 3D table
// (elek_table.glsl); transmittance and irradiance are shared. Two programs
// rather than a run-time branch: software renderers execute both sides of
// even a uniform branch, and a GPU is spared the registers of the unused one.
#include "common/frame_uniforms.glsl"
#include "common/constants.glsl"
#include "common/gbuffer.glsl"
#include "atmosphere/definitions.glsl"
#include "atmosphere/uniforms.glsl"
#include "atmosphere/functions.glsl"
#include "atmosphere/rendering.glsl"
#include "atmosphere/elek_table.glsl"

in vec2 vNdc;
layout(binding = 0) uniform sampler2D gNormal;
layout(binding = 1) uniform sampler2D gAlbedo;
layout(binding = 2) uniform sampler2D gMaterial;
layout(binding = 3) uniform sampler2D gDepth;
layout(binding = 4) uniform sampler2D transmittance_texture;
layout(binding = 5) uniform sampler3D scattering_texture;
layout(binding = 6) uniform sampler3D single_mie_scattering_texture;
layout(binding = 7) uniform sampler2D irradiance_texture;
layout(binding = 8) uniform sampler3D elek_scattering_texture;
layout(binding = 9) uniform sampler3D elek_single_mie_scattering_texture;

layout(location = 0) out vec4 outRadiance;

const float LIMB_DARKENING_U = 0.6;
const float MAX_HDR_RADIANCE = 6.0e4;  // below the largest half float (65504)  // linear law I(mu) = 1 - u (1 - mu), visible light

// Sun disc radiance towards `dir`, before the atmosphere. Normalised so the
// disc delivers the solar irradiance: the mean of the linear law over the disc
// is 1 - u / 3. Angles from |dir x sun| stay precise for a 0.27 deg disc.
vec3 sunDiscRadiance(vec3 dir, vec3 sun, float angularRadius, vec3 irradiance) {
    if (dot(dir, sun) <= 0.0) return vec3(0.0);
    float angle = asin(min(length(cross(dir, sun)), 1.0));
    if (angle >= angularRadius) return vec3(0.0);
    float x = angle / angularRadius;
    float mu = sqrt(1.0 - x * x);
    float discSolidAngle = PI * angularRadius * angularRadius;
    vec3 radiance = irradiance / discSolidAngle * (1.0 - LIMB_DARKENING_U * (1.0 - mu)) / (1.0 - LIMB_DARKENING_U / 3.0);
    return min(radiance, vec3(MAX_HDR_RADIANCE));  // a tiny disc must not overflow the RGBA16F target
}

void main() {
    AtmosphereParameters atmosphere = atmosphereParameters();
    const bool elek = ELEK_TABLE != 0;
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 dir = worldRayFromNdc(vNdc);
    vec3 sun = frame.sunDirection.xyz;
    // Camera relative to the planet centre in km, from the altitude formed in double.
    vec3 camera = cameraFromPlanetCentreKm();
    vec3 transmittance;

    int material = int(texelFetch(gMaterial, pixel, 0).r * 255.0 + 0.5);
    if (material == MATERIAL_NONE) {
        vec3 sky = elek ? GetSkyRadianceElek(atmosphere, transmittance_texture, elek_scattering_texture,
                                             elek_single_mie_scattering_texture, camera, dir, sun, transmittance)
                        : GetSkyRadiance(atmosphere, transmittance_texture, scattering_texture,
                                         single_mie_scattering_texture, camera, dir, sun, transmittance);
        vec3 disc = sunDiscRadiance(dir, sun, frame.sunDirection.w, atmosphere.solar_irradiance);
        outRadiance = vec4(sky + transmittance * disc, 1.0);
        return;
    }

    // Distance to the surface along this pixel's ray, from the reversed-Z depth.
    float viewDistance = viewDistanceFromDepth(texelFetch(gDepth, pixel, 0).r);
    vec3 forward = -vec3(frame.worldFromView[2]);
    float rayDistanceKm = viewDistance / max(dot(dir, forward), 1e-6) / M_PER_KM;
    vec3 point = camera + dir * rayDistanceKm;

    vec3 normal = normalize(texelFetch(gNormal, pixel, 0).xyz);
    vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
    vec3 skyIrradiance;
    vec3 sunIrradiance = GetSunAndSkyIrradiance(atmosphere, transmittance_texture, irradiance_texture, point, normal,
                                                sun, skyIrradiance);
    vec3 surface = albedo / PI * (sunIrradiance + skyIrradiance);
    vec3 inscatter =
        elek ? GetSkyRadianceToPointAlongRayElek(atmosphere, transmittance_texture, elek_scattering_texture,
                                                 elek_single_mie_scattering_texture, camera, dir, rayDistanceKm, sun,
                                                 transmittance)
             : GetSkyRadianceToPointAlongRay(atmosphere, transmittance_texture, scattering_texture,
                                             single_mie_scattering_texture, camera, dir, rayDistanceKm, sun,
                                             transmittance);
    outRadiance = vec4(surface * transmittance + inscatter, 1.0);
}
