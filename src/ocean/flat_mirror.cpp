#include "ocean/flat_mirror.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace planet::ocean {

double resolvedWaveSlope(const std::vector<GerstnerWave>& waves, double footprintM) {
    double variance = 0.0;
    for (const GerstnerWave& w : waves) {
        const double lod = glm::smoothstep(2.0, 4.0, w.wavelength_m / std::max(footprintM, 1.0e-6));  // gerstnerLod
        const double ak = w.amplitude_m * w.wavenumber();
        variance += lod * 0.5 * ak * ak;
    }
    return std::sqrt(variance);
}

bool seaIsAFlatMirror(const std::vector<GerstnerWave>& waves, double heightAboveSeaM, double radiansPerPixel,
                      double cloudTopAboveSeaM) {
    if (!(heightAboveSeaM > 0.0) || !(radiansPerPixel > 0.0) || !std::isfinite(heightAboveSeaM)) return false;
    const double footprint = heightAboveSeaM * radiansPerPixel;
    const double shift = 2.0 * resolvedWaveSlope(waves, footprint) * std::max(cloudTopAboveSeaM, 0.0);
    return shift <= kFlatMirrorShiftFraction * footprint;
}

bool seaIsASmoothMirror(const std::vector<GerstnerWave>& waves, double heightAboveSeaM, double radiansPerPixel) {
    if (!(heightAboveSeaM > 0.0) || !(radiansPerPixel > 0.0) || !std::isfinite(heightAboveSeaM)) return false;
    return resolvedWaveSlope(waves, heightAboveSeaM * radiansPerPixel) == 0.0;
}

}  // namespace planet::ocean
