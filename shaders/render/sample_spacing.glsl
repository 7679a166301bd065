// The passes that do a costly thing at one pixel of each N x N block of the frame and spread
// it to the pixels between, with their N. Compiled as GLSL and as C++
// (src/render/render_targets.cpp sizes the samples' targets from it).

// The terrain's shadow (render/terrain_shadow.frag, read by render/surface_light.frag).
const int TERRAIN_SHADOW_SPACING = 2;
// A sample's value where its pixel shows no surface (below any clearance the march returns).
const float TERRAIN_SHADOW_NO_SURFACE = -1.0e30f;

// The clouds in the sea's reflection (ocean/sea_reflection.frag).
const int SEA_REFLECTION_SPACING = 2;
