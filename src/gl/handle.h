// Move-only RAII owners for GL object names.
//
// GlObject<Kind> creates its object in the constructor (DSA glCreate*), deletes
// it in the destructor, cannot be copied, and leaves a moved-from owner empty
// (name 0, which every glDelete* ignores). Feature classes hold these as
// members, so a GL object's lifetime is the lifetime of whatever uses it.
// (STYLE habit 5; Bruneton's Program class, plus the deleted copy it lacks.)
#pragma once

#include <string_view>
#include <utility>

#include "gl/gl.h"

namespace planet::gl {

template <class Kind>
class GlObject {
public:
    GlObject() : name_(Kind::create()) {}
    template <class Arg>
    explicit GlObject(Arg arg) : name_(Kind::create(arg)) {}
    ~GlObject() { reset(); }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    GlObject(GlObject&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }

    GLuint id() const { return name_; }
    explicit operator bool() const { return name_ != 0; }

    // Debug label seen in RenderDoc / apitrace and in KHR_debug messages.
    void label(std::string_view text) const {
        if (name_) glObjectLabel(Kind::labelNamespace, name_, static_cast<GLsizei>(text.size()), text.data());
    }

private:
    void reset() {
        if (name_) Kind::destroy(name_);
        name_ = 0;
    }
    GLuint name_ = 0;
};

struct BufferKind {
    static constexpr GLenum labelNamespace = GL_BUFFER;
    static GLuint create() { GLuint n = 0; glCreateBuffers(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct VertexArrayKind {
    static constexpr GLenum labelNamespace = GL_VERTEX_ARRAY;
    static GLuint create() { GLuint n = 0; glCreateVertexArrays(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct FramebufferKind {
    static constexpr GLenum labelNamespace = GL_FRAMEBUFFER;
    static GLuint create() { GLuint n = 0; glCreateFramebuffers(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
struct TextureKind {
    static constexpr GLenum labelNamespace = GL_TEXTURE;
    static GLuint create(GLenum target) { GLuint n = 0; glCreateTextures(target, 1, &n); return n; }
    static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
struct QueryKind {
    static constexpr GLenum labelNamespace = GL_QUERY;
    static GLuint create(GLenum target) { GLuint n = 0; glCreateQueries(target, 1, &n); return n; }
    static void destroy(GLuint n) { glDeleteQueries(1, &n); }
};
// A query name from glGenQueries, its object made at the first glBeginQuery: Mesa's 4.5
// contexts refuse glCreateQueries for ARB_pipeline_statistics_query's targets, which
// glBeginQuery takes.
struct GenQueryKind {
    static constexpr GLenum labelNamespace = GL_QUERY;
    static GLuint create() { GLuint n = 0; glGenQueries(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteQueries(1, &n); }
};
struct ShaderKind {
    static constexpr GLenum labelNamespace = GL_SHADER;
    static GLuint create(GLenum stage) { return glCreateShader(stage); }
    static void destroy(GLuint n) { glDeleteShader(n); }
};
struct ProgramKind {
    static constexpr GLenum labelNamespace = GL_PROGRAM;
    static GLuint create() { return glCreateProgram(); }
    static void destroy(GLuint n) { glDeleteProgram(n); }
};

using Buffer = GlObject<BufferKind>;
using VertexArray = GlObject<VertexArrayKind>;
using Framebuffer = GlObject<FramebufferKind>;
using Texture = GlObject<TextureKind>;
using Query = GlObject<QueryKind>;
using GenQuery = GlObject<GenQueryKind>;  // for pipeline statistics (see GenQueryKind)
using Shader = GlObject<ShaderKind>;
using ProgramObject = GlObject<ProgramKind>;

}  // namespace planet::gl
