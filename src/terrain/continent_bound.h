// The highest the continents map can be over a cap of the sphere, from a pyramid of maxima: for the
// control stage that drops a patch of the sea floor where the map says for sure that all of it lies
// under the sea's dark depths (terrain/terrain.tesc, issue 15). The slope bound alone (70 per radian
// times a patch's radius) says nothing from orbit, where a patch is hundreds of kilometres across
// and the sea floor's patches were drawn, lit and shadowed under a sea that hides them: a third of
// the `orbit` frame (terrain mesh 17 -> 6 ms with a patch dropped by its centre's value alone).
//
// Level k of the pyramid has (size >> k)^2 texels a face, like a mip chain of the map. Its texel t
// holds the largest value the map (bilinear, as the GPU filters it, seams included) takes within
// t's 3 x 3 neighbourhood of texels at that level, reached on the face's plane past its edges into
// the faces beyond. A point within angle r of a direction c lies within s(r) r on c's face plane:
// the gnomonic map stretches an arc at angle a from the face's axis by 1 / cos^2 a, and a point of
// the face is at most 54.7 deg from it (a corner), so s(r) = 1 / cos^2(54.7 deg + r) (3.0 for a
// small cap, 3.8 at 0.08 rad); that is (size / 2) s(r) r texels of level 0's grid. Where that is
// at most 2^k, one texel of level k, the cap lies inside the 3 x 3 around the level-k texel that
// holds c, and that texel's value bounds the map over it. The shaders sample the pyramid with nearest filtering at the level continentMaxLevel
// picks (terrain/patch_continents.glsl); continentMaxWithin is its CPU twin (tests).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "gl/handle.h"
#include "noise/continents.h"

namespace planet::terrain {

// The largest cap (rad) the pyramid bounds (the stretch there: 6.4).
inline constexpr double kContinentMaxRadiusRad = 0.2;
// Levels 0 .. kContinentMaxLevels - 1 (fewer on a map smaller than 128 a face): at 512 a face the
// coarsest bounds a cap of 0.11 rad, a part of a patch from space (terrain/patch_continents.glsl).
inline constexpr int kContinentMaxLevels = 8;

// The plane's stretch s(r) over a cap of `radiusRad` (see above).
double continentCapStretch(double radiusRad);

struct ContinentMaxPyramid {
    int size = 0;                            // the map's face size (level 0's)
    std::vector<std::vector<float>> levels;  // level k: 6 faces of (size >> k)^2, index (face * n + y) * n + x
};

// The pyramid of `map`'s first channel (a map of at least 1 texel a face), at most `maxLevels`
// levels: the continents' elevation, or the weather map's coverage (clouds/clear_sky.h: where it
// is 0 for sure). Each level's blocks reach 2^(levels - 1) texels past the faces' edges.
template <class Texel>
ContinentMaxPyramid buildContinentMaxPyramid(const noise::CubeMapOf<Texel>& map, int maxLevels = kContinentMaxLevels);
extern template ContinentMaxPyramid buildContinentMaxPyramid(const noise::CubeMapOf<glm::vec4>&, int);
extern template ContinentMaxPyramid buildContinentMaxPyramid(const noise::CubeMapOf<glm::vec2>&, int);

// The level whose texels bound a cap of `radiusRad` ((size / 2) s(r) r <= 2^k), or -1 where none
// does (the cap too large for the pyramid's levels, or past kContinentMaxRadiusRad).
int continentMaxLevel(int size, int levels, double radiusRad);

// The highest value the map takes within `radiusRad` of the unit `centre`, bounded from above
// (+infinity where no level bounds the cap): the CPU twin of the shaders' lookup.
float continentMaxWithin(const ContinentMaxPyramid& pyramid, glm::dvec3 centre, double radiusRad);

// The pyramid as an R32F cube map with one mip level per pyramid level, nearest filtering.
gl::Texture makeContinentMaxTexture(const ContinentMaxPyramid& pyramid);

}  // namespace planet::terrain
