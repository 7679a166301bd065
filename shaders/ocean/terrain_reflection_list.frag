// The terrain reflection's list (ocean/terrain_reflection.glsl): the pixels where the ocean left
// the sky it reflected, because land may lie within the reflected ray's reach. A full-screen
// draw (no colour written) rather than a dispatch, so that conditional rendering skips it where
// the ocean drew nothing.
#include "ocean/terrain_reflection.glsl"

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (texelFetch(seaSkyReflection, pixel, 0).a > 0.0) listPixel(pixel);
}
