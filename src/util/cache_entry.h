// The disk caches' entries, written once for all of them: the atmosphere tables
// (atmosphere/table_cache.h), the continents (noise/continents.h), and the clouds' volume and
// weather map.
//
// An entry is a folder named by its key, holding its EXR images and a key.txt of "name
// value" lines: a '# comment' line, "key <key>", the cache's own fields (version, sizes,
// parameters), then "<file> <checksum>" for each image. '#' starts a comment line.
//
//   writeCacheEntry  encodes the images (OpenEXR, float memory stored as FLOAT or HALF
//                    channels, the key repeated in a header attribute), writes them and
//                    key.txt into the temporary sibling folder <dir>.tmp<pid>, then renames
//                    it into place (replaceFolder), so a reader never sees half an entry and
//                    a left-over temporary folder is never taken for one.
//   readCacheEntry   trusts nothing: no folder, no key.txt, another key, a field that differs
//                    (version, size), a missing image, a checksum that differs, a file
//                    OpenEXR cannot read, another size or header key, a missing channel or
//                    one of another type, a NaN or Inf value: each rejects the entry with
//                    the reason, and the caller makes it again.
//   loadOrMake       the flow every cache follows around them: load unless forced, else
//                    make (timed) and save, with what happened in a CacheOutcome.
//
// The key itself (what is hashed) is each cache's own, with Fnv1a below.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace planet {

// 64-bit FNV-1a (Fowler, Noll, Vo). Numbers are hashed as little-endian 64-bit
// words whatever the host, so keys are portable.
class Fnv1a {
public:
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            hash_ ^= p[i];
            hash_ *= 0x100000001b3ull;
        }
    }
    void number(double v) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &v, sizeof bits);
        word(bits);
    }
    void integer(std::int64_t v) { word(static_cast<std::uint64_t>(v)); }
    std::uint64_t value() const { return hash_; }

private:
    void word(std::uint64_t w) {
        unsigned char b[8];
        for (int i = 0; i < 8; ++i) b[i] = static_cast<unsigned char>(w >> (8 * i));
        bytes(b, sizeof b);
    }
    std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

// 16 lower-case hex digits.
std::string hex16(std::uint64_t value);
// hex16 of the FNV-1a hash of the bytes.
std::string checksum(const std::string& bytes);
// 'path', for messages.
std::string quote(const std::filesystem::path& path);
// The "name value" lines of a key.txt.
std::map<std::string, std::string> parseKeyFile(const std::string& text);

// Moves a finished entry folder `tmp` to `target`, replacing an old entry
// (moved aside first: rename() cannot replace a non-empty folder, then
// removed). If another process put an entry there in between, that one is
// kept (it is as good). Throws FileError naming `what`; `tmp` is removed on failure.
void replaceFolder(const std::filesystem::path& tmp, const std::filesystem::path& target, const std::string& what);

// Removes what interrupted writers left in a cache root: the folders (and files)
// "<name>.tmp<pid>" and "<name>.old<pid>" of a process that no longer runs, or older than
// maxAge whoever wrote them. Called before every write of an entry.
void removeStaleTemporaries(const std::filesystem::path& root, std::chrono::hours maxAge = std::chrono::hours(24));

// ------------------------------------------------------------------ entries

// key.txt's "name value" lines, in the order they are written.
using CacheFields = std::vector<std::pair<std::string, std::string>>;

// A double with 17 significant digits (reads back exactly), for key.txt fields.
std::string exactText(double value);

// How a cache stores its values in an EXR file; memory is always float.
enum class CachePixel { Float, Half };

// One channel of an image over float texels in memory: its name in the file, the value of
// pixel (0, 0), and the distance in bytes from one pixel to the next in a row (rows follow
// each other). writeCacheEntry only reads through `base`; readCacheEntry fills it.
struct CacheChannel {
    std::string name;
    float* base = nullptr;
    std::size_t xStride = 0;
};

// Four channels over interleaved texels of four floats (glm::vec4 and the like), named
// after the texel's x, y, z, w.
std::vector<CacheChannel> interleavedChannels(float* texels, const std::vector<std::string>& names);

// One image of an entry: `file` in the entry's folder, width x height pixels.
struct CacheImage {
    std::string file;
    int width = 0, height = 0;
    std::vector<CacheChannel> channels;
};

// What a cache's entries look like.
struct CacheFormat {
    std::string what;          // for messages: "tables", "continents"
    std::string comment;       // key.txt's first line, after "# "
    std::string keyAttribute;  // the EXR string attribute that repeats the key in every image
    CachePixel pixel = CachePixel::Float;
    bool compress = false;     // ZIP; uncompressed loads faster, and noise hardly compresses
};

// Writes an entry into `dir` atomically (see the file header): every image, with the string
// attributes keyAttribute = key and `attributes` in its header, and key.txt ("# comment",
// "key <key>", `fields`, one checksum line per image). An entry already at `dir` is
// replaced. Throws FileError; nothing is left behind then.
void writeCacheEntry(const std::filesystem::path& dir, const CacheFormat& format, const std::string& key,
                     const CacheFields& fields, const std::vector<CacheImage>& images,
                     const CacheFields& attributes = {});

// Reads the entry in `dir` into the images' channels if key.txt names `key` and holds every
// field of `expected` with that value, and every image is intact (see the file header).
// Returns true, or false with the reason in *reason (the channels' memory is then undefined).
bool readCacheEntry(const std::filesystem::path& dir, const CacheFormat& format, const std::string& key,
                    const CacheFields& expected, const std::vector<CacheImage>& images,
                    std::string* reason = nullptr);

// ------------------------------------------------------------------ load or make

// What loadOrMake did.
struct CacheOutcome {
    std::filesystem::path dir;  // the entry
    bool hit = false;           // the result came from the entry
    bool forced = false;        // the entry was not looked at
    std::string rejected;       // why an entry that was there was refused ("" when none was there)
    double seconds = 0.0;       // how long make() took (0 on a hit)
    std::string notSaved;       // why save() failed ("" when it did not, or on a hit)
};

// The flow of every cache: unless `force`, load(&reason) from the entry at `dir` (an
// optional); when that gives nothing, onMake(outcome so far) (to say what comes next),
// make() (timed), then save(result). A failure to save is recorded in notSaved, not thrown:
// the result is returned anyway, and the caller decides whether it matters.
template <class Load, class Make, class Save,
          class Result = std::remove_cvref_t<decltype(*std::declval<const Load&>()(std::declval<std::string*>()))>>
Result loadOrMake(const std::filesystem::path& dir, bool force, const Load& load, const Make& make, const Save& save,
                  const std::function<void(const CacheOutcome&)>& onMake = {}, CacheOutcome* outcome = nullptr) {
    CacheOutcome o;
    o.dir = dir;
    o.forced = force;
    if (!force) {
        std::string reason;
        if (auto loaded = load(&reason)) {
            o.hit = true;
            if (outcome) *outcome = o;
            return std::move(*loaded);
        }
        if (std::filesystem::exists(dir)) o.rejected = reason;
    }
    if (onMake) onMake(o);
    const auto start = std::chrono::steady_clock::now();
    Result made = make();
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    try {
        save(made);
    } catch (const std::exception& e) {
        o.notSaved = e.what();
    }
    if (outcome) *outcome = o;
    return made;
}

}  // namespace planet
