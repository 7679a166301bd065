// Marks in the stencil the pixels whose ray meets no cloud: a ray that never enters the cloud layer
// (from under it, one whose surface point is under its bottom too: the chord between two points
// inside the bottom sphere stays inside it; from above it, one whose closest approach to the
// planet's centre, up to its surface point or into space, stays above its top), or one that crosses
// it only within the clear sky around the camera (the CPU's uClearAxisKm, Renderer::clearAxisKm:
// within that distance of the vertical through the camera the weather's coverage is 0, so no cloud
// lies there in any frame: the weather map stands, only the volume moves with the wind, and coverage
// 0 leaves it no density) or only within the clear sky around where it enters the layer (the clear
// sky map there). Discards the others; writes no colour. Two uses
// (src/render/renderer.cpp):
//  - the sky march (SPARSE_LATTICE: a pixel of the reduced-rate lattice, the ray of its block's traced
//    pixel, as render/sky_sparse.frag forms it): such a ray's march is one lookup of the air, exactly
//    what the program without the clouds' code (CLOUDS_OFF) computes, which marches those pixels
//    (Renderer::drawSkyMarch; a software renderer runs the clouds' code for every pixel, masked: the
//    `ground` view's march, no cloud in sight, 36 -> 5 ms with none of it; docs/PERFORMANCE.md,
//    twenty-fifth);
//  - the reconstruction in a frame where only the clock ran (the camera and the sun stood): the clock
//    moved nothing such a ray sees (the wind moves only the clouds; the air in the layer is the
//    atmosphere's lookups, which no cloud shades; the surface's own radiance is this frame's, the sea's
//    waves too), so render/sky_temporal.frag's still program rebuilds those pixels, the general one the
//    rest (Renderer::drawSkyTemporalSplit; the `ground` view with the explorer's clock on: the general
//    reconstruction over every pixel cost 124 ms, 81-90 with the meadow split off, twenty-third; its
//    clear sky split off too, 95 -> 47 ms, twenty-fifth).
#include "common/frame_uniforms.glsl"
#include "atmosphere/definitions.glsl"  // Length, Number: cloud_model.glsl's types
#include "clouds/cloud_model.glsl"
#include "clouds/cloud_block.glsl"
#include "clouds/cloud_density.glsl"  // CloudClearDistance
#ifdef SPARSE_LATTICE
#include "render/sparse_pattern.glsl"
#endif

#ifndef SPARSE_LATTICE
in vec2 vNdc;
#endif
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;

// km: room for the float the points are formed in (the shell is widened by it).
const float NO_CLOUD_MARGIN_KM = 0.01;
// km from the vertical through the camera within which the layer holds no cloud (0: none).
layout(location = 0) uniform float uClearAxisKm;

// Whether the part [from, to] (km) of the ray from `camera` along `dir` lies in the clear sky around
// where it enters the layer: the clear sky map's chord there (clouds/cloud_density.glsl's
// CloudClearDistance: no cloud within it, along any straight way through the layer) is longer than the
// part. (Its directions run along one great circle away from the entry's, so none is farther from it
// than the part's end.)
bool partInClearSky(vec3 camera, vec3 dir, vec2 part) {
    return part.y - part.x < CloudClearDistance(normalize(camera + dir * part.x), 0.0) - NO_CLOUD_MARGIN_KM;
}

// Whether the ray from `camera` (km from the planet centre) along `dir` to its surface point
// (`distanceM` m away; 0: none, into space) meets no cloud: it has no part inside the cloud layer
// (the march's own intervals, clouds/cloud_model.glsl's CloudLayerIntervals, on the shell widened by
// the margin, so a pixel marked here is one the march would have found no layer for); or its parts
// there end within uClearAxisKm of the camera's vertical (a ray leaves that axis as it goes, by
// sin(its angle from the vertical) a km: its farthest point in the layer is its last); or each part
// lies in the clear sky around where it enters (from orbit, the clear sea between the clouds).
bool rayMeetsNoCloud(vec3 camera, vec3 dir, float distanceM) {
    float r = length(camera);
    float toEnd = distanceM > 0.0 ? distanceM / M_PER_KM : 1.0e30;  // km
    vec2 first;
    vec2 second;
    int crossings = CloudLayerIntervals(r, dot(camera, dir) / r, toEnd, clouds.bottomRadius - NO_CLOUD_MARGIN_KM,
                                        clouds.topRadius + NO_CLOUD_MARGIN_KM, first, second);
    float last = crossings == 2 ? second.y : first.y;  // km along the ray
    return crossings == 0 || last * length(cross(camera, dir)) / r < uClearAxisKm ||  // (|cross| / r: the sine)
           (partInClearSky(camera, dir, first) && (crossings < 2 || partInClearSky(camera, dir, second)));
}

void main() {
#ifdef SPARSE_LATTICE
    ivec2 pixel = sparseTracedPixel(ivec2(gl_FragCoord.xy));
    vec3 dir = worldRayFromNdc(pixelCentreNdc(vec2(pixel) + 0.5));
#else
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 dir = worldRayFromNdc(vNdc);
#endif
    float distance = texelFetch(surfaceDistance, pixel, 0).r;  // m, 0: none
    if (!rayMeetsNoCloud(cameraFromPlanetCentreKm(), dir, distance)) discard;
}
