// InputError and the typed TOML reads declared in toml_error.h.
#include "scene/toml_error.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>

#include "util/file_util.h"

namespace planet {

namespace {

std::string composeWhat(const std::string& file, int line, const std::string& field, const std::string& message) {
    std::string text = locationPrefix(file, line);
    if (!field.empty()) text += field + ": ";
    return text + message;
}

[[noreturn]] void wrongType(const toml::node& node, const std::string& file, const std::string& field,
                            const std::string& expected) {
    throw InputError(file, sourceLine(node), field, "expected " + expected + ", got " + typeName(node));
}

}  // namespace

InputError::InputError(std::string file_, int line_, std::string field_, const std::string& message_)
    : std::runtime_error(composeWhat(file_, line_, field_, message_)),
      file(std::move(file_)),
      line(line_),
      field(std::move(field_)),
      message(message_) {}

std::string locationPrefix(const std::string& file, int line) {
    if (file.empty()) return "";
    if (line <= 0) return file + ": ";
    return file + ":" + std::to_string(line) + ": ";
}

int sourceLine(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

InputLocation locate(const toml::node& node, const std::string& file, const std::string& field) {
    return InputLocation{file, sourceLine(node), field};
}

std::string formatNumber(double value) {
    char buf[64];
    const double magnitude = std::fabs(value);
    const bool ordinary = magnitude == 0.0 || (magnitude >= 1e-5 && magnitude < 1e16);
    const auto format = ordinary ? std::chars_format::fixed : std::chars_format::scientific;
    const auto result = std::to_chars(buf, buf + sizeof buf, value, format);  // shortest round trip
    return std::string(buf, result.ptr);
}

std::string typeName(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::table: return "a table";
        case toml::node_type::array: return "an array of " + std::to_string(node.as_array()->size()) + " elements";
        case toml::node_type::string: return "a string";
        case toml::node_type::integer: return "an integer";
        case toml::node_type::floating_point: return "a float";
        case toml::node_type::boolean: return "a boolean";
        case toml::node_type::date: return "a date";
        case toml::node_type::time: return "a time";
        case toml::node_type::date_time: return "a date-time";
        default: return "nothing";
    }
}

std::string readInputFile(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw InputError(path.string(), 0, "", "file not found");
    if (std::filesystem::is_directory(path, ec)) throw InputError(path.string(), 0, "", "is a folder, not a file");
    try {
        return readFile(path);
    } catch (const FileError& e) {
        throw InputError(path.string(), 0, "", e.what());
    }
}

toml::table parseToml(std::string_view text, const std::string& sourceName) {
    try {
        return toml::parse(text, sourceName);
    } catch (const toml::parse_error& e) {
        const int line = static_cast<int>(e.source().begin.line);
        throw InputError(sourceName, line, "", "TOML syntax error: " + std::string(e.description()));
    }
}

toml::table parseTomlFile(const std::filesystem::path& path) {
    return parseToml(readInputFile(path), path.string());
}

double readNumber(const toml::node& node, const std::string& file, const std::string& field) {
    if (const auto* f = node.as_floating_point()) return f->get();
    if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
    wrongType(node, file, field, "a number");
}

int readInt(const toml::node& node, const std::string& file, const std::string& field) {
    if (node.is_floating_point() || node.is_integer()) {
        const double v = readNumber(node, file, field);
        const std::string shown = "value " + formatNumber(v);
        if (v != std::floor(v)) throw InputError(file, sourceLine(node), field, shown + " is not a whole number");
        if (v < INT_MIN || v > INT_MAX) throw InputError(file, sourceLine(node), field, shown + " does not fit an int");
        return static_cast<int>(v);
    }
    wrongType(node, file, field, "a whole number");
}

bool readBool(const toml::node& node, const std::string& file, const std::string& field) {
    if (const auto* b = node.as_boolean()) return b->get();
    wrongType(node, file, field, "true or false");
}

std::string readString(const toml::node& node, const std::string& file, const std::string& field) {
    if (const auto* s = node.as_string()) return s->get();
    wrongType(node, file, field, "a string");
}

glm::dvec3 readVec3(const toml::node& node, const std::string& file, const std::string& field) {
    const auto* array = node.as_array();
    if (!array || array->size() != 3) wrongType(node, file, field, "an array of 3 numbers");
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) {
        const toml::node& element = *array->get(static_cast<size_t>(i));
        v[i] = readNumber(element, file, field + "[" + std::to_string(i) + "]");
    }
    return v;
}

void checkRange(double value, double lo, double hi, const std::string& unit, const InputLocation& where) {
    if (value >= lo && value <= hi) return;
    std::string message =
        "value " + formatNumber(value) + " is out of range [" + formatNumber(lo) + ", " + formatNumber(hi) + "]";
    if (!unit.empty()) message += " " + unit;
    throw InputError(where.file, where.line, where.field, message);
}

namespace {

// Levenshtein distance, one row at a time.
size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
        }
    }
    return row[b.size()];
}

}  // namespace

std::string closestMatch(const std::string& key, const std::vector<std::string>& candidates) {
    std::string best;
    size_t bestDistance = SIZE_MAX;
    for (const std::string& candidate : candidates) {
        const size_t d = editDistance(key, candidate);
        const size_t nearEnough = std::max<size_t>(2, candidate.size() / 4);
        if (d <= nearEnough && d < bestDistance) {
            best = candidate;
            bestDistance = d;
        }
    }
    return best;
}

std::string unknownKeyWarning(const std::string& file, int line, const std::string& path,
                              const std::vector<std::string>& candidates) {
    std::string text = locationPrefix(file, line) + "unknown key '" + path + "' (ignored)";
    const std::string suggestion = closestMatch(path, candidates);
    if (!suggestion.empty()) text += "; did you mean '" + suggestion + "'?";
    return text;
}

std::string joinNames(const std::vector<std::string>& names) {
    if (names.empty()) return "(none)";
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

}  // namespace planet
