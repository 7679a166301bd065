// Which sea pixels the terrain's screen-space reflection (ocean/screen_space_reflections.glsl) searches
// at all: apart, since the sea's mesh (ocean/ocean.frag) takes the same test to mark the open sea,
// without the search's atmosphere. Needs nothing.
#ifndef OCEAN_TERRAIN_REFLECTION_REACH_GLSL
#define OCEAN_TERRAIN_REFLECTION_REACH_GLSL

// Off (0) the sea reflects the sky and the clouds only (tests compare the two).
#define OCEAN_SCREEN_SPACE_REFLECTIONS 1
// On (1), every sea pixel is searched, land within reach or not (tests: the same image).
#define TERRAIN_REFLECTION_SEARCH_ALL 0
// Off (0), rays whose reach spans under a pixel on screen are searched too (tests compare the two).
#define TERRAIN_REFLECTION_PIXEL_REACH 1

// Whether the terrain may be reflected along a ray from the sea distanceM from the camera:
// whether the ray's reach below the highest mountain spans a pixel on screen, and land may lie within it (terrain/terrain_shadow.glsl's
// terrainReachBelowLandKm, the continents map's slope bound). A segment of length L seen from at least
// D - L away subtends at most L / (D - L) rad: under a pixel, the search could only meet the
// pixel it starts from or its neighbour (from space, 22 km pixels against a few km of reach).
// There the reflection covers at most that share of a coast pixel (the sea within reach of
// land as high as the highest peak; real coasts are lower, so far less), where a hit put it
// over the whole pixel: left out, the pixel is nearer the truth wherever that share is under
// half (tests/test_ocean_reflections.cpp: from space only coast pixels change, 0.008 % of the
// frame's luminance on average).
// `reachM`: the reflected ray's reachBelowLand (the sea's light forms it with the sun's, at once:
// terrain/terrain_shadow.glsl's terrainReachesBelowLandKm).
bool terrainMayBeReflected(float reachM, float distanceM, float pixelAngle) {
#if OCEAN_SCREEN_SPACE_REFLECTIONS
    if (TERRAIN_REFLECTION_SEARCH_ALL != 0) return true;
    if (TERRAIN_REFLECTION_PIXEL_REACH != 0 && reachM < pixelAngle * (distanceM - reachM)) return false;
    return reachM > 0.0;
#else
    return false;
#endif
}

#endif
