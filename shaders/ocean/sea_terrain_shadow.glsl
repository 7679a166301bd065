// The sea's pixels whose terrain shadow is marched after the ocean pass (ocean/
// sea_terrain_shadow.comp), not in it: where land may lie within the sun ray's reach and the
// terrain shadow's samples around the pixel disagree (a shadow's edge, the shore). In the ocean's
// fragment shader the march's code ran for every sea pixel, masked, marched or not (a software
// renderer runs the first turn of a loop for every group of pixels: README "Programs, not
// branches"): at 1280x720 a sixth of the ocean pass at orbit. The ocean shades such a pixel as
// lit by the terrain and lists the point it marches from and the share of its radiance that the
// sun's light on it carries (every such term is linear in the sun's visibility: the glitter, the
// light scattered up by the water, the foam); the compute pass marches and takes away what the
// terrain's shadow hides: L = L_lit - share x (1 - v).
//
//
// The list holds at most `capacity` entries (src/render/render_targets.cpp: as many as the frame
// has pixels, 16 bytes each; the flooded valley in the range's shadow at a 5 degree sun lists a
// quarter of them); a fragment beyond it (where sea fragments overlap) takes the nearest
// sample's clearance instead (listSeaTerrainShadow returns false), as does a shore fragment
// behind the land's edge. Each entry holds the pixel,
// the sea's distance along its ray (the compute pass marches from there, and marches only where
// the surface distance is still that: the fragment was not hidden by a later one) and the sun's
// share. Its header is the indirect dispatch's group counts, as render/pixel_list.glsl's;
// RenderTargets::clearSeaTerrainShadowList resets it before the ocean.
const uint SEA_TERRAIN_SHADOW_GROUP_SIZE = 64u;

layout(std430, binding = BUFFER_SEA_TERRAIN_SHADOW_LIST) buffer SeaTerrainShadowList {
    uint groupsX;
    uint groupsY;
    uint groupsZ;
    uint count;     // pixels that asked, beyond the capacity too
    uint capacity;  // entries the buffer holds
    uint unused0;
    uint unused1;
    uint unused2;
    uvec4 entries[];  // x | y << 16; the sea's distance, m (float bits); the sun's share (half floats)
} seaTerrainShadowList;

bool listSeaTerrainShadow(ivec2 pixel, float seaDistanceM, vec3 sunShare) {
    uint i = atomicAdd(seaTerrainShadowList.count, 1u);
    if (i >= seaTerrainShadowList.capacity) return false;
    seaTerrainShadowList.entries[i] = uvec4(uint(pixel.x) | (uint(pixel.y) << 16), floatBitsToUint(seaDistanceM),
                                            packHalf2x16(sunShare.rg), packHalf2x16(vec2(sunShare.b, 0.0)));
    if (i % SEA_TERRAIN_SHADOW_GROUP_SIZE == 0u) atomicAdd(seaTerrainShadowList.groupsX, 1u);  // the first of a new group
    return true;
}
