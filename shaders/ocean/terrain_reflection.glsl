// The terrain's reflection in the sea (Michelic §6: "screen-space reflections of the terrain";
// the search is ocean/screen_space_reflections.glsl's), searched only at the pixels where the
// ocean's light found that land may lie within the reflected ray's reach (from orbit a tenth of
// the sea; a search in the ocean's own program cost every sea pixel on a software renderer):
// ocean/sea_light.frag leaves the sky it reflected there (its sea sky reflection target, a > 0)
// and lists them (render/pixel_list.glsl) where ground above the sea is on screen (render/
// land_on_screen.glsl); then ocean/terrain_reflection.comp, one invocation per listed pixel,
// searches the terrain along the pixel's reflected ray (the ocean's sea reflection target) from
// the sea's point there, and where it finds some with confidence c replaces that share of the
// sky's reflection:
//     L += w c (L_terrain - L_sky),        w = coverage x Fresnel (the ocean's weight),
// and leaves the sky's share w (1 - c) as the weight of the clouds' change to it, which the
// sea reflection pass adds next.
#include "common/frame_uniforms.glsl"
#include "atmosphere/interface.glsl"
#include "ocean/ocean_block.glsl"
#include "ocean/screen_space_reflections.glsl"
#define PIXEL_LIST_BINDING BUFFER_TERRAIN_REFLECTION_LIST
#include "render/pixel_list.glsl"

layout(binding = UNIT_SEA_SKY_REFLECTION) uniform sampler2D seaSkyReflection;  // sky, sea distance (ocean/sea_light.frag)
