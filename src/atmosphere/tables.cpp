#include "atmosphere/tables.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace planet::atmosphere {

std::size_t TableSizes::bytes() const {
    const glm::ivec3 s = scatteringSize();
    const std::size_t texel = 4 * sizeof(float);
    return texel * (static_cast<std::size_t>(transmittance_width) * transmittance_height +
                    2 * static_cast<std::size_t>(s.x) * s.y * s.z +
                    static_cast<std::size_t>(irradiance_width) * irradiance_height);
}

TableSizes tableSizesFor(const std::string& choice, const std::string& glRenderer) {
    if (choice == "full") return TableSizes{};
    if (choice == "reduced") return TableSizes::reduced();
    if (choice != "auto") throw std::invalid_argument("--tables must be full, reduced or auto, not '" + choice + "'");
    for (const char* software : {"llvmpipe", "softpipe", "swrast"})
        if (glRenderer.find(software) != std::string::npos) return TableSizes::reduced();
    return TableSizes{};
}

namespace {

// Texel index pair and weight along one axis for GL_LINEAR + GL_CLAMP_TO_EDGE.
struct Tap {
    int i0, i1;
    double t;
};

Tap tap(double coord, int size) {
    const double x = coord * size - 0.5;
    const double f = std::floor(x);
    const int i = static_cast<int>(f);
    return {std::clamp(i, 0, size - 1), std::clamp(i + 1, 0, size - 1), x - f};
}

}  // namespace

glm::dvec4 texture(const Table2D& table, const glm::dvec2& uv) {
    const Tap u = tap(uv.x, table.width), v = tap(uv.y, table.height);
    const glm::dvec4 a = glm::mix(table.at(u.i0, v.i0), table.at(u.i1, v.i0), u.t);
    const glm::dvec4 b = glm::mix(table.at(u.i0, v.i1), table.at(u.i1, v.i1), u.t);
    return glm::mix(a, b, v.t);
}

glm::dvec4 texture(const Table3D& table, const glm::dvec3& uvw) {
    const Tap u = tap(uvw.x, table.width), v = tap(uvw.y, table.height), w = tap(uvw.z, table.depth);
    auto plane = [&](int z) {
        const glm::dvec4 a = glm::mix(table.at(u.i0, v.i0, z), table.at(u.i1, v.i0, z), u.t);
        const glm::dvec4 b = glm::mix(table.at(u.i0, v.i1, z), table.at(u.i1, v.i1, z), u.t);
        return glm::mix(a, b, v.t);
    };
    return glm::mix(plane(w.i0), plane(w.i1), w.t);
}

}  // namespace planet::atmosphere
