// A list of pixels for a compute pass that works on those alone: the fragments of a pass
// list the pixels it could not finish (listPixel), and the compute pass runs one invocation
// per listed pixel (listedPixel), dispatched indirectly with as many groups as the list needs,
// so that a software renderer pays for the listed pixels, packed densely wherever they lie,
// and nothing when none is listed. The header is the indirect dispatch's group counts
// (glDispatchComputeIndirect reads them from offset 0), kept equal to
// ceil(count / PIXEL_LIST_GROUP_SIZE) as pixels are added; src/render/render_targets.cpp
// resets it to (0, 1, 1), count 0, before the listing pass (RenderTargets::clearPixelList).
// Its users: the sky's refine (render/sky_temporal.frag lists, render/sky_refine.comp marches;
// BUFFER_SKY_REFINE) and the sea's reflection (ocean/sea_reflection.frag lists, ocean/
// sea_reflection.comp marches; BUFFER_SEA_REFLECTION_LIST) and the terrain's reflection in the
// sea (ocean/sea_light.frag lists, ocean/terrain_reflection.comp searches;
// BUFFER_TERRAIN_REFLECTION_LIST). Define PIXEL_LIST_BINDING first.
const uint PIXEL_LIST_GROUP_SIZE = 64u;

layout(std430, binding = PIXEL_LIST_BINDING) buffer PixelList {
    uint groupsX;
    uint groupsY;
    uint groupsZ;
    uint count;
    uint pixels[];  // x | y << 16
} pixelList;

// With two flags (bits 30 and 31 of the entry: y stays under 16384) for what the compute pass is
// to do there (render/terrain_shadow_sample_marches.comp: which of two marches).
void listPixelWithFlags(ivec2 pixel, uint flags) {
    uint i = atomicAdd(pixelList.count, 1u);
    pixelList.pixels[i] = uint(pixel.x) | (uint(pixel.y) << 16) | (flags << 30);
    if (i % PIXEL_LIST_GROUP_SIZE == 0u) atomicAdd(pixelList.groupsX, 1u);  // the first of a new group
}
void listPixel(ivec2 pixel) { listPixelWithFlags(pixel, 0u); }

ivec2 listedPixel(uint i) {
    uint p = pixelList.pixels[i];
    return ivec2(p & 0xffffu, (p >> 16) & 0x3fffu);
}
uint listedFlags(uint i) { return pixelList.pixels[i] >> 30; }
