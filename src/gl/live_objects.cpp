#include "gl/live_objects.h"

namespace planet::gl {

namespace {

// Names answered true by isObject, scanning up until gapLimit names in a row answer false.
int countNames(GLboolean (*isObject)(GLuint), GLuint gapLimit) {
    int live = 0;
    GLuint sinceLast = 0;
    for (GLuint name = 1; sinceLast < gapLimit; ++name) {
        if (isObject(name)) {
            ++live;
            sinceLast = 0;
        } else {
            ++sinceLast;
        }
    }
    return live;
}

}  // namespace

LiveObjects countLiveObjects(GLuint gapLimit) {
    // epoxy's entry points are function pointers behind macros; wrap them for the scan.
    LiveObjects o;
    o.buffers = countNames([](GLuint n) { return glIsBuffer(n); }, gapLimit);
    o.textures = countNames([](GLuint n) { return glIsTexture(n); }, gapLimit);
    o.framebuffers = countNames([](GLuint n) { return glIsFramebuffer(n); }, gapLimit);
    o.vertexArrays = countNames([](GLuint n) { return glIsVertexArray(n); }, gapLimit);
    o.queries = countNames([](GLuint n) { return glIsQuery(n); }, gapLimit);
    o.programs = countNames([](GLuint n) { return glIsProgram(n); }, gapLimit);
    o.shaders = countNames([](GLuint n) { return glIsShader(n); }, gapLimit);
    return o;
}

std::string describe(const LiveObjects& o) {
    return "buffers " + std::to_string(o.buffers) + ", textures " + std::to_string(o.textures) + ", framebuffers " +
           std::to_string(o.framebuffers) + ", vertex arrays " + std::to_string(o.vertexArrays) + ", queries " +
           std::to_string(o.queries) + ", programs " + std::to_string(o.programs) + ", shaders " +
           std::to_string(o.shaders);
}

}  // namespace planet::gl
