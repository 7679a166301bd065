// The pixels the temporal reconstruction (render/sky_temporal.frag) marks as beyond what its
// samples and history can rebuild, listed densely for the refine pass (render/sky_refine.comp),
// which marches each again at full rate: one invocation per listed pixel, packed densely
// wherever the marks lie, and none in a still frame, which lists nothing. The header is the indirect dispatch's
// group counts (glDispatchComputeIndirect reads them from offset 0), kept equal to
// ceil(count / REFINE_GROUP_SIZE) as pixels are added; src/render/renderer.cpp resets it to
// (0, 1, 1), count 0, before the reconstruction.
const uint REFINE_GROUP_SIZE = 64u;

layout(std430, binding = BUFFER_SKY_REFINE) buffer SkyRefineList {
    uint groupsX;
    uint groupsY;
    uint groupsZ;
    uint count;
    uint pixels[];  // x | y << 16
} refineList;

void listForRefine(ivec2 pixel) {
    uint i = atomicAdd(refineList.count, 1u);
    refineList.pixels[i] = uint(pixel.x) | (uint(pixel.y) << 16);
    if (i % REFINE_GROUP_SIZE == 0u) atomicAdd(refineList.groupsX, 1u);  // the first of a new group
}

ivec2 listedPixel(uint i) {
    uint p = refineList.pixels[i];
    return ivec2(p & 0xffffu, p >> 16);
}
