// Cloud probe: the unified march of clouds and atmosphere (clouds/cloud_march.glsl,
// MarchView: the very function the sky pass runs) for a list of rays, for tests and
// `planet sky-probe` (src/clouds/cloud_probe.h). One invocation per ray.
// Input per ray (std430, 3 vec4): origin (km from the planet centre), w: distance to the
// surface point in km (<= 0: to space); unit direction; unit sun direction.
// Output per ray (2 vec4): transmittance (rgb), w: small steps; in-scattered radiance (rgb,
// the sky beyond included for rays to space), w: large steps.
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(location = 0) uniform int rayCount;

layout(std430, binding = BUFFER_PROBE_INPUT) readonly buffer ProbeRays {
    vec4 rays[];
};
layout(std430, binding = BUFFER_PROBE_OUTPUT) writeonly buffer ProbeResults {
    vec4 results[];
};

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= rayCount) return;
    ViewMarch m = MarchView(rays[3 * i].xyz, rays[3 * i + 1].xyz, rays[3 * i].w, rays[3 * i + 2].xyz, MarchQualityOf(0.5));
    results[2 * i] = vec4(m.transmittance, float(m.steps));
    results[2 * i + 1] = vec4(m.inscatter, float(m.skipped));
}
