// The reflection at the ocean grid's points, between them (ocean/grid_reflection.comp forms it
// into an N x N texture, texel (i, j) the point (i, j), once per point and frame).

layout(binding = UNIT_OCEAN_GRID_REFLECTION) uniform sampler2D oceanGridReflection;

// Bilinear between the four grid points around `at`, a place on the grid in point indices
// ((i, j), fractional; ocean.tese passes it on): per pixel, so the reflection follows the grid's
// cells whatever the triangles' size (a patch of the grids' stride, src/grid/grid_stride.h, spans
// up to 8 x 8 of them, and the reflected sky changes across them at the terminator). The texture
// unit's bilinear filter: one fetch where four reads of a buffer cost a software renderer a
// tenth of the sea's fragments at orbit.
vec3 gridReflectionAt(vec2 at) {
    return textureLod(oceanGridReflection, (at + 0.5) / vec2(textureSize(oceanGridReflection, 0)), 0.0).rgb;
}
