// Atmosphere precomputation, order k step a: scattering density of order k
// (Elek Eq. 12) from the radiance of order k - 1 (delta Rayleigh and Mie for
// k = 2, delta multiple otherwise) and the ground's delta irradiance.
// Writes delta scattering density. Dispatched a group of r layers at a time.
#define TRANSMITTANCE_LOG_LOOKUP true  // the precomputation reads the transmittance table in log space
#include "atmosphere/definitions.glsl"
#include "atmosphere/uniforms.glsl"
#include "atmosphere/functions.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(location = 0) uniform int layerOffset;
layout(location = 1) uniform int scatteringOrder;
layout(binding = 0) uniform sampler2D transmittanceTable;
layout(binding = 1) uniform sampler3D deltaRayleighTable;
layout(binding = 2) uniform sampler3D deltaMieTable;
layout(binding = 3) uniform sampler3D deltaMultipleTable;
layout(binding = 4) uniform sampler2D deltaIrradianceTable;
layout(binding = 0, rgba32f) uniform writeonly image3D deltaDensityImage;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, layerOffset);
    if (texel.x >= SCATTERING_TEXTURE_NU_SIZE * SCATTERING_TEXTURE_MU_S_SIZE ||
        texel.y >= SCATTERING_TEXTURE_MU_SIZE || texel.z >= SCATTERING_TEXTURE_R_SIZE) return;
    AtmosphereParameters atmosphere = atmosphereParameters();
    vec3 density = ComputeScatteringDensityTexture(atmosphere, transmittanceTable, deltaRayleighTable, deltaMieTable,
                                                   deltaMultipleTable, deltaIrradianceTable, vec3(texel) + 0.5,
                                                   scatteringOrder);
    imageStore(deltaDensityImage, texel, vec4(density, 1.0));
}
