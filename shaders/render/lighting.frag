// Lighting / composition: G-buffer -> linear HDR radiance.
//
// For now: Lambertian ground lit by the sun at its top-of-atmosphere
// irradiance, plus a small constant ambient term that stands in for sky
// irradiance until the atmosphere pass provides it (Elek Eq. 20 replaces both).
// Pixels with no surface (space) get zero radiance.
#include "common/frame_uniforms.glsl"
#include "common/constants.glsl"

in vec2 vNdc;
layout(binding = 0) uniform sampler2D gNormal;
layout(binding = 1) uniform sampler2D gAlbedo;
layout(binding = 2) uniform sampler2D gMaterial;

layout(location = 0) out vec4 outRadiance;

const float AMBIENT_FRACTION = 0.02;  // placeholder sky light, fraction of the sun's irradiance

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int material = int(texelFetch(gMaterial, pixel, 0).r * 255.0 + 0.5);
    if (material == MATERIAL_NONE) {
        outRadiance = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 normal = normalize(texelFetch(gNormal, pixel, 0).xyz);
    vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
    vec3 irradiance = frame.sunIrradiance.rgb * (max(dot(normal, frame.sunDirection.xyz), 0.0) + AMBIENT_FRACTION);
    outRadiance = vec4(albedo / PI * irradiance, 1.0);
}
