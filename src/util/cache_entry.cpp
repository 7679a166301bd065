#include "util/cache_entry.h"

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

}  // namespace planet
