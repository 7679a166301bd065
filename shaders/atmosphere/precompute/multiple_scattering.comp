// Atmosphere precomputation, order k step c: radiance of order k, the
// scattering density integrated along the view ray (Elek Eq. 13). Writes
// delta multiple (phase included) and adds it, divided by the Rayleigh phase,
// to the phase-free scattering table. Dispatched a group of r layers at a time.
#define TRANSMITTANCE_LOG_LOOKUP true  // the precomputation reads the transmittance table in log space
#include "atmosphere/definitions.glsl"
#include "atmosphere/uniforms.glsl"
#include "atmosphere/functions.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(location = 0) uniform int layerOffset;
layout(binding = 0) uniform sampler2D transmittanceTable;
layout(binding = 5) uniform sampler3D deltaDensityTable;
layout(binding = 0, rgba32f) uniform writeonly image3D deltaMultipleImage;
layout(binding = 1, rgba32f) uniform image3D scatteringImage;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, layerOffset);
    if (texel.x >= SCATTERING_TEXTURE_NU_SIZE * SCATTERING_TEXTURE_MU_S_SIZE ||
        texel.y >= SCATTERING_TEXTURE_MU_SIZE || texel.z >= SCATTERING_TEXTURE_R_SIZE) return;
    AtmosphereParameters atmosphere = atmosphereParameters();
    float nu;
    vec3 radiance = ComputeMultipleScatteringTexture(atmosphere, transmittanceTable, deltaDensityTable,
                                                     vec3(texel) + 0.5, nu);
    imageStore(deltaMultipleImage, texel, vec4(radiance, 1.0));
    imageStore(scatteringImage, texel,
               imageLoad(scatteringImage, texel) + vec4(radiance / RayleighPhaseFunction(nu), 0.0));
}
