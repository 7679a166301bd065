// Errors and typed reads for everything the program reads from TOML.
//
// InputError is the one exception type for bad input files (presets, views):
// it carries the file, the 1-based line (0 when unknown) and the dotted field
// path, and its what() reads like a compiler diagnostic:
//
//     assets/presets/earth.toml:12: planet.radius_km: value -5 is out of range [1, 100000] km
//
// The helpers below parse text or files with toml++ (syntax errors become
// InputError with the parser's line) and read single values with a type
// check; each failure names the node's source line. Numbers accept TOML
// integers and floats alike; ints must be whole; 3-vectors are arrays of
// exactly three numbers.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <toml++/toml.h>

namespace planet {

struct InputError : std::runtime_error {
    InputError(std::string file, int line, std::string field, const std::string& message);
    // Bad input that does not come from a file (a command-line option).
    explicit InputError(const std::string& message) : InputError("", 0, "", message) {}

    std::string file;     // as given by the caller, e.g. "assets/presets/earth.toml"
    int line = 0;         // 1-based, 0 when unknown
    std::string field;    // dotted key path, e.g. "planet.radius_km"; empty when none
    std::string message;  // the bare message, without location
};

// Where a value came from, for error messages.
struct InputLocation {
    std::string file;
    int line = 0;
    std::string field;
};

// Location of a node: its source line (0 when toml++ has none).
InputLocation locate(const toml::node& node, const std::string& file, const std::string& field);
int sourceLine(const toml::node& node);

// "file:line: " (line omitted when 0, nothing when file is empty).
std::string locationPrefix(const std::string& file, int line);

// Shortest text that reads back as the same double, in fixed notation for
// ordinary magnitudes ("100000", "0.0001", "6360.5") and scientific otherwise.
std::string formatNumber(double value);

// Reads a whole file; a missing or unreadable file is an InputError naming it.
std::string readInputFile(const std::filesystem::path& path);

// Parses TOML text; a syntax error is an InputError with sourceName and line.
toml::table parseToml(std::string_view text, const std::string& sourceName);
// readInputFile + parseToml, with the path as source name.
toml::table parseTomlFile(const std::filesystem::path& path);

// Typed reads: throw InputError at the node's line naming the field on wrong type.
double readNumber(const toml::node& node, const std::string& file, const std::string& field);
int readInt(const toml::node& node, const std::string& file, const std::string& field);
bool readBool(const toml::node& node, const std::string& file, const std::string& field);
std::string readString(const toml::node& node, const std::string& file, const std::string& field);
glm::dvec3 readVec3(const toml::node& node, const std::string& file, const std::string& field);

// Throws "value V is out of range [lo, hi] unit" unless lo <= value <= hi
// (NaN is always out of range).
void checkRange(double value, double lo, double hi, const std::string& unit, const InputLocation& where);

// Unknown keys are warnings, not errors, one line each:
//     "file:line: unknown key 'path' (ignored); did you mean 'candidate'?"
// The suggestion is the closest candidate when it is near enough (edit
// distance) to be a likely typo; closestMatch returns "" when none is.
std::string unknownKeyWarning(const std::string& file, int line, const std::string& path,
                              const std::vector<std::string>& candidates);
std::string closestMatch(const std::string& key, const std::vector<std::string>& candidates);

// "a, b, c" (or "(none)") for messages listing what is available.
std::string joinNames(const std::vector<std::string>& names);

// A TOML node's type for messages: "a string", "an array of 2 elements", "a table", ...
std::string typeName(const toml::node& node);

}  // namespace planet
