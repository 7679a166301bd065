#include "ocean/far_field.h"

#include <algorithm>
#include <cmath>

#include "grid/constants.h"

namespace planet::ocean {

double edgeTargetPixels(double distanceM, double radiansPerPixel, double maxWaveHeightM, double targetEdgePx) {
    const double wavePixels = 2.0 * maxWaveHeightM / distanceM / radiansPerPixel;
    return targetEdgePx * std::clamp(grid_constant::WAVE_VISIBLE_PIXELS / std::max(wavePixels, 1e-9), 1.0,
                                     double(grid_constant::OCEAN_FAR_EDGE_FACTOR));
}

double meshSagM(double distanceM, double radiansPerPixel, double edgePixels, double planetRadiusM) {
    const double edge = distanceM * radiansPerPixel * edgePixels;
    return edge * edge / (8.0 * planetRadiusM);
}

bool seaIsFarField(double heightAboveSeaM, double radiansPerPixel, double maxWaveHeightM, double targetEdgePx,
                   double coarsestEdgePx, double planetRadiusM) {
    const double nearest = heightAboveSeaM - maxWaveHeightM;
    if (!(nearest > 0.0) || !std::isfinite(nearest) || !(radiansPerPixel > 0.0)) return false;
    const double edge = std::max(coarsestEdgePx, edgeTargetPixels(nearest, radiansPerPixel, maxWaveHeightM, targetEdgePx));
    return meshSagM(nearest, radiansPerPixel, edge, planetRadiusM) >= grid_constant::OCEAN_FAR_FIELD_SAG_M;
}

}  // namespace planet::ocean
