// The pixels whose terrain shadow is marched after the pass that shades them (render/
// terrain_shadow_list.comp), not in it: where the terrain shadow's samples around the pixel
// disagree (a shadow's edge, the shore) and, at sea, land may lie within the sun ray's reach.
// In the pass's own program the march's code ran for every pixel, masked, marched or not (a
// software renderer runs the first turn of a loop for every group of pixels: README "Programs,
// not branches"): at 1280x720 a sixth of the ocean pass at orbit, a quarter of the surface light
// on the `ground` view. Two passes list, each into the list cleared before it and marched right
// after it (the ground's before the ocean copies the radiance it sees through the water):
//   the surface light (render/surface_light.frag), the ground's pixels, marched from the ground
//     (the program built with TERRAIN_SHADOW_LIST_GROUND 1);
//   the sea's light (ocean/sea_light.frag), the sea's pixels, marched from sea level.
// A pass lists a pixel with its distance along its ray and the share of its radiance that the
// sun's light on it carries (every such term is linear in the sun's visibility v: the ground's
// direct sun; the glitter, the light scattered up by the water, the foam), and keeps its lit
// radiance, or where the share is most of it the rest (the radiance less the share); the compute
// pass marches from the pixel's point and takes share x (1 - v) away from the lit radiance, or
// adds share x v to the rest. Either way a pixel the march finds at the kept side (lit; in full
// shadow) is the value the pass would have written.
//
// The list holds at most `capacity` entries (src/render/render_targets.cpp: as many as the frame
// has pixels, 16 bytes each; the flooded valley in the range's shadow at a 5 degree sun lists a
// fifth of them; each pass runs once per pixel, so it lists each at most once). A pixel beyond it
// takes the samples' mean visibility instead (listTerrainShadow returns false), as does a shore
// pixel behind the land's edge. The compute pass marches only where the pixel's surface distance
// is still the listed one (a safeguard: nothing draws over a pass's pixels before it). Its header
// is the indirect dispatch's group counts, as render/pixel_list.glsl's;
// RenderTargets::clearTerrainShadowList resets it before each listing pass.
const uint TERRAIN_SHADOW_LIST_GROUP_SIZE = 64u;

layout(std430, binding = BUFFER_TERRAIN_SHADOW_LIST) buffer TerrainShadowList {
    uint groupsX;
    uint groupsY;
    uint groupsZ;
    uint count;     // pixels that asked, beyond the capacity too
    uint capacity;  // entries the buffer holds
    uint unused0;
    uint unused1;
    uint unused2;
    uvec4 entries[];  // x | y << 16; the sea's distance, m (float bits); the sun's share (packSunShare)
} terrainShadowList;

// The sun's share (three floats >= 0) in 64 bits: each float's top 21 bits (its exponent and 13 bits
// of mantissa, rounded: 1.2e-4 relative; half floats' 4.9e-4 made a lit pixel's radiance differ
// from the march in place by over 1e-3 at 2 % of the flooded valley's pixels).
uint sunShareBits(float x) { return min((floatBitsToUint(max(x, 0.0)) + 0x200u) >> 10, 0x1fffffu); }
float sunShareValue(uint bits) { return uintBitsToFloat((bits & 0x1fffffu) << 10); }
uvec2 packSunShare(vec3 share) {
    uint r = sunShareBits(share.r), g = sunShareBits(share.g), b = sunShareBits(share.b);
    return uvec2(r | (g << 21), (g >> 11) | (b << 10));
}
vec3 unpackSunShare(uvec2 bits) {
    return vec3(sunShareValue(bits.x), sunShareValue((bits.x >> 21) | (bits.y << 11)), sunShareValue((bits.y >> 10) & 0x1fffffu));
}

// `keptRest`: the pixel keeps the radiance less the sun's share (the march adds share x v), else the
// lit radiance (the march takes share x (1 - v) away); in the entry's top bit.
bool listTerrainShadow(ivec2 pixel, float seaDistanceM, vec3 sunShare, bool keptRest) {
    uint i = atomicAdd(terrainShadowList.count, 1u);
    if (i >= terrainShadowList.capacity) return false;
    uvec2 share = packSunShare(sunShare);
    terrainShadowList.entries[i] = uvec4(uint(pixel.x) | (uint(pixel.y) << 16), floatBitsToUint(seaDistanceM),
                                            share.x, share.y | (keptRest ? 0x80000000u : 0u));
    if (i % TERRAIN_SHADOW_LIST_GROUP_SIZE == 0u) atomicAdd(terrainShadowList.groupsX, 1u);  // the first of a new group
    return true;
}
