#include "render/readback.h"

#include <algorithm>

namespace planet {

namespace {

template <class T>
void flipRows(std::vector<T>& pixels, int width, int height, int channels) {
    const std::size_t row = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)),
                         pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y + 1)),
                         pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height - 1 - y)));
}

}  // namespace

ImageRGBA8 readTextureRGBA8(const gl::Texture& texture, int width, int height) {
    ImageRGBA8 image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(image.pixels.size()),
                      image.pixels.data());
    flipRows(image.pixels, width, height, 4);  // GL's row 0 is the bottom
    return image;
}

ImageRGBAF readTextureRGBAF(const gl::Texture& texture, int width, int height) {
    ImageRGBAF image{width, height, std::vector<float>(static_cast<std::size_t>(width) * height * 4)};
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(image.pixels.size() * sizeof(float)),
                      image.pixels.data());
    flipRows(image.pixels, width, height, 4);
    return image;
}

ImageRGBA8 readFramebufferRGBA8(GLuint framebuffer, int width, int height) {
    ImageRGBA8 image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    if (framebuffer == 0) glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadnPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(image.pixels.size()),
                  image.pixels.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    flipRows(image.pixels, width, height, 4);
    return image;
}

}  // namespace planet
