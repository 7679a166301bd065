// The terrain shadow's samples (render/terrain_shadow.frag): one pixel of each
// TERRAIN_SHADOW_SPACING x TERRAIN_SHADOW_SPACING block of the frame. Compiled as GLSL and
// as C++ (src/render/render_targets.cpp sizes the samples' target from it).
const int TERRAIN_SHADOW_SPACING = 2;
// A sample's value where its pixel shows no surface (below any clearance the march returns).
const float TERRAIN_SHADOW_NO_SURFACE = -1.0e30f;
