// Atmosphere precomputation, step 3: single scattering (Elek Eq. 10), phase
// free, for every texel of the 4D table packed in 3D. Writes delta Rayleigh,
// delta Mie, the scattering table (rgb: Rayleigh, a: Mie red, Bruneton's
// combined layout) and the single Mie table. Dispatched a group of r layers
// at a time, starting at layerOffset.
#define TRANSMITTANCE_LOG_LOOKUP true  // the precomputation reads the transmittance table in log space
#include "atmosphere/definitions.glsl"
#include "atmosphere/uniforms.glsl"
#include "atmosphere/functions.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(location = 0) uniform int layerOffset;
layout(binding = 0) uniform sampler2D transmittanceTable;
layout(binding = 0, rgba32f) uniform writeonly image3D deltaRayleighImage;
layout(binding = 1, rgba32f) uniform writeonly image3D deltaMieImage;
layout(binding = 2, rgba32f) uniform writeonly image3D scatteringImage;
layout(binding = 3, rgba32f) uniform writeonly image3D singleMieImage;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, layerOffset);
    if (texel.x >= SCATTERING_TEXTURE_NU_SIZE * SCATTERING_TEXTURE_MU_S_SIZE ||
        texel.y >= SCATTERING_TEXTURE_MU_SIZE || texel.z >= SCATTERING_TEXTURE_R_SIZE) return;
    AtmosphereParameters atmosphere = atmosphereParameters();
    vec3 rayleigh;
    vec3 mie;
    ComputeSingleScatteringTexture(atmosphere, transmittanceTable, vec3(texel) + 0.5, rayleigh, mie);
    imageStore(deltaRayleighImage, texel, vec4(rayleigh, 1.0));
    imageStore(deltaMieImage, texel, vec4(mie, 1.0));
    imageStore(scatteringImage, texel, vec4(rayleigh, mie.r));
    imageStore(singleMieImage, texel, vec4(mie, 1.0));
}
