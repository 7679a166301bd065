#include "atmosphere/tables.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "gl/context.h"

namespace planet::atmosphere {

std::size_t TableSizes::bytes() const {
    const glm::ivec3 s = scatteringSize();
    const std::size_t texel = 4 * sizeof(float);
    return texel * (static_cast<std::size_t>(transmittance_width) * transmittance_height +
                    2 * static_cast<std::size_t>(s.x) * s.y * s.z +
                    static_cast<std::size_t>(irradiance_width) * irradiance_height);
}

namespace {

// "AxBx..." as `count` integers in [lo, hi]; nullopt when it is not that.
std::optional<std::vector<int>> parseDims(const std::string& text, std::size_t count, int lo, int hi) {
    std::vector<int> dims;
    std::size_t start = 0;
    while (dims.size() < count) {
        const std::size_t end = std::min(text.find('x', start), text.size());
        const std::string field = text.substr(start, end - start);
        if (field.empty() || field.size() > 4 || field.find_first_not_of("0123456789") != std::string::npos)
            return std::nullopt;
        dims.push_back(std::stoi(field));
        if (dims.back() < lo || dims.back() > hi) return std::nullopt;
        start = end + 1;
        if (end == text.size()) break;
    }
    if (dims.size() != count || start <= text.size()) return std::nullopt;
    return dims;
}

// "R x MU x MU_S x NU[,TW x TH[,IW x IH]]": the scattering table (and Elek's, the same
// r, mu, mu_s) and optionally the transmittance and irradiance tables (else full size).
TableSizes explicitSizes(const std::string& choice) {
    const auto fail = [&] {
        return std::invalid_argument(
            "--tables must be full, medium, reduced, auto, or RxMUxMU_SxNU[,TWxTH[,IWxIH]] (e.g. 16x64x16x8,128x32,32x8; "
            "each 2-512, MU even), not '" + choice + "'");
    };
    std::vector<std::string> parts;
    for (std::size_t start = 0;;) {
        const std::size_t comma = choice.find(',', start);
        parts.push_back(choice.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (parts.size() > 3) throw fail();
    const auto scattering = parseDims(parts[0], 4, 2, 512);
    if (!scattering || (*scattering)[1] % 2 != 0) throw fail();
    TableSizes s;
    s.scattering_r = s.elek_r = (*scattering)[0];
    s.scattering_mu = s.elek_mu = (*scattering)[1];
    s.scattering_mu_s = s.elek_mu_s = (*scattering)[2];
    s.scattering_nu = (*scattering)[3];
    if (parts.size() > 1) {
        const auto t = parseDims(parts[1], 2, 2, 4096);
        if (!t) throw fail();
        s.transmittance_width = (*t)[0];
        s.transmittance_height = (*t)[1];
    }
    if (parts.size() > 2) {
        const auto i = parseDims(parts[2], 2, 2, 4096);
        if (!i) throw fail();
        s.irradiance_width = (*i)[0];
        s.irradiance_height = (*i)[1];
    }
    return s;
}

}  // namespace

TableSizes tableSizesFor(const std::string& choice, const std::string& glRenderer) {
    if (choice == "full") return TableSizes{};
    if (choice == "medium") return TableSizes::medium();
    if (choice == "reduced") return TableSizes::reduced();
    if (choice != "auto") return explicitSizes(choice);
    return gl::softwareRenderer(glRenderer) ? TableSizes::medium() : TableSizes{};
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
