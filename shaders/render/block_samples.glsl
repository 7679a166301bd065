// The samples of a pass that works at one pixel of each N x N block of the frame (render/
// sample_spacing.glsl) around a frame pixel: the corners of the cell of their grid that holds it,
// clamped to the samples' last texel `last`. One, two or four distinct ones: a pixel in a row or
// column of samples has each of its two twice, a pixel on a sample has it four times (corners[0]
// == corners[3]), so a mean over the four is the bilinear weight at the pixel.
void blockSampleCorners(ivec2 pixel, int spacing, ivec2 last, out ivec2 corners[4]) {
    ivec2 low = pixel / spacing;
    ivec2 high = min((pixel + spacing - 1) / spacing, last);
    corners = ivec2[4](low, ivec2(high.x, low.y), ivec2(low.x, high.y), high);
}
