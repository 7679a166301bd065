// Atmosphere lookup tables: sizes, and CPU-side texel storage with the same
// filtering as the GPU's (GL_LINEAR, GL_CLAMP_TO_EDGE) so the shared model
// code can "sample" them when compiled as C++.
//
//   transmittance  2D  (mu, r)                      RGB: transmittance to the top boundary
//   scattering     3D  (nu * mu_s, mu, r)           RGB: Rayleigh + multiple orders, phase-free
//   single_mie     3D  same                         RGB: single Mie, phase-free
//   irradiance     2D  (mu_s, r)                    RGB: sky irradiance (direct sun excluded)
//   Elek 3D        3D  (mu_s, mu, r), azimuth 0     RGB: the scattering / single Mie tables at
//                                                   omega = 0 (Elek §4.1.1; elek_table.h)
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace planet::atmosphere {

struct TableSizes {
    int transmittance_width = 256;   // mu
    int transmittance_height = 64;   // r
    int scattering_r = 32;
    int scattering_mu = 128;
    int scattering_mu_s = 32;
    int scattering_nu = 8;
    int irradiance_width = 64;       // mu_s
    int irradiance_height = 16;      // r
    // Elek's 3D table (shaders/atmosphere/elek_table.glsl): no nu axis.
    int elek_r = 32;
    int elek_mu = 128;               // even: ground and sky halves
    int elek_mu_s = 32;

    // Small tables for tests: quick to make, but the sky is off by 3 % (daylight median)
    // to 160x (twilight worst) against the full tables.
    static TableSizes reduced() { return {64, 16, 8, 32, 8, 4, 16, 4, 8, 32, 8}; }
    // What `auto` picks on software renderers: the full tables with 96 view angles
    // instead of 128, 3/4 of their precomputation, and as accurate as issue 14 asks
    // (docs/PERFORMANCE.md, "Atmosphere table sizes"): against the full tables
    // on 3824 rays, daylight median 0.05 %, worst 1.3 %; twilight / horizon median
    // 0.11 %, worst 7 %. Any other dimension halved, or r at 16 or 24, fails a bar; r at 28
    // passes at 7/8 of the cost, r at 28 with 96 view angles misses the daylight median.
    static TableSizes medium() { return {256, 64, 32, 96, 32, 8, 64, 16, 32, 96, 32}; }
    glm::ivec3 scatteringSize() const { return {scattering_nu * scattering_mu_s, scattering_mu, scattering_r}; }
    glm::ivec3 elekSize() const { return {elek_mu_s, elek_mu, elek_r}; }
    // Bytes of the four 4D-model tables as RGBA32F textures (the Elek tables not included).
    std::size_t bytes() const;
    bool operator==(const TableSizes&) const = default;
};

// Sizes for a --tables choice: "full", "medium", "reduced", "auto" (medium when the GL
// renderer is a software one: llvmpipe, softpipe, swrast; full otherwise), or explicit
// sizes "RxMUxMU_SxNU[,TWxTH[,IWxIH]]" (the scattering table's r, mu, mu_s, nu, also
// Elek's 3D table's r, mu, mu_s; the transmittance and irradiance tables, full size if
// not given). Throws std::invalid_argument naming the accepted forms.
TableSizes tableSizesFor(const std::string& choice, const std::string& glRenderer);

struct Table2D {
    int width = 0, height = 0;
    std::vector<glm::dvec4> texels;  // row-major, row 0 = v 0

    Table2D() = default;
    Table2D(int w, int h) : width(w), height(h), texels(static_cast<std::size_t>(w) * h, glm::dvec4(0.0)) {}
    glm::dvec4& at(int x, int y) { return texels[static_cast<std::size_t>(y) * width + x]; }
    const glm::dvec4& at(int x, int y) const { return texels[static_cast<std::size_t>(y) * width + x]; }
};

struct Table3D {
    int width = 0, height = 0, depth = 0;
    std::vector<glm::dvec4> texels;  // x fastest, then y, then z

    Table3D() = default;
    Table3D(glm::ivec3 s)
        : width(s.x), height(s.y), depth(s.z), texels(static_cast<std::size_t>(s.x) * s.y * s.z, glm::dvec4(0.0)) {}
    glm::dvec4& at(int x, int y, int z) {
        return texels[(static_cast<std::size_t>(z) * height + y) * width + x];
    }
    const glm::dvec4& at(int x, int y, int z) const {
        return texels[(static_cast<std::size_t>(z) * height + y) * width + x];
    }
};

// Bilinear / trilinear lookups at normalised coordinates, clamped to the edge
// texels: what texture() returns for a GL_LINEAR, GL_CLAMP_TO_EDGE texture.
glm::dvec4 texture(const Table2D& table, const glm::dvec2& uv);
glm::dvec4 texture(const Table3D& table, const glm::dvec3& uvw);
// One texel, as GLSL's texelFetch at level 0 (the coordinates must be in range).
inline glm::dvec4 texelFetch(const Table2D& table, const glm::ivec2& xy, int /*lod*/) { return table.at(xy.x, xy.y); }

// The full set of precomputed tables.
struct AtmosphereTables {
    AtmosphereTables() = default;
    explicit AtmosphereTables(const TableSizes& s)  // zero-filled tables of these sizes
        : sizes(s), transmittance(s.transmittance_width, s.transmittance_height), scattering(s.scatteringSize()),
          singleMie(s.scatteringSize()), irradiance(s.irradiance_width, s.irradiance_height) {}

    TableSizes sizes;
    Table2D transmittance;
    Table3D scattering;
    Table3D singleMie;
    Table2D irradiance;
};

}  // namespace planet::atmosphere
