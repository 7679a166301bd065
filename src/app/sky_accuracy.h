// How far a sky-probe result is from a reference on the same rays (issue 14's
// measure of the atmosphere tables): per ray, the worst channel's relative error
// of the radiance, |got - reference| / max(reference, floor); its median and
// worst over two classes of rays:
//
//   daylight             sun zenith <= 80 deg and the view more than 2 deg above the
//                        horizon (its zenith angle below 90 deg + the horizon's dip
//                        minus 2 deg)
//   twilight or horizon  every other ray: a sun lower than 80 deg, views within 2 deg
//                        of the horizon, views of the ground
//
// The floor (1e-6 /sr, about 1e-4 of the noon zenith sky, a tenth of the sky's
// light with the sun 5 deg below the horizon) keeps the ratio finite; rays whose
// reference is under it in every channel (space seen past the atmosphere from
// above it) have nothing to compare and are counted apart, not in either class.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "app/sky_probe_cases.h"

namespace planet {

inline constexpr double kSkyAccuracyFloorPerSr = 1e-6;

enum class SkyRayClass { Daylight, TwilightOrHorizon };

// The class of a ray from a camera `altitudeM` above a planet of radius `planetRadiusM`.
SkyRayClass classifySkyRay(const ProbeRow& ray, double planetRadiusM);

// The worst channel's relative radiance error of one ray (see above).
double skyRadianceError(const ProbeResultRow& got, const ProbeResultRow& reference);

struct SkyErrorSummary {
    std::size_t rays = 0;
    double median = 0.0, worst = 0.0;
    std::size_t worstRow = 0;  // index into the inputs
};

struct SkyAccuracy {
    SkyErrorSummary daylight, twilightOrHorizon;
    std::size_t darkRays = 0;  // reference under the floor in every channel: not compared
};

// Throws InputError when the two lists are not the same rays in the same order.
SkyAccuracy compareSkyProbes(const std::vector<ProbeResultRow>& got, const std::vector<ProbeResultRow>& reference,
                             double planetRadiusM);

// "daylight: 96 rays, median 0.012 %, worst 0.31 % (row 17: ...)" and the same for twilight.
std::string describe(const SkyAccuracy& accuracy, const std::vector<ProbeResultRow>& rays);

}  // namespace planet
