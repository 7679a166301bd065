// Atmosphere precomputation, order k step b: sky irradiance on the ground
// from the radiance of order k - 1 (Elek Eq. 16). Writes delta irradiance and
// adds it to the accumulated irradiance table. scatteringOrder is k - 1.
#define TRANSMITTANCE_LOG_LOOKUP true  // the precomputation reads the transmittance table in log space
#include "atmosphere/definitions.glsl"
#include "atmosphere/uniforms.glsl"
#include "atmosphere/functions.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(location = 1) uniform int scatteringOrder;
layout(binding = 1) uniform sampler3D deltaRayleighTable;
layout(binding = 2) uniform sampler3D deltaMieTable;
layout(binding = 3) uniform sampler3D deltaMultipleTable;
layout(binding = 0, rgba32f) uniform writeonly image2D deltaIrradianceImage;
layout(binding = 1, rgba32f) uniform image2D irradianceImage;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (texel.x >= IRRADIANCE_TEXTURE_WIDTH || texel.y >= IRRADIANCE_TEXTURE_HEIGHT) return;
    AtmosphereParameters atmosphere = atmosphereParameters();
    vec3 irradiance = ComputeIndirectIrradianceTexture(atmosphere, deltaRayleighTable, deltaMieTable,
                                                       deltaMultipleTable, vec2(texel) + 0.5, scatteringOrder);
    imageStore(deltaIrradianceImage, texel, vec4(irradiance, 1.0));
    imageStore(irradianceImage, texel, imageLoad(irradianceImage, texel) + vec4(irradiance, 0.0));
}
