// The reduced-rate march's pattern (render/sky_sparse.frag traces, render/sky_temporal.frag
// reconstructs): each frame traces one pixel of every 4x4 block of the frame, the same one in
// every block, stepping through the block in a fixed permutation (Bayer's ordered-dither
// order, so that any run of frames spreads its pixels over the block) and covering it in 16
// frames. Include after common/frame_uniforms.glsl.
#include "render/gradient_noise.glsl"
const int SPARSE_BLOCK = 4;   // pixels per side of a block
const int SPARSE_CYCLE = 16;  // frames until every pixel of a block has been traced

ivec2 sparseOffset(int frameIndex) {
    const int order[16] = int[16](0, 10, 2, 8, 5, 15, 7, 13, 1, 11, 3, 9, 4, 14, 6, 12);
    int i = order[frameIndex % SPARSE_CYCLE];
    return ivec2(i % SPARSE_BLOCK, i / SPARSE_BLOCK);
}

// The pixel block `block` traces this frame (clamped into the frame on its right and top
// edges, where a block sticks out).
ivec2 sparseTracedPixel(ivec2 block) {
    return min(block * SPARSE_BLOCK + sparseOffset(frame.frameIndex), ivec2(frame.viewportSize) - 1);
}

// Where in each step the traced pixel of `block` samples, in [0, 1): interleaved gradient
// noise over the blocks (render/sky_air.glsl; on the block lattice, where its pattern is the
// intended one: evaluated at the traced pixels, four apart, it aliases into diagonal bands that
// show in dense cloud), moved by the golden ratio every frame (Roberts' R1), so the 16 pixels
// of a block, traced in 16 frames, sample 16 well-spread depths, and each pixel's visits differ.
float sparseJitter(ivec2 block) {
    return fract(interleavedGradientNoise(block) + 0.6180339887 * float(frame.frameIndex % 4096));
}
