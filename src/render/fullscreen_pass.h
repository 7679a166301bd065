// A pass that shades every pixel with one full-screen triangle
// (shaders/common/fullscreen.vert + a fragment shader).
#pragma once

#include <string>

#include "gl/program.h"

namespace planet {

class FullscreenPass {
public:
    FullscreenPass(const gl::ShaderSources& sources, const std::string& name, const std::string& fragmentFile)
        : program_(sources, gl::ProgramDesc{name, {"common/fullscreen.vert", fragmentFile}}) {}

    // Draws the triangle with the program bound; the caller binds targets and inputs.
    // Needs a bound vertex array (any: the vertex shader uses gl_VertexID only).
    void draw() const {
        glUseProgram(program_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    gl::HotProgram& program() { return program_; }
    const gl::HotProgram& program() const { return program_; }

private:
    gl::HotProgram program_;
};

}  // namespace planet
