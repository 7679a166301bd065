// The terrain's shadow at a sparse set of pixels: the march's clearance angle (rad; the sun's
// disc is whole at its angular radius and above, hidden at minus that: terrain/terrain_shadow.glsl)
// at the G-buffer's surface point of one pixel of each TERRAIN_SHADOW_SPACING-square block, the
// block's corner; TERRAIN_SHADOW_NO_SURFACE where the pixel shows none. The surface light reads
// these at the pixels around its own and marches only where they do not all say the same,
// clearly lit or fully shadowed (its terrainVisibility): the march is the surface light's main
// cost at a low sun or at ground level, and most of a frame is wholly lit or wholly in shadow.
// The sea floor's dark depths (ocean/water.glsl's SEA_FLOOR_DARK_DEPTH_M), which the surface
// light does not light, are not marched either: TERRAIN_SHADOW_NO_SURFACE there, so that a
// shallower pixel beside them marches its own.
#include "common/frame_uniforms.glsl"
#include "common/gbuffer.glsl"
#define SUN_VISIBILITY_TERRAIN 1
#include "atmosphere/interface.glsl"
#include "render/sample_spacing.glsl"
#include "ocean/water.glsl"

layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gDepth;
#include "render/surface_point.glsl"

layout(location = 0) out float outClearance;

void main() {
    SurfacePoint s;
    outClearance = TERRAIN_SHADOW_NO_SURFACE;
    // A loop of one turn or none rather than an if: a software renderer runs both sides of an
    // if, but skips a loop that none of its pixels enters (the sky's).
    bool surface = surfacePointAt(ivec2(gl_FragCoord.xy) * TERRAIN_SHADOW_SPACING, s);
    int marches = surface && depthBelowSea(s) < SEA_FLOOR_DARK_DEPTH_M ? 1 : 0;
    for (int i = 0; i < marches; ++i) outClearance = TerrainShadowClearance(s.point, frame.sunDirection);
}
