// Double-precision ray-sphere reference for GPU-vs-CPU checks.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace planet::test {

// Nearest positive distance along a unit direction from origin to a sphere at
// the world origin, or -1.
inline double nearestHitDouble(const glm::dvec3& origin, const glm::dvec3& dir, double radius) {
    const double b = glm::dot(origin, dir);
    const double c = glm::dot(origin, origin) - radius * radius;
    const double disc = b * b - c;
    if (disc < 0) return -1;
    const double q = -b - std::copysign(std::sqrt(disc), b);  // stable roots: q and c / q
    double t0 = q, t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > 0) return t0;
    return t1 > 0 ? t1 : -1;
}

}  // namespace planet::test
