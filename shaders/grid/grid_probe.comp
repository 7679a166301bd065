// Grid probe: terrain/grid.glsl's inverse, gridPointOf, at a list of places on the grid (point
// indices, fractional): each place's direction (gridDirection of gridCoordinateAt, in double) mapped
// back to a place, for comparing with where it came from (tests/test_ocean_far_field.cpp).
// Input per place (std430, vec2): the place. Output per place (vec2): the place found.
#include "terrain/grid.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(location = 0) uniform int placeCount;

layout(std430, binding = BUFFER_PROBE_INPUT) readonly buffer Places {
    vec2 places[];
};
layout(std430, binding = BUFFER_PROBE_OUTPUT) writeonly buffer Found {
    vec2 found[];
};

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= placeCount) return;
    found[i] = gridPointOf(vec3(gridDirection(gridCoordinateAt(places[i]))));
}
