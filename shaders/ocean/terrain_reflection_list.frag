// The terrain reflection's list (ocean/terrain_reflection.glsl): the pixels where the ocean left
// the sky it reflected, because land may lie within the reflected ray's reach. A draw over the
// ground sphere's rectangle (src/render/renderer.cpp; no colour written) rather than a
// dispatch, so that conditional rendering skips it where the ocean drew nothing, or where no
// land is on screen: with TERRAIN_REFLECTION_LAND_SEEN 1 the same draw, counted by an
// any-samples query, keeps only the pixels that show ground above the sea, the only thing the
// search can find (a reflected ray rises from the sea, in front of the floor below it). On the
// open sea, where nearly every ray's reach has land within the slope bound somewhere, that is
// what spares the search.
#include "ocean/terrain_reflection.glsl"

#ifndef TERRAIN_REFLECTION_LAND_SEEN
#define TERRAIN_REFLECTION_LAND_SEEN 0
#endif

layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gNormal;        // w: the ground's height, m
layout(binding = UNIT_SEABED_DEPTH) uniform sampler2D seabedDepth;      // the G-buffer depth before the sea

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
#if TERRAIN_REFLECTION_LAND_SEEN
    bool land = texelFetch(seabedDepth, pixel, 0).r > 0.0 && texelFetch(gNormal, pixel, 0).w > ocean.seaLevel;
    if (!land && TERRAIN_REFLECTION_SEARCH_ALL == 0) discard;
#else
    if (texelFetch(seaSkyReflection, pixel, 0).a > 0.0) listPixel(pixel);
#endif
}
