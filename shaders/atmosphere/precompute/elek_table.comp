// Atmosphere precomputation, last (optional) step: Elek's 3D table (Elek
// §4.1.1, shaders/atmosphere/elek_table.glsl) from the finished 4D scattering
// and single Mie tables, looked up at azimuth omega = 0. Phase-free, like the
// 4D tables. Dispatched a group of r layers at a time, starting at layerOffset.
#define TRANSMITTANCE_LOG_LOOKUP true  // the precomputation reads the transmittance table in log space
#include "atmosphere/definitions.glsl"
#include "atmosphere/uniforms.glsl"
#include "atmosphere/functions.glsl"
#include "atmosphere/elek_table.glsl"
#include "atmosphere/rendering.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(location = 0) uniform int layerOffset;
layout(binding = 1) uniform sampler3D scatteringTable;
layout(binding = 2) uniform sampler3D singleMieTable;
layout(binding = 0, rgba32f) uniform writeonly image3D elekScatteringImage;
layout(binding = 1, rgba32f) uniform writeonly image3D elekSingleMieImage;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, layerOffset);
    if (texel.x >= ELEK_TEXTURE_MU_S_SIZE || texel.y >= ELEK_TEXTURE_MU_SIZE || texel.z >= ELEK_TEXTURE_R_SIZE) return;
    AtmosphereParameters atmosphere = atmosphereParameters();
    vec3 mie;
    vec3 scattering = ComputeElekTableTexture(atmosphere, scatteringTable, singleMieTable, vec3(texel) + 0.5, mie);
    imageStore(elekScatteringImage, texel, vec4(scattering, 1.0));
    imageStore(elekSingleMieImage, texel, vec4(mie, 1.0));
}
