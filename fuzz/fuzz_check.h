// What every fuzz target checks beyond "no crash": a value a parser accepted is finite.
// A failed check aborts, which libFuzzer reports as a crash and saves the input.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <glm/glm.hpp>

namespace planet::fuzz {

[[noreturn]] inline void fail(const std::string& what) {
    std::fprintf(stderr, "fuzz check failed: %s\n", what.c_str());
    std::abort();
}

inline void requireFinite(double v, const std::string& what) {
    if (!std::isfinite(v)) fail(what + " accepted as " + std::to_string(v));
}
inline void requireFinite(const glm::dvec3& v, const std::string& what) {
    for (int i = 0; i < 3; ++i) requireFinite(v[i], what + "[" + std::to_string(i) + "]");
}
inline void requireFinite(int, const std::string&) {}
inline void requireFinite(bool, const std::string&) {}

}  // namespace planet::fuzz
