// Under water: with the camera below the sea surface, everything it sees through the
// water body (seabed, and in the distance nothing but water) is attenuated by
// exp(-extinction * distance) and veiled by the light the water scatters, lit by the sun
// and sky through the surface above (ocean/water.glsl). The surface itself, seen from
// below, is drawn afterwards by the ocean pass.
#include "common/frame_uniforms.glsl"
#include "common/constants.glsl"
#include "atmosphere/definitions.glsl"
#include "atmosphere/uniforms.glsl"
#include "atmosphere/functions.glsl"
#include "atmosphere/rendering.glsl"
#include "ocean/water.glsl"

in vec2 vNdc;
layout(binding = 0) uniform sampler2D seabedDepth;
layout(binding = 1) uniform sampler2D seabedRadiance;
layout(binding = 4) uniform sampler2D transmittance_texture;
layout(binding = 7) uniform sampler2D irradiance_texture;
uniform float uCameraDepth;  // m below the mean sea surface, > 0

layout(location = 0) out vec4 outRadiance;

void main() {
    AtmosphereParameters atmosphere = atmosphereParameters();
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 dir = worldRayFromNdc(vNdc);
    float depth = texelFetch(seabedDepth, pixel, 0).r;
    vec3 forward = -vec3(frame.worldFromView[2]);
    float distance = depth > 0.0 ? viewDistanceFromDepth(depth) / max(dot(dir, forward), 1e-6) : 1e30;
    vec3 up = frame.cameraUp.xyz;
    vec3 surfacePoint = cameraFromPlanetCentreKm() + up * (uCameraDepth / M_PER_KM);
    vec3 skyIrradiance;
    vec3 sunIrradiance = GetSunAndSkyIrradiance(atmosphere, transmittance_texture, irradiance_texture, surfacePoint,
                                                up, frame.sunDirection.xyz, skyIrradiance);
    vec3 light = (sunIrradiance + skyIrradiance) * waterTransmittanceAlong(uCameraDepth);  // down to the camera
    vec3 transmittance = waterTransmittanceAlong(distance);
    vec3 behind = texelFetch(seabedRadiance, pixel, 0).rgb;
    outRadiance = vec4(transmittance * behind + (1.0 - transmittance) * deepWaterRadiance(light), 1.0);
}
