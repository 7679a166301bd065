// Whole-file reads and atomic writes.
//
// Every file the program produces (images, CSV, presets, caches) goes through
// writeFileAtomic: the bytes land in a temporary file beside the target, which
// is then renamed over it, so an interrupted run never leaves a half-written
// file behind.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace planet {

struct FileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Reads a whole file; throws FileError naming the path when it cannot.
std::string readFile(const std::filesystem::path& path);

// Why `path` cannot be read as a file ("is a folder, not a file", "Permission denied", "No such
// file or directory", ...), or "" when it can.
std::string whyNotReadableFile(const std::filesystem::path& path);

// Writes bytes to path atomically (temp file + rename). Creates missing parent
// folders. Throws FileError naming the path on failure and leaves any existing
// file at path untouched.
void writeFileAtomic(const std::filesystem::path& path, std::string_view bytes);

}  // namespace planet
