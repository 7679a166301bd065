// Atmosphere precomputation, step 2: direct sun irradiance on the ground
// for every (mu_s, r) texel. Writes delta irradiance only: the accumulated
// irradiance table holds sky light, the direct sun is added at render time.
#define TRANSMITTANCE_LOG_LOOKUP true  // the precomputation reads the transmittance table in log space
#include "atmosphere/definitions.glsl"
#include "atmosphere/uniforms.glsl"
#include "atmosphere/functions.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0) uniform sampler2D transmittanceTable;
layout(binding = 0, rgba32f) uniform writeonly image2D deltaIrradianceImage;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (texel.x >= IRRADIANCE_TEXTURE_WIDTH || texel.y >= IRRADIANCE_TEXTURE_HEIGHT) return;
    AtmosphereParameters atmosphere = atmosphereParameters();
    vec3 irradiance = ComputeDirectIrradianceTexture(atmosphere, transmittanceTable, vec2(texel) + 0.5);
    imageStore(deltaIrradianceImage, texel, vec4(irradiance, 1.0));
}
