// Images on disk (CPU only; src/render/readback.h reads them from GL).
//
// PNG: the display-ready RGBA8 image (tone-mapped sRGB bytes), via stb.
// OpenEXR: linear HDR radiance as half-float RGBA, via OpenEXR 3; the exposure
// used for display is stored in the header ("planetExposure") so a viewer can
// reproduce the PNG. Both are written atomically (writeFileAtomic): an
// interrupted run never leaves a half-written image.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>


namespace planet {

struct ImageRGBA8 {
    int width = 0, height = 0;
    std::vector<std::uint8_t> pixels;  // row 0 = top
};

struct ImageRGBAF {
    int width = 0, height = 0;
    std::vector<float> pixels;  // row 0 = top, 4 floats per pixel
};

// PNG of 8-bit pixels with 1 to 4 channels, rows top first. Throws
// std::invalid_argument for an empty image, FileError when it cannot write.
void writePng(const std::uint8_t* pixels, int width, int height, int channels, const std::filesystem::path& path);
void writePng(const ImageRGBA8& image, const std::filesystem::path& path);
void writeExr(const ImageRGBAF& image, const std::filesystem::path& path, double exposure);
ImageRGBAF readExr(const std::filesystem::path& path);  // throws FileError on a missing or corrupt file
double readExrExposure(const std::filesystem::path& path);  // the planetExposure header value (FileError if absent)

}  // namespace planet
