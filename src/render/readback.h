// Reading rendered images back from GL (rows flipped so row 0 is the top).
#pragma once

#include "gl/handle.h"
#include "render/image_io.h"

namespace planet {

ImageRGBA8 readTextureRGBA8(const gl::Texture& texture, int width, int height);
ImageRGBAF readTextureRGBAF(const gl::Texture& texture, int width, int height);
// Colour of a framebuffer (0: the window's back buffer).
ImageRGBA8 readFramebufferRGBA8(GLuint framebuffer, int width, int height);

}  // namespace planet
