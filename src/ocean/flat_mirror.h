// When the sea is a flat mirror to every pixel (issue 15; shaders/ocean/cloud_reflection.glsl).
//
// Per pixel the sea reflects along the mirror ray of its normal filtered over the pixel's
// footprint (shaders/ocean/ocean_waves.glsl): a wave of wavelength lambda is kept with weight
// gerstnerLod = smoothstep(2, 4, lambda / footprint) (shaders/ocean/gerstner.glsl), shorter ones
// only roughen the glitter. The kept waves tilt the normal by their slope, about
//   s(f) = sqrt(sum_i lod_i(f) (A_i k_i)^2 / 2)       (a sine's mean square slope is (A k)^2 / 2)
// and the mirror ray by twice that, which moves its crossing of the cloud layer's top, h_top
// above the sea, by about 2 s h_top. Where that is a small part of the pixel's footprint, the
// pixel's ray sees the clouds the mean surface's mirror ray sees, and the ocean pass forms the
// clouds' share of the reflection once per grid point instead of marching every pixel's ray.
// From a camera `height` above the sea no sea pixel has a footprint below height x the angle of
// a pixel (the nearest sea is straight down; obliquity only stretches it), and s falls as the
// footprint grows, so the test at that smallest footprint holds for every sea pixel.
#pragma once

#include <vector>

#include "ocean/waves.h"

namespace planet::ocean {

// s(f) above, radians (the waves' own amplitudes: shoaling only lowers them).
double resolvedWaveSlope(const std::vector<GerstnerWave>& waves, double footprintM);

// How far the tilt may move the mirror ray's crossing of the layer's top, as a fraction of the
// smallest footprint.
inline constexpr double kFlatMirrorShiftFraction = 0.25;

// Whether every sea pixel sees the sea as a flat mirror for the clouds (see above): the camera
// `heightAboveSeaM` above the sea (<= 0: under or on it, never), `radiansPerPixel` the angle of
// a pixel, the cloud layer's top `cloudTopAboveSeaM` above the sea.
bool seaIsAFlatMirror(const std::vector<GerstnerWave>& waves, double heightAboveSeaM, double radiansPerPixel,
                      double cloudTopAboveSeaM);

// Whether no sea pixel resolves any wave (s(f) = 0 at the smallest footprint, as above: every
// wave under two footprints long, or flat): then every fragment's normal is the sphere's and
// its mirror ray the mean surface's, and the whole reflected sky, clouds and all, is formed at
// the grid's points (shaders/ocean/cloud_reflection.glsl, OCEAN_SMOOTH_MIRROR). A smooth mirror
// is a flat one.
bool seaIsASmoothMirror(const std::vector<GerstnerWave>& waves, double heightAboveSeaM, double radiansPerPixel);

}  // namespace planet::ocean
