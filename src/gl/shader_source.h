// GLSL source assembly: preamble, #include and error-log translation.
//
// GLSL has no #include, so the loader expands `#include "path"` itself (paths
// relative to the shaders/ root). Each distinct file gets a GLSL source-string
// number, and `#line <line> <file-number>` directives are emitted around every
// inclusion, so a driver's compile log ("0:12(3): error: ...", NVIDIA's
// "0(12) : error ...", glslang's "ERROR: 0:12: ...") can be rewritten to the
// real "shaders/common/math.glsl:12" by translateShaderLog(). Every file is
// included at most once per shader (implicit include guard), and a cycle or a
// missing file is an error naming the including file and line.
//
// This is pure CPU code: the same expansion feeds the driver and the offline
// glslangValidator check in the tests.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace planet::gl {

struct ShaderError : std::runtime_error {
    explicit ShaderError(const std::string& message, std::vector<std::string> sourceFiles = {})
        : std::runtime_error(message), files(std::move(sourceFiles)) {}
    std::vector<std::string> files;  // the files of the failed build, when known (for hot reload to watch)
};

struct ExpandedShader {
    std::string text;                // ready for glShaderSource
    std::vector<std::string> files;  // source-string number -> path relative to the shaders root
};

// Expands `file` (relative to root) and its includes; `preamble` goes first and
// must start with the #version line. Throws ShaderError.
ExpandedShader expandShader(const std::filesystem::path& root, const std::string& file, const std::string& preamble);

// Rewrites "<n>:<line>" style locations in a compile log to "<file>:<line>".
std::string translateShaderLog(const std::string& log, const std::vector<std::string>& files);

// Stage name of a shader file from its extension: vert, tesc, tese, geom, frag, comp. Empty if unknown.
std::string shaderStageName(const std::string& file);

}  // namespace planet::gl
