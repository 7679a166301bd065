// Running the planet executable from tests: a shell command's exit code and
// output (stdout + stderr), and a fixture giving each test its own folder.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>

namespace planet::test {

struct ProcessResult {
    int exitCode = -1;
    std::string output;
};

inline ProcessResult runCommand(const std::string& command) {
    ProcessResult result;
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

// A test that runs the `planet` executable in a fresh folder of its own
// (named after the test), without a display or a cache override.
class CliFixture : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = std::filesystem::path(PLANET_TEST_OUT) / (std::string(info->test_suite_name()) + "." + info->name());
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    // A shell command running planet with `args` in the test's folder, with the reduced
    // atmosphere tables unless `args` says otherwise (`auto` on llvmpipe takes a minute
    // to precompute; tests/test_sky_accuracy.cpp tests it).
    std::string planet(const std::string& args) const {
        return "cd '" + dir.string() +
               "' && env -u DISPLAY -u WAYLAND_DISPLAY -u PLANET_CACHE PLANET_TABLES=reduced '" PLANET_EXE "' " + args;
    }
    // Links the folder's cache/clouds to one cloud cache for every test that asks: the
    // default preset's 256^3 cloud volume takes 10-30 s to bake on two cores, once.
    void shareCloudCache() const {
        const std::filesystem::path shared = std::filesystem::path(PLANET_TEST_OUT) / "shared_cloud_cache";
        std::filesystem::create_directories(shared);
        std::filesystem::create_directories(dir / "cache");
        std::filesystem::create_directory_symlink(shared, dir / "cache" / "clouds");
    }
    std::filesystem::path dir;
};

}  // namespace planet::test
