// Atmosphere precomputation, step 1: transmittance to the top boundary
// (Elek Eq. 9) for every (r, mu) texel. Writes the transmittance table.
// Driven by src/atmosphere/precompute_gpu.cpp, which follows
// computeReferenceTables() (src/atmosphere/reference_tables.cpp) step by step.
#define TRANSMITTANCE_LOG_LOOKUP true  // the precomputation reads the transmittance table in log space
#include "atmosphere/definitions.glsl"
#include "atmosphere/uniforms.glsl"
#include "atmosphere/functions.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform writeonly image2D transmittanceImage;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (texel.x >= TRANSMITTANCE_TEXTURE_WIDTH || texel.y >= TRANSMITTANCE_TEXTURE_HEIGHT) return;
    AtmosphereParameters atmosphere = atmosphereParameters();
    vec3 transmittance = ComputeTransmittanceToTopAtmosphereBoundaryTexture(atmosphere, vec2(texel) + 0.5);
    imageStore(transmittanceImage, texel, vec4(transmittance, 1.0));
}
