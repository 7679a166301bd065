#include "gl/program.h"

#include <algorithm>
#include <system_error>

namespace planet::gl {

namespace fs = std::filesystem;

namespace {

GLenum stageEnum(const std::string& stage) {
    if (stage == "vert") return GL_VERTEX_SHADER;
    if (stage == "tesc") return GL_TESS_CONTROL_SHADER;
    if (stage == "tese") return GL_TESS_EVALUATION_SHADER;
    if (stage == "geom") return GL_GEOMETRY_SHADER;
    if (stage == "frag") return GL_FRAGMENT_SHADER;
    if (stage == "comp") return GL_COMPUTE_SHADER;
    return 0;
}

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
              : glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

Shader compileStage(const ShaderSources& sources, const std::string& file, std::vector<std::string>& files) {
    const GLenum stage = stageEnum(shaderStageName(file));
    if (stage == 0) throw ShaderError(file + ": unknown shader stage (use .vert .tesc .tese .geom .frag .comp)");
    const ExpandedShader expanded = expandShader(sources.root, file, sources.preamble);
    files.insert(files.end(), expanded.files.begin(), expanded.files.end());
    Shader shader(stage);
    const char* text = expanded.text.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok)
        throw ShaderError("compiling " + file + ":\n" + translateShaderLog(infoLog(shader.id(), false), expanded.files),
                          files);
    shader.label(file);
    return shader;
}

}  // namespace

Program buildProgram(const ShaderSources& sources, const ProgramDesc& desc) {
    Program program;
    std::vector<Shader> shaders;
    for (const std::string& file : desc.stages) shaders.push_back(compileStage(sources, file, program.files));
    for (const Shader& s : shaders) glAttachShader(program.id(), s.id());
    glLinkProgram(program.id());
    for (const Shader& s : shaders) glDetachShader(program.id(), s.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) throw ShaderError("linking program '" + desc.name + "':\n" + infoLog(program.id(), true));
    program.object.label(desc.name);
    return program;
}

HotProgram::HotProgram(const ShaderSources& sources, ProgramDesc desc)
    : sources_(sources), desc_(std::move(desc)), program_(buildProgram(sources_, desc_)), watched_(program_.files),
      builtFrom_(stamp()) {}

HotProgram::SourceStamp HotProgram::stamp() const {
    SourceStamp s;
    s.newest = fs::file_time_type::min();  // file_clock's epoch is in the future on libstdc++
    for (const std::string& f : watched_) {
        std::error_code ec;
        const auto t = fs::last_write_time(sources_.root / f, ec);
        if (ec)
            ++s.missing;
        else if (t > s.newest)
            s.newest = t;
    }
    return s;
}

bool HotProgram::reloadIfChanged(bool force) {
    if (!force && stamp() == builtFrom_) return false;
    try {
        program_ = buildProgram(sources_, desc_);
        watched_ = program_.files;
        builtFrom_ = stamp();
        error_.clear();
        return true;
    } catch (const ShaderError& e) {
        // Also watch files the broken edit brought in (a new include), so fixing them reloads.
        for (const std::string& f : e.files)
            if (std::find(watched_.begin(), watched_.end(), f) == watched_.end()) watched_.push_back(f);
        builtFrom_ = stamp();  // a broken edit (or a deleted file) is reported once, not every poll
        error_ = e.what();
        return false;
    }
}

}  // namespace planet::gl
