// Shader programs built from files under shaders/, with hot reload.
//
// A ProgramDesc names a program and its stage files (stage from the extension:
// .vert .tesc .tese .geom .frag .comp). buildProgram() expands includes,
// compiles, links, and throws ShaderError with the log rewritten to real
// file:line. HotProgram keeps the last program that built; reloadIfChanged()
// rebuilds when any file it was made of changed on disk, and on failure keeps
// the old program running and holds the error for the UI.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "gl/handle.h"
#include "gl/shader_source.h"

namespace planet::gl {

struct ProgramDesc {
    std::string name;                // debug label, e.g. "lighting"
    std::vector<std::string> stages; // files relative to the shaders root
};

// The #version line every shader starts with; passes append their own #defines.
inline std::string shaderPreamble() { return "#version 450 core\n"; }

struct ShaderSources {
    std::filesystem::path root;  // the shaders/ folder
    std::string preamble;        // #version line and shared #defines

    // These sources with `#define name 1` added: a program's build of its own (`if (!on)`: as they are).
    ShaderSources withDefine(const std::string& name, bool on = true) const {
        return on ? ShaderSources{root, preamble + "#define " + name + " 1\n"} : *this;
    }
};

struct Program {
    ProgramObject object;
    std::vector<std::string> files;  // every file it was built from, includes too
    GLuint id() const { return object.id(); }
};

Program buildProgram(const ShaderSources& sources, const ProgramDesc& desc);

class HotProgram {
public:
    HotProgram(const ShaderSources& sources, ProgramDesc desc);  // throws ShaderError if the first build fails

    // Rebuilds if a source file changed (or `force`). Returns true when a new
    // program is in use. On failure the previous program stays and error() is set.
    bool reloadIfChanged(bool force = false);
    // Other sources for the next (re)build, e.g. a preamble with other #defines; the program in
    // use stays until reloadIfChanged(true) builds from them.
    void setSources(const ShaderSources& sources) { sources_ = sources; }
    GLuint id() const { return program_.id(); }
    const std::string& error() const { return error_; }
    const std::string& name() const { return desc_.name; }

private:
    // What the watched files look like on disk: the newest change, and how many are gone (a
    // deleted file changes no time, but must be noticed and reported).
    struct SourceStamp {
        std::filesystem::file_time_type newest{};
        int missing = 0;
        bool operator==(const SourceStamp&) const = default;
    };
    SourceStamp stamp() const;

    ShaderSources sources_;
    ProgramDesc desc_;
    Program program_;
    std::vector<std::string> watched_;  // files whose change triggers a rebuild
    SourceStamp builtFrom_{};
    std::string error_;
};

}  // namespace planet::gl
