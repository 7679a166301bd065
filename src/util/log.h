// Log lines to stderr with a level tag; stdout stays for results (tables, paths).
#pragma once

#include <cstdio>
#include <string_view>

namespace planet {

enum class LogLevel { Debug, Info, Warning, Error };

inline void log(LogLevel level, std::string_view message) {
    static constexpr const char* tags[] = {"debug", "info", "warning", "error"};
    std::fprintf(stderr, "[planet %s] %.*s\n", tags[static_cast<int>(level)], static_cast<int>(message.size()),
                 message.data());
}
inline void logInfo(std::string_view m) { log(LogLevel::Info, m); }
inline void logWarning(std::string_view m) { log(LogLevel::Warning, m); }
inline void logError(std::string_view m) { log(LogLevel::Error, m); }

}  // namespace planet
