// Sky probe: the atmosphere interface's SkyRadiance (the very function the sky pass
// calls) for a list of view rays, the GPU side of `planet sky-probe`
// (src/app/sky_probe_command.cpp). One invocation per row; rows
// [firstRow, firstRow + rowCount) per dispatch.
//
// Inputs per row (std430, 3 vec4): camera position (km, from the planet
// centre) with, in w, its altitude above the bottom radius (km, formed in double: the
// position's length in float resolves only half a metre), unit view ray, unit sun
// direction; w unused.
// Outputs per row (2 vec4): sky radiance (rgb, W m^-2 sr^-1 nm^-1: scattered
// light only, no ground, no sun disc), and the whole ray's transmittance (rgb).
#include "atmosphere/interface.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(location = 0) uniform int firstRow;
layout(location = 1) uniform int rowCount;
layout(std430, binding = BUFFER_PROBE_INPUT) readonly buffer ProbeRays {
    vec4 rays[];
};
layout(std430, binding = BUFFER_PROBE_OUTPUT) writeonly buffer ProbeResults {
    vec4 results[];
};

void main() {
    int row = firstRow + int(gl_GlobalInvocationID.x);
    if (row >= firstRow + rowCount) return;
    vec3 up = normalize(rays[3 * row].xyz);
    float altitude = rays[3 * row].w;
    vec3 view_ray = rays[3 * row + 1].xyz;
    vec3 sun_direction = rays[3 * row + 2].xyz;
    vec3 transmittance;
    vec3 radiance = SkyRadianceAt(up, altitude, view_ray, sun_direction, transmittance);
    transmittance = GetViewRayTransmittanceAt(atmosphereParameters(), transmittance_texture, up, altitude, view_ray);  // to the ground too
    results[2 * row] = vec4(radiance, 0.0);
    results[2 * row + 1] = vec4(transmittance, 0.0);
}
