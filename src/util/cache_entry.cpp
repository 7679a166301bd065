// The disk caches' entries (see cache_entry.h): key.txt, the EXR images, the atomic swap.
#include "util/cache_entry.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>
#include <half.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <regex>
#include <signal.h>
#include <sstream>
#include <unistd.h>

#include "util/file_util.h"

namespace planet {

std::string hex16(std::uint64_t v) {
    static const char digits[] = "0123456789abcdef";
    std::string s(16, '0');
    for (int i = 15; i >= 0; --i, v >>= 4) s[static_cast<std::size_t>(i)] = digits[v & 15];
    return s;
}

std::string checksum(const std::string& bytes) {
    Fnv1a h;
    h.bytes(bytes.data(), bytes.size());
    return hex16(h.value());
}

// Built by appending: GCC 12 warns falsely about "'" + std::string&& (-Wrestrict).
std::string quote(const std::filesystem::path& path) {
    std::string s = "'";
    s += path.string();
    s += '\'';
    return s;
}

std::map<std::string, std::string> parseKeyFile(const std::string& text) {
    std::map<std::string, std::string> fields;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const std::size_t space = line.find(' ');
        if (space != std::string::npos) fields[line.substr(0, space)] = line.substr(space + 1);
    }
    return fields;
}

void replaceFolder(const std::filesystem::path& tmp, const std::filesystem::path& target, const std::string& what) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path old = target.string() + ".old" + std::to_string(::getpid());
    fs::remove_all(old, ec);
    if (fs::exists(target)) {
        fs::rename(target, old, ec);
        if (ec) {
            fs::remove_all(tmp, ec);
            throw FileError("cannot replace " + quote(target) + ": " + ec.message());
        }
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        const std::string why = ec.message();
        fs::remove_all(tmp, ec);
        if (!fs::exists(target / "key.txt")) throw FileError("cannot move " + what + " to " + quote(target) + ": " + why);
    }
    fs::remove_all(old, ec);
}

std::string exactText(double value) {
    std::ostringstream s;
    s.precision(17);
    s << value;
    return s.str();
}

std::vector<CacheChannel> interleavedChannels(float* texels, const std::vector<std::string>& names) {
    std::vector<CacheChannel> channels;
    for (std::size_t c = 0; c < names.size(); ++c)
        channels.push_back({names[c], texels + c, names.size() * sizeof(float)});
    return channels;
}

namespace {

Imf::PixelType pixelType(CachePixel p) { return p == CachePixel::Half ? Imf::HALF : Imf::FLOAT; }

// The image's channels as OpenEXR slices, for a data window starting at `origin`.
Imf::FrameBuffer slices(const CacheImage& image, Imath::V2i origin) {
    Imf::FrameBuffer fb;
    for (const CacheChannel& c : image.channels) {
        const std::size_t ys = c.xStride * static_cast<std::size_t>(image.width);
        char* base = reinterpret_cast<char*>(c.base) -
                     (static_cast<std::ptrdiff_t>(origin.x) * static_cast<std::ptrdiff_t>(c.xStride) +
                      static_cast<std::ptrdiff_t>(origin.y) * static_cast<std::ptrdiff_t>(ys));
        fb.insert(c.name, Imf::Slice(Imf::FLOAT, base, c.xStride, ys));
    }
    return fb;
}

std::string encodeExr(const CacheImage& image, const CacheFormat& format, const CacheFields& attributes) {
    Imf::Header header(image.width, image.height);
    for (const CacheChannel& c : image.channels) header.channels().insert(c.name, Imf::Channel(pixelType(format.pixel)));
    header.compression() = format.compress ? Imf::ZIP_COMPRESSION : Imf::NO_COMPRESSION;
    for (const auto& [name, value] : attributes) header.insert(name, Imf::StringAttribute(value));
    // OpenEXR converts HALF to float when reading, but writes only what the frame buffer
    // holds: HALF channels are rounded into buffers of their own first.
    const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    std::vector<std::vector<half>> halves;
    Imf::FrameBuffer fb = slices(image, {0, 0});
    if (format.pixel == CachePixel::Half) {
        fb = {};
        for (const CacheChannel& c : image.channels) {
            std::vector<half>& h = halves.emplace_back(pixels);
            const char* base = reinterpret_cast<const char*>(c.base);
            for (std::size_t i = 0; i < pixels; ++i) {
                float v;
                std::memcpy(&v, base + i * c.xStride, sizeof v);
                h[i] = half(v);
            }
            fb.insert(c.name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(h.data()), sizeof(half),
                                         sizeof(half) * static_cast<std::size_t>(image.width)));
        }
    }
    Imf::StdOSStream stream;
    {
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(fb);
        file.writePixels(image.height);
    }
    return stream.str();
}

// Decodes `bytes` into the image's channels; empty on success, else the reason.
std::string decodeExr(const std::string& bytes, const CacheImage& image, const CacheFormat& format,
                      const std::string& key) {
    try {
        Imf::StdISStream stream;
        stream.str(bytes);
        Imf::InputFile file(stream);
        const Imf::Header& header = file.header();
        const auto* k = header.findTypedAttribute<Imf::StringAttribute>(format.keyAttribute);
        if (!k) return "no " + format.keyAttribute + " attribute";
        if (k->value() != key) return "its header key " + k->value() + " is not " + key;
        const Imath::Box2i dw = header.dataWindow();
        const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
        if (w != image.width || h != image.height)
            return "size " + std::to_string(w) + "x" + std::to_string(h) + ", expected " +
                   std::to_string(image.width) + "x" + std::to_string(image.height);
        for (const CacheChannel& c : image.channels) {
            const Imf::Channel* channel = header.channels().findChannel(c.name);
            if (!channel) return "no channel " + c.name;
            if (channel->type != pixelType(format.pixel))
                return "channel " + c.name + " is not " + (format.pixel == CachePixel::Half ? "HALF" : "FLOAT");
        }
        file.setFrameBuffer(slices(image, dw.min));
        file.readPixels(dw.min.y, dw.max.y);
    } catch (const std::exception& e) {
        return std::string("OpenEXR cannot read it: ") + e.what();
    }
    const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    for (const CacheChannel& c : image.channels) {
        const char* base = reinterpret_cast<const char*>(c.base);
        for (std::size_t i = 0; i < pixels; ++i) {
            float v;
            std::memcpy(&v, base + i * c.xStride, sizeof v);
            if (!std::isfinite(v))
                return "texel " + std::to_string(i) + " channel " + c.name + " is not finite (" + std::to_string(v) + ")";
        }
    }
    return {};
}

}  // namespace

void removeStaleTemporaries(const std::filesystem::path& root, std::chrono::hours maxAge) {
    namespace fs = std::filesystem;
    static const std::regex temporary(R"(.+\.(tmp|old)([0-9]+))");
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(root, ec)) {
        std::smatch m;
        const std::string name = entry.path().filename().string();
        if (!std::regex_match(name, m, temporary)) continue;
        // A writer still running keeps its folder; a PID that came back for another program is
        // caught by the age.
        const long pid = std::stol(m[2].str().substr(0, 9));
        const bool writerGone = pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
        std::error_code timeError;
        const auto age = fs::file_time_type::clock::now() - entry.last_write_time(timeError);
        if (writerGone || (!timeError && age > maxAge)) fs::remove_all(entry.path(), ec);
    }
}

void writeCacheEntry(const std::filesystem::path& dir, const CacheFormat& format, const std::string& key,
                     const CacheFields& fields, const std::vector<CacheImage>& images, const CacheFields& attributes) {
    namespace fs = std::filesystem;
    const fs::path target = dir.lexically_normal();
    const fs::path tmp = target.string() + ".tmp" + std::to_string(::getpid());
    std::error_code ec;
    if (target.has_parent_path()) removeStaleTemporaries(target.parent_path());
    fs::remove_all(tmp, ec);
    CacheFields headerAttributes{{format.keyAttribute, key}};
    headerAttributes.insert(headerAttributes.end(), attributes.begin(), attributes.end());
    std::ostringstream keyFile;
    keyFile << "# " << format.comment << "\nkey " << key << "\n";
    for (const auto& [name, value] : fields) keyFile << name << " " << value << "\n";
    try {
        for (const CacheImage& image : images) {
            std::string bytes;
            try {
                bytes = encodeExr(image, format, headerAttributes);
            } catch (const std::exception& e) {
                throw FileError("could not encode OpenEXR " + quote(target / image.file) + ": " + e.what());
            }
            writeFileAtomic(tmp / image.file, bytes);
            keyFile << image.file << " " << checksum(bytes) << "\n";
        }
        writeFileAtomic(tmp / "key.txt", keyFile.str());
    } catch (...) {
        fs::remove_all(tmp, ec);
        throw;
    }
    replaceFolder(tmp, target, format.what);
}

bool readCacheEntry(const std::filesystem::path& dir, const CacheFormat& format, const std::string& key,
                    const CacheFields& expected, const std::vector<CacheImage>& images, std::string* reason) {
    auto reject = [&](const std::string& why) {
        if (reason) *reason = why;
        return false;
    };
    if (!std::filesystem::is_directory(dir)) return reject("no cache folder " + quote(dir));
    const std::filesystem::path keyPath = dir / "key.txt";
    std::string keyText;
    try {
        keyText = readFile(keyPath);
    } catch (const FileError& e) {
        return reject(e.what());
    }
    const std::map<std::string, std::string> fields = parseKeyFile(keyText);
    auto field = [&](const std::string& name) {
        const auto it = fields.find(name);
        return it == fields.end() ? std::string() : it->second;
    };
    if (field("key") != key) return reject(quote(keyPath) + " holds key " + field("key") + ", expected " + key);
    for (const auto& [name, value] : expected)
        if (field(name) != value)
            return reject(quote(keyPath) + " holds " + name + " '" + field(name) + "', expected '" + value + "'");
    for (const CacheImage& image : images) {
        const std::filesystem::path path = dir / image.file;
        std::string bytes;
        try {
            bytes = readFile(path);
        } catch (const FileError& e) {
            return reject(e.what());
        }
        const std::string listed = field(image.file);
        if (listed.empty()) return reject(quote(keyPath) + " has no checksum for " + image.file);
        if (checksum(bytes) != listed)
            return reject(quote(path) + " is damaged (checksum " + checksum(bytes) + ", expected " + listed + ")");
        const std::string why = decodeExr(bytes, image, format, key);
        if (!why.empty()) return reject(quote(path) + ": " + why);
    }
    return true;
}

}  // namespace planet
