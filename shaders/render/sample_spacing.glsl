// The passes that do a costly thing at one pixel of each N x N block of the frame and spread
// it to the pixels between, with their N. Compiled as GLSL and as C++
// (src/render/render_targets.cpp sizes the samples' targets from it).

// The terrain's shadow (render/terrain_shadow.frag, read by render/surface_light.frag): N for a
// frame `frameHeight` pixels high, 2, and 4 from 720 rows up. The shadows the samples miss are
// those narrower than their spacing, features of the world, not of the pixels: 4 pixels at 720
// rows subtend what 2 do at 360. Measured (the `mountains` view at a 5 deg sun, against a march at
// every pixel, TerrainShadowRender.TheSampledShadowIsTheMarchedOneButForSlivers): 0.68 % of the
// surface pixels differ at 320x180 with 2, 0.56 % at 640x360 with 4, 0.26 % at 1280x720 with 4; the
// `ground` view's shadow passes at 1280x720 on llvmpipe 59 ms with 2, 15 with 4.
int terrainShadowSpacing(int frameHeight) { return frameHeight >= 720 ? 4 : 2; }
// A sample's value where its pixel shows no surface (below any clearance the march returns).
const float TERRAIN_SHADOW_NO_SURFACE = -1.0e30f;

// The clouds in the sea's reflection (ocean/sea_reflection.frag).
const int SEA_REFLECTION_SPACING = 2;
