#include "render/image_io.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfRgba.h>
#include <ImfStandardAttributes.h>
#include <ImfStdIO.h>
#include <ImfDoubleAttribute.h>
#include <stb_image_write.h>

#include <sstream>
#include <stdexcept>
#include <string>

#include "util/file_util.h"

namespace planet {

namespace {

void appendBytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

void writePng(const std::uint8_t* pixels, int width, int height, int channels, const std::filesystem::path& path) {
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4 || !pixels)
        throw std::invalid_argument("writePng: empty image or bad channel count for '" + path.string() + "'");
    std::string bytes;
    if (!stbi_write_png_to_func(appendBytes, &bytes, width, height, channels, pixels, width * channels))
        throw FileError("could not encode PNG for '" + path.string() + "'");
    writeFileAtomic(path, bytes);
}

void writePng(const ImageRGBA8& image, const std::filesystem::path& path) {
    if (image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4)
        throw std::invalid_argument("writePng: pixel buffer does not match the image size");
    writePng(image.pixels.data(), image.width, image.height, 4, path);
}

void writeExr(const ImageRGBAF& image, const std::filesystem::path& path, double exposure) {
    const int w = image.width, h = image.height;
    std::vector<Imf::Rgba> halfs(static_cast<std::size_t>(w) * h);
    for (std::size_t i = 0; i < halfs.size(); ++i) {
        const float* p = &image.pixels[i * 4];
        halfs[i] = Imf::Rgba(p[0], p[1], p[2], p[3]);
    }
    Imf::Header header(w, h);
    header.channels().insert("R", Imf::Channel(Imf::HALF));
    header.channels().insert("G", Imf::Channel(Imf::HALF));
    header.channels().insert("B", Imf::Channel(Imf::HALF));
    header.channels().insert("A", Imf::Channel(Imf::HALF));
    header.insert("planetExposure", Imf::DoubleAttribute(exposure));
    Imf::addComments(header, "linear radiance; display = 1 - exp(-planetExposure * radiance), then sRGB");
    try {
        Imf::StdOSStream stream;
        {
            Imf::OutputFile file(stream, header);
            Imf::FrameBuffer fb;
            const std::size_t xs = sizeof(Imf::Rgba), ys = xs * static_cast<std::size_t>(w);
            char* base = reinterpret_cast<char*>(halfs.data());
            fb.insert("R", Imf::Slice(Imf::HALF, base + offsetof(Imf::Rgba, r), xs, ys));
            fb.insert("G", Imf::Slice(Imf::HALF, base + offsetof(Imf::Rgba, g), xs, ys));
            fb.insert("B", Imf::Slice(Imf::HALF, base + offsetof(Imf::Rgba, b), xs, ys));
            fb.insert("A", Imf::Slice(Imf::HALF, base + offsetof(Imf::Rgba, a), xs, ys));
            file.setFrameBuffer(fb);
            file.writePixels(h);
        }
        writeFileAtomic(path, stream.str());
    } catch (const FileError&) {
        throw;
    } catch (const std::exception& e) {
        throw FileError("could not encode OpenEXR for '" + path.string() + "': " + e.what());
    }
}

ImageRGBAF readExr(const std::filesystem::path& path) {
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i dw = file.header().dataWindow();
        const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
        ImageRGBAF image{w, h, std::vector<float>(static_cast<std::size_t>(w) * h * 4, 1.0f)};
        Imf::FrameBuffer fb;
        const std::size_t xs = 4 * sizeof(float), ys = xs * static_cast<std::size_t>(w);
        char* base = reinterpret_cast<char*>(image.pixels.data()) -
                     (static_cast<std::ptrdiff_t>(dw.min.x) * xs + static_cast<std::ptrdiff_t>(dw.min.y) * ys);
        const char* names[] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c)
            fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys, 1, 1, c == 3 ? 1.0 : 0.0));
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        return image;
    } catch (const std::exception& e) {
        throw FileError("cannot read OpenEXR '" + path.string() + "': " + e.what());
    }
}

double readExrExposure(const std::filesystem::path& path) {
    try {
        Imf::InputFile file(path.c_str());
        const auto* exposure = file.header().findTypedAttribute<Imf::DoubleAttribute>("planetExposure");
        if (!exposure) throw FileError("'" + path.string() + "' has no planetExposure attribute");
        return exposure->value();
    } catch (const FileError&) {
        throw;
    } catch (const std::exception& e) {
        throw FileError("cannot read OpenEXR '" + path.string() + "': " + e.what());
    }
}

}  // namespace planet
