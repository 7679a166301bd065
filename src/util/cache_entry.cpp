#include "util/cache_entry.h"

#include <sstream>

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

}  // namespace planet
