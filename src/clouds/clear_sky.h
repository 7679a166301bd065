// Where the sky is clear for sure: for each texel of a coarse cube map over the weather map, an
// angle around every point of the texel within which the weather map's coverage (bilinear, as the
// GPU filters it, seams included) is 0. With the layer's coverage at most 1/2 (CloudLocalCoverage
// then keeps a 0 at 0) and the volume's noise (not a constant layer), no cloud lies there, near or
// far field, so the march crosses that much of the layer in one step (clouds/cloud_density.glsl,
// CloudClearDistance; clouds/cloud_march.glsl). Without it a view from the ground under a clear
// subtropical sky stepped through 100 km of empty layer along every ray near the horizon: the
// `ground` view's reduced-rate march 199 ms at 1280x720 on llvmpipe (issue 15, docs/PERFORMANCE.md).
//
// First the coverage on the coarse map's grid, each texel the largest of the weather's texels it
// covers (their bilinear values over a coarse texel are those of its texels and its neighbours'
// edges, across the faces' seams too: all within the coarse map's own bilinear taps around it).
// Then the pyramid of that map's maxima (terrain/continent_bound.h: level k's texel holds the
// largest value its bilinear filter takes within the texel's 3 x 3 at that level): a point p in a
// level-k texel whose value is 0 has no coverage within angle r of it where its cap stays inside
// those 3 x 3, that is where (size / 2) r / cos^2(a + r) <= 2^k texels of level 0 (a: p's angle
// from its face's axis, the gnomonic map's stretch at angle a + r at most 1 / cos^2(a + r)). A
// texel of the coarse map takes the largest such r over the levels, with a its farthest corner's
// angle, less 1 % (the GPU picks the texel in float). On the earth's 1024 map: 0.1 s, on 2 cores
// (from the weather's own grid, 0.6 s).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "gl/handle.h"
#include "noise/weather_map.h"

namespace planet::clouds {

// The coarse map's face size: the weather map's halved while over this (256: 40 km a texel on the
// earth's 1024 map; a skip shorter than a few texels of the weather map is not worth a lookup).
inline constexpr int kClearSkyMaxSize = 256;
// The pyramid's levels: at 256 a face, the coarsest has 8 texels a face (a cap of up to 0.06 to
// 0.2 rad, 400 to 1300 km on the earth).
inline constexpr int kClearSkyLevels = 6;

struct ClearSkyMap {
    int size = 0;                // texels a face side
    std::vector<float> radians;  // 6 * size * size, index (face * size + y) * size + x: the clear angle
};

// The clear angle of every texel of the coarse map over `weather` (its coverage channel), whose
// size is the weather's halved while over `maxSize` (and even).
ClearSkyMap buildClearSkyMap(const noise::WeatherMap& weather, int maxSize = kClearSkyMaxSize);

// The clear angle at `direction` (need not be unit length): the texel that holds it, as GL's
// nearest filtering picks it (0 on an empty map).
double clearSkyAngleAt(const ClearSkyMap& map, glm::dvec3 direction);

// The largest r with (size / 2) r / cos^2(a + r) <= 2^k (see the header), a + r < pi / 2.
double clearCapRadius(int size, int level, double axisAngle);

// The chord of the unit sphere an angle spans, 2 sin(angle / 2): what the texture holds, so that
// the march's read is the chord its clear sky allows through the layer once scaled by the layer's
// bottom radius (two points at least that far from the centre and a chord d apart are at most
// 2 asin(d / (2 bottomRadius)) apart), with no sine at every step.
double clearSkyChord(double angleRad);

// The map as an R32F cube map of the angles' chords, nearest filtering (a 1 x 1 map of 0 where
// `map` is empty).
gl::Texture makeClearSkyTexture(const ClearSkyMap& map);

}  // namespace planet::clouds
