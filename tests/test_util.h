// Small helpers shared by several test files.
#pragma once

#include <cmath>
#include <random>

#include <glm/glm.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <system_error>

#include <unistd.h>

#include "scene/toml_error.h"

namespace planet::test {

// A fresh, empty folder under the system temp dir, named by `tag` and this process's id (CTest
// runs tests side by side), removed when this goes out of scope.
struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& tag) {
        namespace fs = std::filesystem;
        path = fs::temp_directory_path() / ("planet_" + tag + "_" + std::to_string(::getpid()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        namespace fs = std::filesystem;
        std::error_code ec;
        fs::permissions(path, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(path, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
};

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Runs f, expecting an InputError; returns it for inspection.
inline InputError expectInputError(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "expected an InputError";
    return InputError("", 0, "", "none thrown");
}

// A unit direction at angle `angle` from the unit `centre`, towards a random side.
inline glm::dvec3 atAngle(glm::dvec3 centre, double angle, std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    glm::dvec3 side;
    do side = glm::cross(centre, glm::dvec3(unit(rng), unit(rng), unit(rng)));
    while (glm::length(side) < 1e-3);
    side = glm::normalize(side);
    return std::cos(angle) * centre + std::sin(angle) * side;
}

// A random unit direction; the i-th near a cube face's edge when i is a multiple of 3, near a
// corner when a multiple of 9 (where the faces of a cube map meet).
inline glm::dvec3 randomCubeDirection(int i, std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    glm::dvec3 d = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
    if (i % 3 == 0) {
        const glm::dvec3 a = glm::abs(d);
        const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
        const int other = (axis + 1 + (i / 3) % 2) % 3;
        d[other] = std::copysign(std::abs(d[axis]) * (1.0 - 0.002 * fraction(rng)), d[other]);
        if (i % 9 == 0) d[3 - axis - other] = std::copysign(std::abs(d[axis]), d[3 - axis - other]);
        d = glm::normalize(d);
    }
    return d;
}

}  // namespace planet::test
