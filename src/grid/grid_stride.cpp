#include "grid/grid_stride.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "grid/constants.h"

namespace planet {

namespace {

// Calls f(a - eye, |a - eye|, b, c) for each cell (i, j) of the grid whose first corner a is above
// the horizon and within the view's cone; b and c its neighbours along i and j.
template <typename F>
void forVisibleCells(const std::vector<glm::dvec3>& points, int N, const Camera& camera, double halfDiagonalFov, F f) {
    const glm::dvec3 eye = camera.position;
    const glm::dvec3 forward = camera.forward();
    const double cosCone = std::cos(std::min(halfDiagonalFov, 3.14159265358979323846 * 0.5));
    for (int j = 0; j + 1 < N; ++j)
        for (int i = 0; i + 1 < N; ++i) {
            const glm::dvec3& a = points[static_cast<std::size_t>(j * N + i)];
            const glm::dvec3 toA = a - eye;
            const double distance = glm::length(toA);
            if (!(distance > 0.0) || glm::dot(a, -toA) <= 0.0) continue;  // behind the horizon
            if (glm::dot(toA, forward) < cosCone * distance) continue;     // outside the view's cone
            f(toA, distance, points[static_cast<std::size_t>(j * N + i + 1)],
              points[static_cast<std::size_t>((j + 1) * N + i)]);
        }
}

}  // namespace

VisibleCells measureVisibleCells(const std::vector<glm::dvec3>& points, int N, const Camera& camera,
                                 double radiansPerPixel, double halfDiagonalFov, double planetRadiusM,
                                 double targetPixels, double maxSagM) {
    VisibleCells cells;
    if (N < 2 || static_cast<int>(points.size()) < N * N || !(radiansPerPixel > 0.0)) return cells;
    const double kMaxSagPixels = grid_constant::MAX_SAG_PIXELS;
    const glm::dvec3 eye = camera.position;
    const double sagScale = 8.0 * planetRadiusM;
    // Edge a-b (a at `distanceA` from the camera): its angle on screen, as its sine (cells are a
    // few pixels here, within 0.2 % for an angle under 0.1 rad; sine <= angle, so never larger), and the
    // segments it needs (tessellation.glsl's edgeSegments).
    const auto edge = [&](const glm::dvec3& u, double distanceA, const glm::dvec3& b, double& pixels,
                          double& segments) {
        const glm::dvec3 v = b - eye;
        const double distanceB = glm::length(v);
        pixels = glm::length(glm::cross(u, v)) / (distanceA * distanceB) / radiansPerPixel;
        const double nearest = std::max(std::min(distanceA, distanceB), 1e-3);
        const double chord = glm::length(u - v);
        const double sag = std::min(kMaxSagPixels * nearest * radiansPerPixel, maxSagM);
        segments = std::max(chord / nearest / radiansPerPixel / targetPixels, chord / std::sqrt(sagScale * sag));
    };
    std::vector<double> pixels;
    pixels.reserve(static_cast<std::size_t>(N - 1) * static_cast<std::size_t>(N - 1));
    forVisibleCells(points, N, camera, halfDiagonalFov,
                    [&](const glm::dvec3& toA, double distanceA, const glm::dvec3& b, const glm::dvec3& c) {
                        double pixelsB, segmentsB, pixelsC, segmentsC;
                        edge(toA, distanceA, b, pixelsB, segmentsB);
                        edge(toA, distanceA, c, pixelsC, segmentsC);
                        pixels.push_back(std::max(pixelsB, pixelsC));
                        cells.maxSegments = std::max({cells.maxSegments, segmentsB, segmentsC});
                    });
    if (pixels.empty()) return cells;
    const auto middle = pixels.begin() + static_cast<std::ptrdiff_t>(pixels.size() / 2);
    std::nth_element(pixels.begin(), middle, pixels.end());
    cells.medianPixels = *middle;
    return cells;
}

int strideWithinTessellation(double segments) {
    int k = 1;
    while (k < kMaxGridStride && 2.0 * k * segments <= 64.0) k *= 2;
    return k;
}

namespace {

int largestStrideWithin(double cellPixels, double limitPixels) {
    int k = 1;
    while (k < kMaxGridStride && 2.0 * k * cellPixels <= limitPixels) k *= 2;
    return k;
}

}  // namespace

double halfDiagonalFov(double fovY_rad, double aspect) {
    return std::atan(std::tan(0.5 * fovY_rad) * std::sqrt(1.0 + aspect * aspect));
}

int chooseGridStride(GridStride& state, int stride, bool allowed, const GridParams& params, const GridAnchor& anchor,
                     double radiusM, double maxHeightM, const Camera& camera, double radiansPerPixel, double aspect,
                     double targetPixels, double maxSagM) {
    if (stride > 0) return stride;
    if (!allowed) {
        state.stride = 1;  // afresh when allowed again (the points stay for their anchor)
        state.cellPixels = 0.0;
        return 1;
    }
    const GridStride::PointsOf of{anchor, params.size, params.exponent, radiusM, maxHeightM};
    if (state.points.empty() || !(state.pointsOf == of)) {
        state.points = projectedGridVertices(params, anchor, radiusM, maxHeightM);
        state.pointsOf = of;
    }
    const VisibleCells cells = measureVisibleCells(state.points, params.size, camera, radiansPerPixel,
                                                   halfDiagonalFov(camera.fovY_rad, aspect), radiusM, targetPixels,
                                                   maxSagM);
    state.update(cells.medianPixels, kStridePatchPixels, strideWithinTessellation(cells.maxSegments));
    return state.stride;
}

int gridStrideFor(double cellPixels, double patchPixels, int previous) {
    if (!(cellPixels > 0.0)) return 1;
    const int low = largestStrideWithin(cellPixels, 0.8 * patchPixels);
    const int high = largestStrideWithin(cellPixels, 1.25 * patchPixels);
    return std::clamp(previous, low, high);
}

}  // namespace planet
