#include "ocean/land_cull.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "terrain/height.h"

namespace planet::ocean {

namespace {
constexpr double kSafety = 2.5;     // bilinear cells (sqrt 2) and skewed texels near the cube's corners
constexpr double kMarginM = 0.5;    // above the highest crest, for the GPU's own rounding of the height
constexpr double kDisabled = 2.0;   // above any continent value: nothing culled

// The terrain's height (m, the GPU's own function in float) where the continent value is e
// everywhere, the mountains off: the ramps of e alone (the lowlands on land, the shelf at sea),
// on which the thresholds below are found.
class RampHeight {
public:
    explicit RampHeight(const TerrainParams& terrain) : shape_(terrain::makeTerrainShape(terrain)) {
        shape_.mountainOctaves = 0;  // on land they only add height; under the sea there are none
        map_.size = 1;
        map_.texels.assign(6, glm::vec4(0.0f));
    }
    double operator()(double e) {
        for (glm::vec4& t : map_.texels) t.x = static_cast<float>(e);
        return static_cast<double>(terrain::terrainHeight(glm::vec3(0.0f, 0.0f, 1.0f), shape_, map_));
    }

private:
    terrain::TerrainShape shape_;
    noise::CubeMap map_;
};

double angle(const glm::dvec3& a, const glm::dvec3& b) { return 2.0 * std::asin(std::min(glm::length(a - b) * 0.5, 1.0)); }
}  // namespace

double continentLipschitz(const noise::CubeMap& map) {
    const int n = map.size;
    if (n < 2) return 0.0;
    // Neighbour angles are the same on every face (the faces are rotations of each other).
    std::vector<double> across(static_cast<std::size_t>(n) * n, 0.0), down = across;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const glm::dvec3 d = noise::cubeTexelDirection(0, x, y, n);
            const std::size_t i = static_cast<std::size_t>(y) * n + x;
            if (x + 1 < n) across[i] = angle(d, noise::cubeTexelDirection(0, x + 1, y, n));
            if (y + 1 < n) down[i] = angle(d, noise::cubeTexelDirection(0, x, y + 1, n));
        }
    double steepest = 0.0;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * n + x;
                const glm::vec4 t = map.texels[map.index(face, x, y)];
                steepest = std::max(steepest, static_cast<double>(glm::length(glm::vec3(t.y, t.z, t.w))));
                if (x + 1 < n)
                    steepest = std::max(steepest, std::abs(map.elevation(face, x + 1, y) - t.x) / across[i]);
                if (y + 1 < n)
                    steepest = std::max(steepest, std::abs(map.elevation(face, x, y + 1) - t.x) / down[i]);
            }
    return kSafety * steepest;
}

double landContinentThreshold(const TerrainParams& terrain, double seaLevelM, double maxWaveHeightM) {
    RampHeight lowland(terrain);  // the mountains only add height
    const double needed = seaLevelM + maxWaveHeightM + kMarginM;
    if (!(lowland(1.0) > needed)) return kDisabled;
    double lo = 0.0, hi = 1.0;
    if (lowland(lo) > needed) hi = lo;
    for (int i = 0; i < 60 && hi > lo; ++i) {
        const double mid = 0.5 * (lo + hi);
        (lowland(mid) > needed ? hi : lo) = mid;
    }
    // Above hi the ramp must stay above what is needed (it rises monotonically); if a change of
    // the height function ever broke that, cull nothing rather than a sea.
    for (int i = 0; i <= 256; ++i)
        if (!(lowland(hi + (1.0 - hi) * i / 256.0) > needed)) return kDisabled;
    return hi;
}

double darkFloorContinentThreshold(const TerrainParams& terrain, double seaLevelM) {
    constexpr double kNone = -2.0;
    RampHeight height(terrain);
    const double needed = seaLevelM - kSeaFloorDarkDepthM - kMarginM;
    if (!(height(-1.0) < needed)) return kNone;
    double lo = -1.0, hi = 0.0;
    for (int i = 0; i < 60 && hi > lo; ++i) {
        const double mid = 0.5 * (lo + hi);
        (height(mid) < needed ? lo : hi) = mid;
    }
    // Below lo the ramp must stay below (it falls monotonically with e); else cull nothing.
    for (int i = 0; i <= 256; ++i)
        if (!(height(lo - (lo + 1.0) * i / 256.0) < needed)) return kNone;
    return lo;
}

double continentSampleSlackRad(const noise::CubeMap& map) { return map.size < 1 ? 0.0 : (2.0 / map.size) / 32.0; }

double continentSampleSlack(const noise::CubeMap& map, double lipschitz) {
    return lipschitz * continentSampleSlackRad(map);
}

}  // namespace planet::ocean
