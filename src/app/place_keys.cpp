#include "app/place_keys.h"

#include <algorithm>

namespace planet {

std::optional<double> readNumberKey(const toml::table& table, const NumberKey& k, const std::string& file,
                                    const std::string& prefix) {
    const toml::node* node = table.get(k.key);
    if (!node) return std::nullopt;
    const std::string field = prefix + k.key;
    const double value = readNumber(*node, file, field);
    const InputLocation where = locate(*node, file, field);
    if (!k.open) {
        checkRange(value, k.lo, k.hi, k.unit, where);
    } else if (!(value > k.lo && value < k.hi)) {
        throw InputError(where.file, where.line, where.field,
                         "value " + formatNumber(value) + " is out of range (" + formatNumber(k.lo) + ", " +
                             formatNumber(k.hi) + ") " + k.unit);
    }
    return value;
}

double readRequiredKey(const toml::table& table, const NumberKey& k, const std::string& file, const std::string& prefix,
                       int tableLine) {
    const std::optional<double> value = readNumberKey(table, k, file, prefix);
    if (!value) throw InputError(file, tableLine, prefix + k.key, "required key is missing");
    return *value;
}

void warnUnknownKeys(const toml::table& table, const std::vector<std::string>& known, const std::string& file,
                     const std::string& prefix, std::vector<std::string>* warnings) {
    if (!warnings) return;
    for (auto&& [key, value] : table) {
        const std::string name(key.str());
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        const int keyLine = static_cast<int>(key.source().begin.line);
        warnings->push_back(unknownKeyWarning(file, keyLine > 0 ? keyLine : sourceLine(value), prefix + name, known));
    }
}

void readSunKeys(const toml::table& table, const std::string& file, const std::string& prefix,
                 std::optional<double>& elevation, std::optional<double>& azimuth) {
    using namespace place_keys;
    elevation = readNumberKey(table, kSunElevation, file, prefix);
    azimuth = readNumberKey(table, kSunAzimuth, file, prefix);
    if (elevation.has_value() == azimuth.has_value()) return;
    const NumberKey& present = elevation ? kSunElevation : kSunAzimuth;
    const NumberKey& missing = elevation ? kSunAzimuth : kSunElevation;
    throw InputError(file, sourceLine(*table.get(present.key)), prefix + present.key,
                     std::string("needs '") + missing.key + "' as well (the sun keys come as a pair or not at all)");
}

}  // namespace planet
