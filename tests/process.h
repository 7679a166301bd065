// Runs a command line in a shell and captures its exit code and output (stdout + stderr).
#pragma once

#include <array>
#include <cstdio>
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

}  // namespace planet::test
