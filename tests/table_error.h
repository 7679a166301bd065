// GPU tables against the double-precision reference, texel by texel: shared by the atmosphere's
// GPU tests (test_atmosphere_gpu.cpp) and its range-edge tests (test_atmosphere_edges.cpp).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace planet::test {

// Largest relative error over a table's texels (all four channels), relative to
// max(|ref|, floor) with floor = 1e-3 * the table's largest |ref|: texels that
// are essentially zero (deep shadow, night side) count in absolute terms. A
// non-finite value on either side is an infinite error.
struct TableError {
    double maxRelative = 0.0;
    std::size_t worstTexel = 0;
    int worstChannel = 0;
    double gpu = 0.0, ref = 0.0;
    std::size_t texelsOver1Percent = 0;  // texels with any channel off by more than 1%
};

inline TableError compareTables(const std::vector<glm::dvec4>& gpu, const std::vector<glm::dvec4>& ref) {
    EXPECT_EQ(gpu.size(), ref.size());
    double largest = 0.0;
    for (const glm::dvec4& v : ref)
        for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(v[c]));
    const double floor = std::max(1e-3 * largest, 1e-30);
    TableError e;
    for (std::size_t i = 0; i < std::min(gpu.size(), ref.size()); ++i) {
        bool over = false;
        for (int c = 0; c < 4; ++c) {
            double rel = std::abs(gpu[i][c] - ref[i][c]) / std::max(std::abs(ref[i][c]), floor);
            if (!std::isfinite(gpu[i][c]) || !std::isfinite(ref[i][c])) rel = INFINITY;
            over = over || rel > 0.01;
            if (rel > e.maxRelative) {
                e.maxRelative = rel;
                e.worstTexel = i;
                e.worstChannel = c;
                e.gpu = gpu[i][c];
                e.ref = ref[i][c];
            }
        }
        if (over) ++e.texelsOver1Percent;
    }
    return e;
}

}  // namespace planet::test
