// Pieces shared by the disk caches (atmosphere tables, continents): a 64-bit
// FNV-1a hash for keys and file checksums, and the `key.txt` format.
//
// A cache entry is a folder named by its key, holding its data files and a
// key.txt of "name value" lines (key, version, sizes, one checksum per file);
// '#' starts a comment line. Loaders compare every field and checksum and
// refuse the entry on any mismatch, so a damaged cache is never trusted.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>

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

}  // namespace planet
