#include "gl/debug.h"

#include <string>

#include "util/log.h"

namespace planet::gl {

namespace {

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void* user) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    // Compile errors reach the user through ShaderError, with real file names.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP) return;
    auto* sink = static_cast<DebugMessages*>(const_cast<void*>(user));
    const bool error = type == GL_DEBUG_TYPE_ERROR;
    if (sink) (error ? sink->errors : sink->warnings)++;
    const std::string text = "GL " + std::string(error ? "error" : "warning") + " #" + std::to_string(id) + ": " +
                             std::string(message, length < 0 ? std::char_traits<char>::length(message)
                                                             : static_cast<std::size_t>(length));
    log(error ? LogLevel::Error : LogLevel::Warning, text);
}

}  // namespace

void installDebugOutput(DebugMessages* sink, bool synchronous) {
    glEnable(GL_DEBUG_OUTPUT);
    // Synchronous output names the offending call in a debugger, at some cost.
    synchronous ? glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS) : glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, sink);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr, GL_FALSE);
}

}  // namespace planet::gl
