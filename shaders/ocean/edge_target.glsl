// The ocean mesh's edge target on screen, px, at a distance from the camera. Include after
// common/frame_uniforms.glsl and ocean/ocean_block.glsl.
//
// Where even the highest crest cannot show (ocean.maxWaveHeight, the sum of the amplitudes, and
// as much again sideways, under WAVE_VISIBLE_PIXELS on screen at the edge's nearer end), the
// mesh only has to follow the sphere, and the edge aims at up to OCEAN_FAR_EDGE_FACTOR times
// ocean.targetEdgePixels (continuously: the factor grows with the distance from where the waves
// fall under a quarter of a pixel). The normals, and so the light, come from the fragments' own
// waves (ocean/sea_light.frag); a sphere's chord of 32 pixels at the limb from 400 km sags 0.03 pixel.
// A software renderer shades a 4x4 block of pixels for each triangle that touches it, so 8-pixel
// triangles cost it about three blocks' pixels for one triangle's (orbit, 1280x720: the ocean's
// fragments 158 -> 109 ms with 24-pixel triangles). ocean.tesc aims each edge at the target of
// its nearer end; ocean.frag bounds its mesh's sag by the target at its own distance (no nearer
// than the edge's nearer end, so no smaller).
#include "grid/constants.glsl"  // WAVE_VISIBLE_PIXELS, OCEAN_FAR_EDGE_FACTOR
float oceanEdgeTargetPixels(float distanceM) {
    float wavePixels = 2.0 * ocean.maxWaveHeight / distanceM / radiansPerPixel();
    return ocean.targetEdgePixels * clamp(WAVE_VISIBLE_PIXELS / max(wavePixels, 1e-9), 1.0, OCEAN_FAR_EDGE_FACTOR);
}
