#include "grid/grid_stride.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace planet {

namespace {

// Calls f(a, b, c) for each cell (i, j) of the grid whose first corner a is above the horizon
// and within the view's cone; b and c its neighbours along i and j.
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
            f(a, points[static_cast<std::size_t>(j * N + i + 1)], points[static_cast<std::size_t>((j + 1) * N + i)]);
        }
}

}  // namespace

double medianVisibleCellPixels(const std::vector<glm::dvec3>& points, int N, const Camera& camera,
                               double radiansPerPixel, double halfDiagonalFov) {
    if (N < 2 || static_cast<int>(points.size()) < N * N || !(radiansPerPixel > 0.0)) return 0.0;
    const glm::dvec3 eye = camera.position;
    const auto angle = [&](const glm::dvec3& a, const glm::dvec3& b) {
        const glm::dvec3 u = a - eye, v = b - eye;
        return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
    };
    std::vector<double> pixels;
    pixels.reserve(static_cast<std::size_t>(N - 1) * static_cast<std::size_t>(N - 1));
    forVisibleCells(points, N, camera, halfDiagonalFov, [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
        pixels.push_back(std::max(angle(a, b), angle(a, c)) / radiansPerPixel);
    });
    if (pixels.empty()) return 0.0;
    const auto middle = pixels.begin() + static_cast<std::ptrdiff_t>(pixels.size() / 2);
    std::nth_element(pixels.begin(), middle, pixels.end());
    return *middle;
}

double maxVisibleCellSegments(const std::vector<glm::dvec3>& points, int N, const Camera& camera,
                              double radiansPerPixel, double halfDiagonalFov, double planetRadiusM,
                              double targetPixels, double maxSagM) {
    if (N < 2 || static_cast<int>(points.size()) < N * N || !(radiansPerPixel > 0.0)) return 0.0;
    constexpr double kMaxSagPixels = 0.25;  // shaders/grid/tessellation.glsl's MAX_SAG_PIXELS
    const glm::dvec3 eye = camera.position;
    const auto segments = [&](const glm::dvec3& a, const glm::dvec3& b) {
        const double nearest = std::max(std::min(glm::length(a - eye), glm::length(b - eye)), 1e-3);
        const double chord = glm::length(a - b);
        const double sag = std::min(kMaxSagPixels * nearest * radiansPerPixel, maxSagM);
        return std::max(chord / nearest / radiansPerPixel / targetPixels, chord / std::sqrt(8.0 * planetRadiusM * sag));
    };
    double most = 0.0;
    forVisibleCells(points, N, camera, halfDiagonalFov, [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
        most = std::max({most, segments(a, b), segments(a, c)});
    });
    return most;
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
        state = GridStride{};
        return 1;
    }
    const std::vector<glm::dvec3> points = projectedGridVertices(params, anchor, radiusM, maxHeightM);
    const double fov = halfDiagonalFov(camera.fovY_rad, aspect);
    state.update(medianVisibleCellPixels(points, params.size, camera, radiansPerPixel, fov), kStridePatchPixels,
                 strideWithinTessellation(maxVisibleCellSegments(points, params.size, camera, radiansPerPixel, fov,
                                                                 radiusM, targetPixels, maxSagM)));
    return state.stride;
}

int gridStrideFor(double cellPixels, double patchPixels, int previous) {
    if (!(cellPixels > 0.0)) return 1;
    const int low = largestStrideWithin(cellPixels, 0.8 * patchPixels);
    const int high = largestStrideWithin(cellPixels, 1.25 * patchPixels);
    return std::clamp(previous, low, high);
}

}  // namespace planet
