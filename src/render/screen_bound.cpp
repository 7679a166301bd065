#include "render/screen_bound.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/constants.hpp>

namespace planet {

namespace {

ScreenRect wholeScreen(glm::ivec2 size) { return {{0, 0}, size}; }

// The part of a convex cone's cross-section (its edge directions in order) where
// dot(normal, d) <= 0 (Sutherland-Hodgman; a plane through the apex cuts a cone into a cone,
// and a point between two edge directions is a direction on the facet between them).
std::vector<glm::dvec3> clipped(const std::vector<glm::dvec3>& cone, const glm::dvec3& normal) {
    std::vector<glm::dvec3> out;
    for (std::size_t i = 0; i < cone.size(); ++i) {
        const glm::dvec3 a = cone[i], b = cone[(i + 1) % cone.size()];
        const double da = glm::dot(normal, a), db = glm::dot(normal, b);
        if (da <= 0.0) out.push_back(a);
        if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// A unit vector perpendicular to `a`.
glm::dvec3 perpendicular(const glm::dvec3& a) {
    const glm::dvec3 other = std::abs(a.x) < 0.7 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    return glm::normalize(glm::cross(a, other));
}

}  // namespace

ScreenRect sphereScreenBound(const glm::dmat4& clipFromView, const glm::dmat3& viewFromWorld, const glm::dvec3& centre,
                            double radius, glm::ivec2 size) {
    const double distance = glm::length(centre);
    // Within a thousandth of the radius of the sphere (or in it) the cone is nearly a half-space.
    if (!(distance > radius * 1.001) || !(radius > 0.0)) return wholeScreen(size);
    const glm::dvec3 axis = viewFromWorld * (centre / distance);  // view space: the camera looks down -z
    const double halfAngle = std::asin(radius / distance);
    const double outer = std::atan(std::tan(halfAngle) / std::cos(glm::pi<double>() / kConeSides));
    const glm::dvec3 u = perpendicular(axis), v = glm::cross(axis, u);
    std::vector<glm::dvec3> cone;
    for (int i = 0; i < kConeSides; ++i) {
        const double theta = 2.0 * glm::pi<double>() * i / kConeSides;
        cone.push_back(std::cos(outer) * axis + std::sin(outer) * (std::cos(theta) * u + std::sin(theta) * v));
    }
    // Cut to the view's frustum (the screen's edges: every pixel centre is half a pixel inside
    // them; a margin there would widen a sliver of the sphere at the edge, whose width grows
    // as the root of the depth it reaches into the screen): its four sides are planes through
    // the camera (for a direction, clip w = row 3 . d; inside: |clip x| <= k w, |clip y| <= k w),
    // so what is left is a cone in front of the camera, which projects into the convex hull of
    // its edges' images; a cone behind the camera, or beside the view, leaves nothing.
    const auto row = [&](int i) { return glm::dvec3(clipFromView[0][i], clipFromView[1][i], clipFromView[2][i]); };
    const glm::dvec2 k(1.0 + 1.0e-9);
    for (int axisIndex = 0; axisIndex < 2; ++axisIndex) {
        for (double sign : {1.0, -1.0}) {
            cone = clipped(cone, sign * row(axisIndex) - k[axisIndex] * row(3));
            if (cone.empty()) return {};
        }
    }
    glm::dvec2 lo(1.0e300), hi(-1.0e300);
    for (const glm::dvec3& dir : cone) {
        const glm::dvec4 clip = clipFromView * glm::dvec4(dir, 0.0);  // a point at infinity: the ray's image
        if (!(clip.w > 1.0e-12)) return wholeScreen(size);            // not in front (a field of view near 180 degrees)
        const glm::dvec2 pixel = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * glm::dvec2(size);
        lo = glm::min(lo, pixel);
        hi = glm::max(hi, pixel);
    }
    // Pixel p's centre is p + 0.5: the pixels whose centre lies in [lo, hi], a pixel wider each way.
    const auto first = [](double x) { return static_cast<int>(std::clamp(std::floor(x - 0.5) - 1.0, -1.0e9, 1.0e9)); };
    const auto last = [](double x) { return static_cast<int>(std::clamp(std::ceil(x - 0.5) + 2.0, -1.0e9, 1.0e9)); };
    ScreenRect rect{{first(lo.x), first(lo.y)}, {last(hi.x), last(hi.y)}};
    rect.min = glm::clamp(rect.min, glm::ivec2(0), size);
    rect.max = glm::clamp(rect.max, glm::ivec2(0), size);
    if (rect.empty()) return {};
    return rect;
}

ScreenRect sunDiscScreenBound(const glm::dmat4& clipFromView, const glm::dmat3& viewFromWorld,
                              const glm::dvec3& sunDirection, double angularRadius, glm::ivec2 size) {
    return sphereScreenBound(clipFromView, viewFromWorld, glm::normalize(sunDirection), std::sin(angularRadius), size);
}

ScreenRect intersection(const ScreenRect& a, const ScreenRect& b) {
    const ScreenRect r{glm::max(a.min, b.min), glm::min(a.max, b.max)};
    return r.empty() ? ScreenRect{} : r;
}

ScreenRect blocksAround(const ScreenRect& rect, int block, glm::ivec2 blocks) {
    if (rect.empty()) return {};
    ScreenRect b{rect.min / block - 1, (rect.max - 1) / block + 2};
    b.min = glm::clamp(b.min, glm::ivec2(0), blocks);
    b.max = glm::clamp(b.max, glm::ivec2(0), blocks);
    return b;
}

std::array<ScreenRect, 4> bandsAround(const ScreenRect& rect, glm::ivec2 size) {
    if (rect.empty()) return {ScreenRect{{0, 0}, size}, ScreenRect{}, ScreenRect{}, ScreenRect{}};
    const glm::ivec2 lo = glm::clamp(rect.min, glm::ivec2(0), size);
    const glm::ivec2 hi = glm::clamp(rect.max, glm::ivec2(0), size);
    return {ScreenRect{{0, 0}, {size.x, lo.y}}, ScreenRect{{0, hi.y}, size}, ScreenRect{{0, lo.y}, {lo.x, hi.y}},
            ScreenRect{{hi.x, lo.y}, {size.x, hi.y}}};
}

}  // namespace planet
