#include "ocean/flat_mirror.h"

#include <algorithm>
#include <cmath>

namespace planet::ocean {

namespace {
// GLSL's smoothstep (gerstner.glsl's gerstnerLod uses it with e0 < e1).
double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}
}  // namespace

double resolvedWaveSlope(const std::vector<GerstnerWave>& waves, double footprintM) {
    double variance = 0.0;
    for (const GerstnerWave& w : waves) {
        const double lod = smoothstep(2.0, 4.0, w.wavelength_m / std::max(footprintM, 1.0e-6));
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

}  // namespace planet::ocean
