// Fuzzing the shipped presets (assets/presets/*.toml) and views (assets/views/*.toml):
// a few hundred mutated files, made from a fixed seed (no clock, no system randomness),
// each of which must be EITHER
//   - rejected with an InputError whose message names the file and the line
//     ("path:12: field: message"), or the file alone ("path: field: message") only for
//     a problem of the whole file: a key that the file does not hold (a required key, a
//     cross-field rule blamed on a default); and `planet render` with it exits 1 with
//     exactly "planet: error: <that message>" on stderr, nothing on stdout and no file
//     left in its output folder (checked for a fixed sample of the rejected cases);
//   - or accepted (its warnings each naming file:line; a preset must also write back as
//     a preset that loads to the same scene) and render with every pixel of the linear
//     HDR frame finite.
// Mutations: truncations, byte flips, deleted and duplicated lines, duplicated keys and
// tables, wrong types (string, array, inline table, bool, date for a number; a number
// for a bool or a string; an array for a table), extreme numbers (+-1e308, 0, -0, nan,
// +-inf, +-2^63, an integer beyond 64 bits, denormals), every numeric parameter of the
// parameter table (sceneParams: the ranges of src/*/*_params*.cpp) and every key of a
// view (app/place_keys.h) at the ends of its range and just outside them, unknown keys
// and tables, [[ocean.wave]] lists, CRLF line ends, a byte order mark, deep nesting,
// an empty file and binary garbage. Where the outcome is known (a value out of range, a
// wrong type, a duplicated key) the test asserts it: the verdict, the line and the field.
// Three tests share the cases: loading and checking all of them (about 1 s), the command
// line on a fixed sample of the refused ones (about 5 s) and rendering the loaded ones
// (see LoadedFilesRenderFinitePixels for which, and the time). Each works in its own folder
// under PLANET_TEST_OUT; the renders use a fresh table cache there, never the user's.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/session.h"
#include "app/views.h"
#include "atmosphere/parameters.h"
#include "atmosphere/uniforms.h"
#include "gl_test_support.h"
#include "process.h"
#include "render/readback.h"
#include "render/renderer.h"
#include "scene/preset.h"
#include "scene/scene_params.h"
#include "scene/toml_error.h"
#include "util/file_util.h"

namespace planet {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const fs::path kAssets = fs::path(PLANET_SOURCE_DIR) / "assets";
const fs::path kOut = fs::path(PLANET_TEST_OUT) / "fuzz_assets";

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// ---- deterministic randomness: splitmix64, the same numbers on every platform ----

class Rng {
public:
    explicit Rng(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // In [0, n); n > 0.
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }

private:
    std::uint64_t state_;
};

// ---- text helpers ----

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::string line;
    for (const char c : text) {
        if (c == '\n') {
            lines.push_back(line);
            line.clear();
        } else {
            line += c;
        }
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    return text;
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
}

// A `key = value` line outside comments and strings' continuations, with the table it is in.
struct KeyLine {
    int line = 0;         // 1-based
    std::string section;  // "" at the top level
    std::string key;
};

std::vector<KeyLine> keyLines(const std::string& text) {
    std::vector<KeyLine> keys;
    std::string section;
    const std::vector<std::string> lines = splitLines(text);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& l = lines[i];
        const std::size_t start = l.find_first_not_of(" \t");
        if (start == std::string::npos || l[start] == '#') continue;
        if (l[start] == '[') {
            const std::size_t end = l.find(']');
            section = l.substr(start + 1, end - start - 1);
            continue;
        }
        const std::size_t eq = l.find('=');
        if (eq == std::string::npos) continue;
        std::string key = l.substr(start, eq - start);
        key.erase(key.find_last_not_of(" \t") + 1);
        keys.push_back({static_cast<int>(i) + 1, section, key});
    }
    return keys;
}

// The text with the value of the key on `line` replaced (its comment dropped).
std::string withValue(const std::string& text, int line, const std::string& value) {
    std::vector<std::string> lines = splitLines(text);
    std::string& l = lines.at(static_cast<std::size_t>(line - 1));
    l = l.substr(0, l.find('=') + 1) + " " + value;
    return joinLines(lines);
}

std::optional<KeyLine> findKey(const std::string& text, const std::string& section, const std::string& key) {
    for (const KeyLine& k : keyLines(text))
        if (k.section == section && k.key == key) return k;
    return std::nullopt;
}

// A TOML float literal that reads back as exactly this double.
std::string tomlNumber(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::string text = formatNumber(v);
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
}

// ---- the cases ----

enum class FileKind { Preset, View };

// What a case must give, beyond the invariants every case is checked against.
struct Expect {
    enum Verdict {
        Any,          // rejected or accepted: the invariants only
        Reject,       // an InputError at `line` (when > 0) naming `field` (when not empty), what() holding `text`
        Accept,       // loads; a warning holding `text` when it is not empty
        InsideRange,  // a value inside its range: accepted, or (presets) rejected only by a cross-field rule
    };
    Verdict verdict = Any;
    int line = 0;
    std::string field;
    std::string text;

    static Expect any() { return {}; }
    static Expect accept(std::string warning = "") { return make(Accept, 0, "", std::move(warning)); }
    static Expect reject(int line, std::string field = "", std::string text = "") {
        return make(Reject, line, std::move(field), std::move(text));
    }
    static Expect inside(int line, std::string field) { return make(InsideRange, line, std::move(field), ""); }

private:
    static Expect make(Verdict v, int line, std::string field, std::string text) {
        Expect e;
        e.verdict = v;
        e.line = line;
        e.field = std::move(field);
        e.text = std::move(text);
        return e;
    }
};

struct FuzzCase {
    std::string id;    // also the file's stem, so a view's name
    FileKind kind = FileKind::Preset;
    std::string base;  // the shipped file it was made from: "earth", "beach", ...
    std::string text;
    Expect expect;
};

// The fields whose cross-field rules validateScene may blame (scene_params.h).
bool isCrossFieldRule(const std::string& field) {
    for (const char* f : {"atmosphere.top_radius_km", "atmosphere.mie_extinction_per_m", "terrain.grid_exponent",
                          "ocean.fade_end", "ocean.wave", "clouds.top_altitude_km",
                          // where the atmosphere tables hold (atmosphere/parameters.h, checkAtmosphereLimits)
                          "planet.radius_km", "atmosphere.rayleigh_scale_height_km", "atmosphere.mie_scale_height_km",
                          "atmosphere.rayleigh_scattering_per_m", "atmosphere.ozone_absorption_per_m"})
        if (field == f) return true;
    return false;
}

class CaseMaker {
public:
    explicit CaseMaker(std::vector<FuzzCase>& out) : out_(out) {}
    void add(FileKind kind, const std::string& base, const std::string& what, std::string text, Expect expect = {}) {
        char number[16];
        std::snprintf(number, sizeof number, "%03zu", out_.size());
        out_.push_back({base + "_" + number + "_" + what, kind, base, std::move(text), std::move(expect)});
    }

private:
    std::vector<FuzzCase>& out_;
};

// Mutations that know nothing of the file's meaning: the invariants only.
void addBlindMutations(CaseMaker& make, FileKind kind, const std::string& base, const std::string& text, Rng& rng,
                       int count) {
    const std::vector<std::string> lines = splitLines(text);
    for (int i = 0; i < count; ++i) {
        switch (i % 5) {
            case 0:  // truncated anywhere, also inside a token
                make.add(kind, base, "truncated", text.substr(0, rng.below(text.size())));
                break;
            case 1: {  // one bit flipped, or a byte replaced by any byte
                std::string t = text;
                const std::size_t at = rng.below(t.size());
                if (rng.below(2) == 0)
                    t[at] = static_cast<char>(t[at] ^ (1 << rng.below(8)));
                else
                    t[at] = static_cast<char>(rng.below(256));
                make.add(kind, base, "byteflip", t);
                break;
            }
            case 2: {  // a line deleted
                std::vector<std::string> l = lines;
                l.erase(l.begin() + static_cast<long>(rng.below(l.size())));
                make.add(kind, base, "lostline", joinLines(l));
                break;
            }
            case 3: {  // a line duplicated: a duplicated key or table is a TOML error at the copy
                std::vector<std::string> l = lines;
                const std::size_t at = rng.below(l.size());
                l.insert(l.begin() + static_cast<long>(at) + 1, l[at]);
                make.add(kind, base, "dupline", joinLines(l));
                break;
            }
            case 4: {  // a chunk of the file moved elsewhere
                std::vector<std::string> l = lines;
                const std::size_t from = rng.below(l.size());
                const std::size_t n = std::min<std::size_t>(1 + rng.below(4), l.size() - from);
                std::vector<std::string> chunk(l.begin() + static_cast<long>(from), l.begin() + static_cast<long>(from + n));
                l.erase(l.begin() + static_cast<long>(from), l.begin() + static_cast<long>(from + n));
                const std::size_t to = rng.below(l.size() + 1);
                l.insert(l.begin() + static_cast<long>(to), chunk.begin(), chunk.end());
                make.add(kind, base, "movedlines", joinLines(l));
                break;
            }
        }
    }
}

// Mutations every file gets, whatever it holds.
void addWholeFileMutations(CaseMaker& make, FileKind kind, const std::string& base, const std::string& text, Rng& rng) {
    make.add(kind, base, "empty", "");
    std::string garbage;
    for (int i = 0; i < 96; ++i) garbage += static_cast<char>(rng.below(256));
    make.add(kind, base, "garbage", garbage);
    std::string nul = text;
    nul.insert(rng.below(nul.size()), 1, '\0');
    make.add(kind, base, "nulbyte", nul);
    std::string crlf;
    for (const char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    make.add(kind, base, "crlf", crlf, Expect::accept());
    make.add(kind, base, "bom", "\xEF\xBB\xBF" + text, Expect::accept());
    // Nested arrays far deeper than any parser's stack should take.
    make.add(kind, base, "deepnest", "deep = " + std::string(20000, '[') + std::string(20000, ']') + "\n" + text);
    if (const std::optional<KeyLine> d = findKey(text, "", "description"))
        make.add(kind, base, "longline", withValue(text, d->line, "\"" + std::string(200000, 'x') + "\""),
                 Expect::accept());
}

// A value of the wrong type for a key of each kind.
void addWrongTypes(CaseMaker& make, FileKind kind, const std::string& base, const std::string& text,
                   const std::vector<std::pair<KeyLine, std::string>>& keys, Rng& rng) {
    // key kind ("number", "int", "vec3", "bool", "string") -> values of other types
    const std::map<std::string, std::vector<std::string>> wrong = {
        {"number", {"\"12\"", "[1.0]", "{ value = 1.0 }", "true", "1979-05-27", "07:32:00"}},
        {"int", {"\"4\"", "[4]", "false", "4.5", "1e300"}},
        {"vec3", {"0.5", "[0.1, 0.2]", "[0.1, 0.2, 0.3, 0.4]", "[\"a\", 0.2, 0.3]", "[[0.1], 0.2, 0.3]", "\"[1,2,3]\""}},
        {"bool", {"1", "\"true\"", "[true]", "yes"}},
        {"string", {"42", "true", "[\"a\"]", "{ a = 1 }"}},
    };
    for (const auto& [key, type] : keys) {
        const std::vector<std::string>& values = wrong.at(type);
        const std::string value = values[rng.below(values.size())];
        const std::string path = key.section.empty() ? key.key : key.section + "." + key.key;
        Expect e = Expect::reject(key.line);
        // Not every wrong value names the whole key: an array's element names its index, and
        // a bare word ("yes") is a TOML syntax error without a field.
        if (value != "yes" && value.rfind("[\"a\"", 0) != 0 && value.rfind("[[", 0) != 0) e.field = path;
        if (type == "int" && value == "4.5") e.text = "is not a whole number";
        if (type == "int" && value == "1e300") e.text = "does not fit an int";
        make.add(kind, base, "type_" + key.key, withValue(text, key.line, value), e);
    }
}

// Extreme numbers for numeric keys: accepted only inside the key's range.
void addExtremes(CaseMaker& make, FileKind kind, const std::string& base, const std::string& text,
                 const std::vector<KeyLine>& numeric, Rng& rng, int count) {
    const std::vector<std::string> values = {
        "1e308", "-1e308", "1.7976931348623157e308", "0", "-0.0", "+0.0", "nan", "-nan", "inf", "-inf", "+inf",
        "9223372036854775807", "-9223372036854775808", "99999999999999999999", "4.9e-324", "-4.9e-324", "1e-310",
        "2.2250738585072014e-308", "1e400", "0x7FFFFFFF", "1_000_000"};
    for (int i = 0; i < count; ++i) {
        const KeyLine& key = numeric[rng.below(numeric.size())];
        const std::string value = values[rng.below(values.size())];
        Expect e;
        // Every range is finite and no key takes 1e308: these must be refused, at the key's line.
        if (value == "1e308" || value == "-1e308" || value == "nan" || value == "-nan" || value.find("inf") != std::string::npos ||
            value == "99999999999999999999" || value == "1e400" || value == "1.7976931348623157e308")
            e = Expect::reject(key.line);
        make.add(kind, base, "extreme_" + key.key, withValue(text, key.line, value), e);
    }
}

// Every numeric parameter of the table at the ends of its range (accepted unless a
// cross-field rule says no) and just outside them (refused at the key's line, naming it).
void addPresetRangeEdges(CaseMaker& make, const std::string& base, const std::string& text, Rng& rng) {
    Scene scratch;
    for (const ParamSpec& spec : sceneParams()) {
        const ParamRef ref = spec.field(scratch);
        if (std::holds_alternative<bool*>(ref)) continue;
        const std::optional<KeyLine> key = findKey(text, spec.section, spec.key);
        if (!key) continue;
        const bool isInt = std::holds_alternative<int*>(ref);
        const bool isVec = std::holds_alternative<glm::dvec3*>(ref);
        const int component = isVec ? static_cast<int>(rng.below(3)) : 0;
        auto valueText = [&](double v) {
            const std::string number = isInt ? formatNumber(v) : tomlNumber(v);
            if (!isVec) return number;
            // The other components as the file has them.
            glm::dvec3 file = readVec3(*parseToml(text, "x").at_path(spec.path()).node(), "x", spec.path());
            std::string t = "[";
            for (int c = 0; c < 3; ++c) t += (c ? ", " : "") + (c == component ? number : tomlNumber(file[c]));
            return t + "]";
        };
        const std::string field = isVec ? spec.path() + "[" + std::to_string(component) + "]" : spec.path();
        const double below = isInt ? spec.min - 1 : std::nextafter(spec.min, -HUGE_VAL);
        const double above = isInt ? spec.max + 1 : std::nextafter(spec.max, HUGE_VAL);
        make.add(FileKind::Preset, base, "min_" + spec.key, withValue(text, key->line, valueText(spec.min)),
                 Expect::inside(key->line, field));
        make.add(FileKind::Preset, base, "max_" + spec.key, withValue(text, key->line, valueText(spec.max)),
                 Expect::inside(key->line, field));
        make.add(FileKind::Preset, base, "below_" + spec.key, withValue(text, key->line, valueText(below)),
                 Expect::reject(key->line, field, "out of range"));
        make.add(FileKind::Preset, base, "above_" + spec.key, withValue(text, key->line, valueText(above)),
                 Expect::reject(key->line, field, "out of range"));
    }
}

// Every key of a view at the ends of its range and just outside (fov's range is open).
void addViewRangeEdges(CaseMaker& make, const std::string& base, const std::string& text) {
    struct Range {
        const char* key;
        double lo, hi;
        bool open;
    };
    const Range ranges[] = {{"latitude_deg", -90, 90, false},   {"longitude_deg", -180, 180, false},
                            {"altitude_m", 0.1, 1e9, false},    {"heading_deg", -360, 360, false},
                            {"pitch_deg", -90, 90, false},      {"fov_deg", 1, 170, true},
                            {"sun_elevation_deg", -90, 90, false}, {"sun_azimuth_deg", -360, 360, false}};
    for (const Range& r : ranges) {
        const std::optional<KeyLine> key = findKey(text, "", r.key);
        if (!key) continue;
        const double insideLo = r.open ? std::nextafter(r.lo, HUGE_VAL) : r.lo;
        const double insideHi = r.open ? std::nextafter(r.hi, -HUGE_VAL) : r.hi;
        const double outsideLo = r.open ? r.lo : std::nextafter(r.lo, -HUGE_VAL);
        const double outsideHi = r.open ? r.hi : std::nextafter(r.hi, HUGE_VAL);
        make.add(FileKind::View, base, std::string("min_") + r.key, withValue(text, key->line, tomlNumber(insideLo)),
                 Expect::accept());
        make.add(FileKind::View, base, std::string("max_") + r.key, withValue(text, key->line, tomlNumber(insideHi)),
                 Expect::accept());
        make.add(FileKind::View, base, std::string("below_") + r.key, withValue(text, key->line, tomlNumber(outsideLo)),
                 Expect::reject(key->line, r.key, "out of range"));
        make.add(FileKind::View, base, std::string("above_") + r.key, withValue(text, key->line, tomlNumber(outsideHi)),
                 Expect::reject(key->line, r.key, "out of range"));
    }
}

// Whole sections at a corner of the ranges: every numeric parameter of one section at its
// minimum, or at its maximum, together (cross-field rules may refuse some).
void addSectionCorners(CaseMaker& make, const std::string& base, const std::string& text) {
    Scene scratch;
    std::vector<std::string> sections;
    for (const ParamSpec& spec : sceneParams())
        if (std::find(sections.begin(), sections.end(), spec.section) == sections.end()) sections.push_back(spec.section);
    for (const std::string& section : sections) {
        for (const bool top : {false, true}) {
            std::string t = text;
            for (const ParamSpec& spec : sceneParams()) {
                if (spec.section != section) continue;
                const ParamRef ref = spec.field(scratch);
                if (std::holds_alternative<bool*>(ref)) continue;
                const std::optional<KeyLine> key = findKey(t, spec.section, spec.key);
                if (!key) continue;
                const double v = top ? spec.max : spec.min;
                const std::string number = std::holds_alternative<int*>(ref) ? formatNumber(v) : tomlNumber(v);
                t = withValue(t, key->line, std::holds_alternative<glm::dvec3*>(ref)
                                                ? "[" + number + ", " + number + ", " + number + "]"
                                                : number);
            }
            make.add(FileKind::Preset, base, (top ? "allmax_" : "allmin_") + section, t, Expect::inside(0, ""));
        }
    }
}

// Unknown keys and tables, tables of the wrong type, duplicated tables and keys.
void addStructureMutations(CaseMaker& make, FileKind kind, const std::string& base, const std::string& text, Rng& rng) {
    const std::vector<KeyLine> keys = keyLines(text);
    const int lines = static_cast<int>(splitLines(text).size());
    // An unknown key at the top: a warning at line 1, the file otherwise as it was.
    make.add(kind, base, "unknown_top", "bogus_setting = 1\n" + text, Expect::accept(":1: unknown key 'bogus_setting'"));
    // A misspelt key where the real one is: a warning with a suggestion.
    const KeyLine& k = keys[rng.below(keys.size())];
    std::vector<std::string> l = splitLines(text);
    l.insert(l.begin() + k.line, k.key + "x = 1");
    const std::string path = k.section.empty() ? k.key + "x" : k.section + "." + k.key + "x";
    make.add(kind, base, "unknown_near", joinLines(l),
             Expect::accept(":" + std::to_string(k.line + 1) + ": unknown key '" + path + "'"));
    // A key given twice: TOML refuses the second.
    l = splitLines(text);
    l.insert(l.begin() + k.line, k.key + " = 1");
    make.add(kind, base, "dupkey_" + k.key, joinLines(l), Expect::reject(k.line + 1, "", "TOML syntax error"));
    // An unknown table at the end.
    make.add(kind, base, "unknown_table", text + "[bogus_table]\nvalue = 2\n",
             Expect::accept(":" + std::to_string(lines + 1)));
    if (kind == FileKind::View) {
        // A view is one flat table: a table inside it is an unknown key (a warning).
        make.add(kind, base, "subtable", text + "[camera]\nlatitude_deg = 5\n", Expect::any());
        return;
    }
    // A section given twice.
    std::set<std::string> sections;
    for (const KeyLine& key : keys)
        if (!key.section.empty()) sections.insert(key.section);
    const std::vector<std::string> names(sections.begin(), sections.end());
    const std::string section = names[rng.below(names.size())];
    make.add(kind, base, "duptable_" + section, text + "[" + section + "]\n",
             Expect::reject(lines + 1, "", "TOML syntax error"));
    // A section that is not a table: an array, a number, a bool, a string, an array of tables.
    const std::vector<std::string> notTables = {"[1, 2]", "5", "true", "\"planet\""};
    for (const std::string& value : notTables) {
        const std::string s = names[rng.below(names.size())];
        std::string renamed = text;
        const std::string header = "[" + s + "]";
        renamed.replace(renamed.find(header), header.size(), "[" + s + "_renamed]");
        make.add(kind, base, "nottable_" + s, s + " = " + value + "\n" + renamed, Expect::reject(1, s, "expected a table"));
    }
    {
        const std::string s = names[rng.below(names.size())];
        std::string renamed = text;
        const std::string header = "[" + s + "]";
        renamed.replace(renamed.find(header), header.size(), "[[" + s + "]]");
        make.add(kind, base, "arrayoftables_" + s, renamed, Expect::reject(0, s, "expected a table"));
    }
    // A top-level header key of the wrong type.
    make.add(kind, base, "name_number", "name = 42\n" + (text.rfind("name =", 0) == 0 ? text.substr(text.find('\n') + 1) : text),
             Expect::any());
}

// [[ocean.wave]] lists (scene/preset_waves.h): good, bad and extreme waves.
void addWaveLists(CaseMaker& make, const std::string& base, const std::string& text) {
    const int first = static_cast<int>(splitLines(text).size()) + 1;  // the [[ocean.wave]] header's line
    auto wave = [](const std::string& body) { return "[[ocean.wave]]\n" + body; };
    const std::string good = "origin = [0.0, 0.0, 1.0]\namplitude_m = 0.4\nwavelength_m = 30.0\nsteepness = 0.3\n";
    make.add(FileKind::Preset, base, "wave_good", text + wave(good), Expect::accept());
    make.add(FileKind::Preset, base, "wave_latlon",
             text + wave("latitude_deg = 90\nlongitude_deg = -180\namplitude_m = 0\nwavelength_m = 0.001\n"),
             Expect::accept());
    make.add(FileKind::Preset, base, "wave_zero_origin", text + wave("origin = [0, 0, 0]\namplitude_m = 1\nwavelength_m = 10\n"),
             Expect::reject(first + 1, "ocean.wave[0].origin", ""));
    make.add(FileKind::Preset, base, "wave_huge_origin",
             text + wave("origin = [1e308, 1e308, 0]\namplitude_m = 1\nwavelength_m = 10\n"),
             Expect::reject(first + 1, "ocean.wave[0].origin", ""));
    make.add(FileKind::Preset, base, "wave_tiny_origin",
             text + wave("origin = [1e-300, 0, 0]\namplitude_m = 1\nwavelength_m = 10\n"),
             Expect::reject(first + 1, "ocean.wave[0].origin", ""));
    make.add(FileKind::Preset, base, "wave_nan", text + wave("origin = [0, 1, 0]\namplitude_m = nan\nwavelength_m = 10\n"),
             Expect::reject(first + 2, "ocean.wave[0].amplitude_m", "out of range"));
    make.add(FileKind::Preset, base, "wave_steep",
             text + wave("origin = [0, 1, 0]\namplitude_m = 1000\nwavelength_m = 10\nsteepness = 1\n"),
             Expect::reject(0, "ocean.wave", "above 1"));
    make.add(FileKind::Preset, base, "wave_extremes",
             text + wave("origin = [1e-5, 1e5, 0]\namplitude_m = 0.001\nwavelength_m = 1e7\nsteepness = 1\n"
                         "speed_mps = -1e4\nphase_rad = 1e6\n"),
             Expect::accept());
    make.add(FileKind::Preset, base, "wave_unknown", text + wave(good + "colour = 3\n"),
             Expect::reject(first + 5, "ocean.wave[0].colour", "unknown wave field"));
    make.add(FileKind::Preset, base, "wave_missing", text + wave("origin = [0, 1, 0]\nwavelength_m = 10\n"),
             Expect::reject(first, "ocean.wave[0].amplitude_m", "missing"));
    make.add(FileKind::Preset, base, "wave_table", text + "[ocean.wave]\namplitude_m = 1\n",
             Expect::reject(first, "ocean.wave", "expected [[ocean.wave]] tables"));
    // Many waves: each a sum term in the ocean's shaders.
    std::string many = text;
    for (int i = 0; i < 300; ++i)
        many += wave("latitude_deg = " + std::to_string(i % 180 - 90) + "\nlongitude_deg = " + std::to_string(i - 150) +
                     "\namplitude_m = 0.01\nwavelength_m = " + std::to_string(5 + i) + "\nsteepness = 0.5\n");
    make.add(FileKind::Preset, base, "wave_many", many, Expect::accept());
}

// Valid TOML spelt in other ways than the shipped files spell it: the same meaning, loaded
// (or refused, at the right line, when the value is bad).
void addSpellings(CaseMaker& make, const std::string& base) {
    auto preset = [&](const std::string& what, const std::string& text, Expect e) {
        make.add(FileKind::Preset, base, what, text, std::move(e));
    };
    preset("dotted_keys", "planet.radius_km = 7000.0\natmosphere.top_radius_km = 7060\n", Expect::accept());
    preset("quoted_keys", "[\"planet\"]\n'radius_km' = 6000\n", Expect::accept());
    preset("inline_table", "planet = { radius_km = 6000.0, albedo = [0.1, 0.2, 0.3] }\n", Expect::accept());
    preset("inline_table_bad", "\nplanet = { radius_km = -5.0 }\n", Expect::reject(2, "planet.radius_km", "out of range"));
    preset("inline_table_multiline_array", "[planet]\nalbedo = [\n  0.1,\n  2,\n  0.3,\n]\n",
           Expect::reject(4, "planet.albedo[1]", "out of range"));
    preset("int_spellings", "[terrain]\ngrid_size = 0x20\nseed = 0o17\nnoise_octaves = 0b101\n[ocean]\nwave_count = 1_0\n",
           Expect::accept());
    preset("int_as_float", "[terrain]\ngrid_size = 32.0\n[ocean]\ngrid_size = 1e1\n", Expect::accept());
    preset("float_spellings", "[planet]\nradius_km = +6_360.0\n[sun]\nirradiance = [1E0, 1.5e+0, 2_0.0e-1]\n",
           Expect::accept());
    preset("strings", "name = 'literal \\ name'\ndescription = \"\"\"\nmulti\nline \\u00e9 \\t\"\"\"\n",
           Expect::accept());
    preset("string_escapes_bad", "name = \"bad \\q escape\"\n", Expect::reject(1, "", "TOML syntax error"));
    preset("empty_wave_list", "[ocean]\nwave = []\n", Expect::accept());  // no waves: must write back as such
    preset("wave_list_of_numbers", "[ocean]\nwave = [1, 2]\n", Expect::reject(2, "ocean.wave[0]", "expected a table"));
    preset("comment_only", "# nothing but a comment\n\n   \n", Expect::accept());
    preset("whitespace_only", " \t \n\n", Expect::accept());
    make.add(FileKind::View, "beach", "view_inline_values",
             "latitude_deg = 1e1\nlongitude_deg = -0x10\naltitude_m = 2_000\nfov_deg = +90\n", Expect::reject(2));
    make.add(FileKind::View, "beach", "view_spellings",
             "latitude_deg = 1e1\nlongitude_deg = -16\naltitude_m = 2_000\nfov_deg = +90\n", Expect::accept());
    make.add(FileKind::View, "beach", "view_sun_alone", "latitude_deg = 1\nlongitude_deg = 2\naltitude_m = 3\nsun_azimuth_deg = 4\n",
             Expect::reject(4, "", "sun_elevation_deg"));
    make.add(FileKind::View, "beach", "view_table_key", "latitude_deg = 1\nlongitude_deg = 2\naltitude_m = { m = 3 }\n",
             Expect::reject(3, "altitude_m", "expected a number"));
}

std::string keyType(const Scene& scene, const std::string& section, const std::string& key) {
    Scene copy = scene;
    for (const ParamSpec& spec : sceneParams()) {
        if (spec.section != section || spec.key != key) continue;
        const ParamRef ref = spec.field(copy);
        if (std::holds_alternative<bool*>(ref)) return "bool";
        if (std::holds_alternative<int*>(ref)) return "int";
        if (std::holds_alternative<glm::dvec3*>(ref)) return "vec3";
        return "number";
    }
    return (section.empty() && (key == "name" || key == "description")) ? "string" : "";
}

const std::vector<std::string>& presetNames() {
    static const std::vector<std::string> names = {"earth", "mars", "hazy"};
    return names;
}

std::vector<std::string> viewNames() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(kAssets / "views"))
        if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Every case, in a fixed order from a fixed seed.
const std::vector<FuzzCase>& fuzzCases() {
    static const std::vector<FuzzCase> cases = [] {
        std::vector<FuzzCase> out;
        CaseMaker make(out);
        Rng rng(0x5EED12u);
        for (const std::string& name : presetNames()) {
            const std::string text = readText(kAssets / "presets" / (name + ".toml"));
            addBlindMutations(make, FileKind::Preset, name, text, rng, name == "earth" ? 30 : 15);
            addWholeFileMutations(make, FileKind::Preset, name, text, rng);
            addStructureMutations(make, FileKind::Preset, name, text, rng);
            // Wrong types and extremes on keys picked at random.
            std::vector<std::pair<KeyLine, std::string>> typed;
            std::vector<KeyLine> numeric;
            for (const KeyLine& k : keyLines(text)) {
                const std::string type = keyType(Scene{}, k.section, k.key);
                if (!type.empty()) typed.push_back({k, type});
                if (type == "number" || type == "int" ) numeric.push_back(k);
            }
            std::vector<std::pair<KeyLine, std::string>> picked;
            for (int i = 0; i < (name == "earth" ? 16 : 6); ++i) picked.push_back(typed[rng.below(typed.size())]);
            addWrongTypes(make, FileKind::Preset, name, text, picked, rng);
            addExtremes(make, FileKind::Preset, name, text, numeric, rng, name == "earth" ? 30 : 10);
            if (name == "earth") {  // earth.toml lists every parameter
                addPresetRangeEdges(make, name, text, rng);
                addWaveLists(make, name, text);
                addSpellings(make, name);
                addSectionCorners(make, name, text);
            }
        }
        for (const std::string& name : viewNames()) {
            const std::string text = readText(kAssets / "views" / (name + ".toml"));
            addBlindMutations(make, FileKind::View, name, text, rng, 5);
            std::vector<std::pair<KeyLine, std::string>> typed;
            std::vector<KeyLine> numeric;
            for (const KeyLine& k : keyLines(text)) {
                typed.push_back({k, k.key == "description" ? "string" : "number"});
                if (k.key != "description") numeric.push_back(k);
            }
            addWrongTypes(make, FileKind::View, name, text, {typed[rng.below(typed.size())]}, rng);
            addExtremes(make, FileKind::View, name, text, numeric, rng, 3);
            if (name == "beach" || name == "space") {
                addWholeFileMutations(make, FileKind::View, name, text, rng);
                addStructureMutations(make, FileKind::View, name, text, rng);
                addViewRangeEdges(make, name, text);
            }
        }
        return out;
    }();
    return cases;
}

// ---- loading a case and checking what it gave ----

struct Outcome {
    std::optional<InputError> error;
    std::optional<PresetLoad> preset;
    std::optional<View> view;
    std::vector<std::string> warnings;
};

Outcome load(const FuzzCase& c, const fs::path& file) {
    Outcome o;
    try {
        if (c.kind == FileKind::Preset) {
            o.preset = loadPreset(file);
            o.warnings = o.preset->warnings;
        } else {
            o.view = loadView(file, &o.warnings);
        }
    } catch (const InputError& e) {
        o.error = e;
    }
    return o;
}

// The dotted path of a field without a component index: "planet.albedo[1]" -> "planet.albedo".
std::string withoutIndex(std::string field) {
    const std::size_t bracket = field.find('[');
    return bracket == std::string::npos ? field : field.substr(0, bracket);
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// The invariants of a rejection: file:line: (or file: for a key the file does not hold).
::testing::AssertionResult rejectionIsLocated(const InputError& e, const fs::path& file, const std::string& text) {
    const std::string what = e.what();
    if (e.file != file.string()) return ::testing::AssertionFailure() << "error names the file '" << e.file << "': " << what;
    if (e.line > 0) {
        if (!startsWith(what, file.string() + ":" + std::to_string(e.line) + ": "))
            return ::testing::AssertionFailure() << "message does not start with file:line: " << what;
        const int lines = static_cast<int>(splitLines(text).size()) + 1;
        if (e.line > lines) return ::testing::AssertionFailure() << "line past the end (" << lines << "): " << what;
        return ::testing::AssertionSuccess();
    }
    if (!startsWith(what, file.string() + ": "))
        return ::testing::AssertionFailure() << "message does not start with file: " << what;
    // No line: only for a key the file does not hold (or holds where toml++ keeps no line).
    if (e.field.empty()) return ::testing::AssertionFailure() << "no line and no field: " << what;
    std::optional<toml::table> root;
    try {
        root = toml::parse(std::string_view(text), std::string_view("x"));
    } catch (const toml::parse_error&) {
        return ::testing::AssertionFailure() << "a file that does not parse reported without a line: " << what;
    }
    const toml::node* node = root->at_path(withoutIndex(e.field)).node();
    if (node && node->source().begin.line > 0)
        return ::testing::AssertionFailure() << "the file holds '" << e.field << "' at line "
                                             << node->source().begin.line << " but the message names none: " << what;
    return ::testing::AssertionSuccess();
}

// Exact comparison of every parameter and the waves.
bool sameScene(const Scene& a, const Scene& b) {
    Scene ca = a, cb = b;
    for (const ParamSpec& spec : sceneParams()) {
        const ParamRef ra = spec.field(ca), rb = spec.field(cb);
        bool equal = false;
        if (auto* p = std::get_if<double*>(&ra)) equal = **p == *std::get<double*>(rb) && std::signbit(**p) == std::signbit(*std::get<double*>(rb));
        if (auto* p = std::get_if<int*>(&ra)) equal = **p == *std::get<int*>(rb);
        if (auto* p = std::get_if<bool*>(&ra)) equal = **p == *std::get<bool*>(rb);
        if (auto* p = std::get_if<glm::dvec3*>(&ra)) equal = **p == *std::get<glm::dvec3*>(rb);
        if (!equal) return false;
    }
    return a.waves.size() == b.waves.size();
}

// The checks of one case; returns false (with failures added) when it broke a rule.
void checkCase(const FuzzCase& c, const fs::path& file, const Outcome& o) {
    SCOPED_TRACE(c.id);
    const Expect& x = c.expect;
    if (o.error) {
        const InputError& e = *o.error;
        EXPECT_TRUE(rejectionIsLocated(e, file, c.text));
        EXPECT_NE(x.verdict, Expect::Accept) << "expected to load: " << e.what();
        if (x.verdict == Expect::InsideRange) {
            // A value inside its range may only break a rule between fields, blamed where it is.
            EXPECT_EQ(c.kind, FileKind::Preset) << e.what();
            EXPECT_TRUE(isCrossFieldRule(e.field)) << "an in-range value refused: " << e.what();
            EXPECT_FALSE(contains(e.what(), "out of range")) << e.what();
        }
        if (x.verdict == Expect::Reject) {
            if (x.line > 0) {
                EXPECT_EQ(e.line, x.line) << e.what();
            }
            if (!x.field.empty()) {
                EXPECT_EQ(e.field, x.field) << e.what();
            }
            if (!x.text.empty()) {
                EXPECT_TRUE(contains(e.what(), x.text)) << "wanted '" << x.text << "' in: " << e.what();
            }
        }
        return;
    }
    EXPECT_NE(x.verdict, Expect::Reject) << "expected an error, but it loaded";
    for (const std::string& w : o.warnings) {
        const std::string prefix = file.string() + ":";
        EXPECT_TRUE(startsWith(w, prefix) && w.size() > prefix.size() && std::isdigit(static_cast<unsigned char>(w[prefix.size()])))
            << "warning without file:line: " << w;
    }
    if (x.verdict == Expect::Accept && !x.text.empty()) {
        const bool found = std::any_of(o.warnings.begin(), o.warnings.end(), [&](const std::string& w) { return contains(w, x.text); });
        EXPECT_TRUE(found) << "no warning holding '" << x.text << "' among " << o.warnings.size();
    }
    if (o.preset) {
        EXPECT_TRUE(validateScene(o.preset->scene).empty());
        // What the explorer's "save preset" would write must load back as the same scene.
        try {
            const std::string written = presetToToml(o.preset->scene, o.preset->name, o.preset->description);
            const PresetLoad back = parsePreset(written, "written.toml");
            EXPECT_TRUE(sameScene(back.scene, o.preset->scene)) << "the written preset reads back differently";
            EXPECT_TRUE(back.warnings.empty());
        } catch (const InputError& e) {
            ADD_FAILURE() << "the written preset does not load: " << e.what();
        }
    }
}

// Each test's own folder under PLANET_TEST_OUT (ctest runs the tests of this file side by side).
fs::path testFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return kOut / (std::string(info->test_suite_name()) + "." + info->name());
}

// Writes every case to its file (once per process) and loads it.
struct LoadedCase {
    const FuzzCase* c;
    fs::path file;
    Outcome outcome;
};

std::vector<LoadedCase> loadAllCases() {
    const fs::path folder = testFolder() / "cases";
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::vector<LoadedCase> loaded;
    for (const FuzzCase& c : fuzzCases()) {
        const fs::path file = folder / (c.id + ".toml");
        writeText(file, c.text);
        loaded.push_back({&c, file, load(c, file)});
    }
    return loaded;
}

TEST(FuzzAssets, MutatedFilesAreRefusedWithFileAndLineOrLoad) {
    const Clock::time_point start = Clock::now();
    const std::vector<LoadedCase> loaded = loadAllCases();
    int rejected = 0, accepted = 0, presets = 0;
    std::map<std::string, int> byField;
    for (const LoadedCase& l : loaded) {
        checkCase(*l.c, l.file, l.outcome);
        (l.outcome.error ? rejected : accepted) += 1;
        presets += l.c->kind == FileKind::Preset;
    }
    std::printf("fuzz: %zu cases (%d presets, %zu views): %d refused, %d loaded, in %.2f s\n", loaded.size(), presets,
                loaded.size() - presets, rejected, accepted, secondsSince(start));
    // The mix the seed gives: a few hundred cases, both outcomes well represented.
    EXPECT_GE(loaded.size(), 400u);
    EXPECT_GE(rejected, 150);
    EXPECT_GE(accepted, 100);
}

// ---- the command line: a refused file fails `planet render` and leaves nothing ----

TEST(FuzzAssets, RefusedFilesFailTheCommandAndLeaveNoOutput) {
    const Clock::time_point start = Clock::now();
    const std::vector<LoadedCase> loaded = loadAllCases();
    // A data root whose views folder holds the one view under test; shaders and presets are the source's.
    const fs::path root = testFolder() / "root";
    fs::remove_all(root);
    fs::create_directories(root / "assets" / "views");
    fs::create_directory_symlink(fs::path(PLANET_SOURCE_DIR) / "shaders", root / "shaders");
    fs::create_directory_symlink(kAssets / "presets", root / "assets" / "presets");
    const fs::path work = testFolder() / "cli";
    // Every 7th refused preset and every 3rd refused view: a fixed sample across the kinds of mutation.
    int presetsRun = 0, viewsRun = 0, presetsSeen = 0, viewsSeen = 0;
    for (const LoadedCase& l : loaded) {
        if (!l.outcome.error) continue;
        const FuzzCase& c = *l.c;
        std::string args;
        std::string expected;
        if (c.kind == FileKind::Preset) {
            if (presetsSeen++ % 7 != 0) continue;
            args = "render --preset '" + l.file.string() + "'";
            expected = l.outcome.error->what();
            ++presetsRun;
        } else {
            if (viewsSeen++ % 3 != 0) continue;
            for (const auto& entry : fs::directory_iterator(root / "assets" / "views")) fs::remove(entry.path());
            const fs::path view = root / "assets" / "views" / (c.id + ".toml");
            writeText(view, c.text);
            // The message names the file where the command found it.
            const Outcome there = load(c, view);
            ASSERT_TRUE(there.error.has_value()) << c.id;
            expected = there.error->what();
            args = "render --root '" + root.string() + "' --view '" + c.id + "'";
            ++viewsRun;
        }
        SCOPED_TRACE(c.id);
        fs::remove_all(work);
        fs::create_directories(work / "out");
        const std::string command = "( cd '" + work.string() + "' && env -u DISPLAY -u WAYLAND_DISPLAY PLANET_TABLES=reduced '" PLANET_EXE "' " +
                                    args + " --size 16x16 --out out/x.png --out out/x.exr 2>stderr.txt >stdout.txt )";
        const test::ProcessResult r = test::runCommand(command);
        EXPECT_EQ(r.exitCode, 1) << r.output;
        EXPECT_EQ(readText(work / "stderr.txt"), "planet: error: " + expected + "\n");
        EXPECT_EQ(readText(work / "stdout.txt"), "");
        std::vector<std::string> left;
        for (const auto& entry : fs::recursive_directory_iterator(work / "out")) left.push_back(entry.path().string());
        EXPECT_TRUE(left.empty()) << "left behind: " << joinNames(left);
    }
    std::printf("fuzz: ran planet render on %d refused presets and %d refused views in %.2f s\n", presetsRun, viewsRun,
                secondsSince(start));
    EXPECT_GE(presetsRun, 20);
    EXPECT_GE(viewsRun, 10);
}

// ---- rendering what loads ----

// The atmosphere's tables depend on these (Atmosphere rebuilds them when any changes).
std::string atmosphereKey(const Scene& scene) {
    atmosphere::AtmosphereUniforms u = atmosphere::makeAtmosphereUniforms(atmosphere::makeAtmosphereParameters(scene));
    u.elekRayleighPhase = 0.0f;
    std::string key(reinterpret_cast<const char*>(&u), sizeof u);
    return key + std::to_string(scene.atmosphere.scattering_orders);
}

// Resolutions at small sizes, so that a frame costs about 20 ms on llvmpipe rather than 150:
// the bakes (the cloud volume, volume_size^3 voxels; the weather map; the continents map) are
// rendered at most at these sizes, always (a 512^3 volume alone takes minutes to bake on two
// cores; their extremes are parsed and range-checked, and the bakes have tests of their own);
// the two projected grids (terrain and ocean, whose vertices cost the same at any frame size)
// too, except in the cases made to test their own range, which render as loaded. Every other
// parameter renders as loaded.
void capResolutions(Scene& scene, const std::string& testedField) {
    scene.clouds.volume_size = std::min(scene.clouds.volume_size, 32);
    scene.clouds.weather_map_size = std::min(scene.clouds.weather_map_size, 16);
    scene.terrain.continent_map_size = std::min(scene.terrain.continent_map_size, 32);
    if (testedField != "terrain.grid_size") scene.terrain.grid_size = std::min(scene.terrain.grid_size, 24);
    if (testedField != "ocean.grid_size") scene.ocean.grid_size = std::min(scene.ocean.grid_size, 24);
    scene.render.temporal = false;  // a still is marched at full rate; so is every frame here, whatever the history
}

class FuzzAssetsRender : public test::GLTest {
protected:
    void SetUp() override {
        test::GLTest::SetUp();
        cache_ = testFolder() / "cache";
        fs::remove_all(cache_);  // a cache of its own, fresh: never the user's, the same work every run
        if (const char* old = std::getenv("PLANET_CACHE")) oldCache_ = old;
        ::setenv("PLANET_CACHE", (cache_ / "atmosphere").c_str(), 1);
    }
    void TearDown() override {
        if (oldCache_) ::setenv("PLANET_CACHE", oldCache_->c_str(), 1);
        else ::unsetenv("PLANET_CACHE");
        test::GLTest::TearDown();
    }
    fs::path cache_;
    std::optional<std::string> oldCache_;
};

// Renders the loaded cases whose atmosphere is (ownAtmosphere false) or is not (true) their
// preset's; returns how many it rendered.
std::size_t renderLoadedCases(bool wantOwnAtmosphere) {
    const Clock::time_point start = Clock::now();
    const std::vector<LoadedCase> loaded = loadAllCases();
    const std::vector<std::string> views = viewNames();
    std::map<std::string, View> shippedViews;
    for (const std::string& v : views) shippedViews[v] = loadView(kAssets / "views" / (v + ".toml"));
    std::map<std::string, std::string> baseAtmosphere;  // preset name -> key
    for (const std::string& p : presetNames())
        baseAtmosphere[p] = atmosphereKey(loadPreset(kAssets / "presets" / (p + ".toml")).scene);
    const Scene earth = loadPreset(kAssets / "presets" / "earth.toml").scene;

    struct Job {
        const FuzzCase* c;
        Scene scene;
        View view;
        std::string atmosphere;
    };
    // What is rendered, at 16x16 with the reduced tables (the smallest --tables gives), with
    // the resolutions of capResolutions: every loaded case whose atmosphere is its preset's
    // (they share one set of tables: about 20 ms a frame on llvmpipe), and every loaded case
    // made to test a value (range ends, extreme numbers, section corners, spellings, waves),
    // each atmosphere of theirs with tables of its own (0.6-1.5 s to precompute, 4 s with 10
    // scattering orders); of the blind mutations (truncations, flips, lost or moved lines)
    // that change the atmosphere, every 4th in case order. A case that loads to the scene and
    // view of one already rendered is not rendered again. Measured on the 2-core machine
    // (llvmpipe), with the machine shared with other builds (load 5): the preset's atmosphere,
    // 212 frames in 3 atmospheres, 11 s; atmospheres of their own, 39 frames in 37
    // atmospheres, 28 s of CPU, 60 s of wall time.
    std::vector<Job> jobs;
    int loadedCount = 0, skipped = 0, blindOther = 0, same = 0;  // loaded: of the half this call renders
    std::set<std::string> rendered;
    for (const LoadedCase& l : loaded) {
        if (l.outcome.error) continue;
        const FuzzCase& c = *l.c;
        Job job{&c, c.kind == FileKind::Preset ? l.outcome.preset->scene : earth, {}, ""};
        job.view = c.kind == FileKind::View ? *l.outcome.view : shippedViews.at(views[jobs.size() % views.size()]);
        job.atmosphere = atmosphereKey(job.scene);
        const bool ownAtmosphere = job.atmosphere != baseAtmosphere.at(c.kind == FileKind::Preset ? c.base : "earth");
        if (ownAtmosphere != wantOwnAtmosphere) continue;
        ++loadedCount;
        const bool blind = c.expect.verdict == Expect::Any;
        if (ownAtmosphere && blind && blindOther++ % 4 != 0) {
            ++skipped;
            continue;
        }
        capResolutions(job.scene, c.expect.field);
        // A case that loads to a scene and view already rendered (a flipped bit in a comment,
        // CRLF, an unknown key) would render the same pixels again.
        const View& v = job.view;
        std::string key = presetToToml(job.scene, "", "");
        for (const double x : {v.latitude_deg, v.longitude_deg, v.altitude_m, v.heading_deg, v.pitch_deg, v.fov_deg,
                               v.sun_elevation_deg.value_or(1e300), v.sun_azimuth_deg.value_or(1e300)})
            key += " " + formatNumber(x);
        if (!rendered.insert(key).second) {
            ++same;
            continue;
        }
        jobs.push_back(std::move(job));
    }
    // Grouped by atmosphere, in a stable order: one renderer, one set of tables per group.
    std::stable_sort(jobs.begin(), jobs.end(), [](const Job& a, const Job& b) { return a.atmosphere < b.atmosphere; });

    const glm::ivec2 size(16, 16);
    Session base;  // its copies share one continents map with the renderer
    std::unique_ptr<Renderer> renderer;
    std::string current;
    int groups = 0, bad = 0;
    for (const Job& job : jobs) {
        SCOPED_TRACE(job.c->id + " from view '" + job.view.name + "'");
        if (!renderer || job.atmosphere != current) {
            renderer.reset();
            renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced(),
                                                  base.continents);
            current = job.atmosphere;
            ++groups;
        }
        Session s = base;
        s.scene = job.scene;
        s.presetScene = job.scene;
        applyView(job.view, s);
        renderer->render(s.scene, s.camera, size);
        const ImageRGBAF hdr = readTextureRGBAF(renderer->targets().hdr(), size.x, size.y);
        if (!test::allFinite(hdr)) {
            int count = 0;
            for (std::size_t i = 0; i < hdr.pixels.size(); i += 4)
                count += !(std::isfinite(hdr.pixels[i]) && std::isfinite(hdr.pixels[i + 1]) &&
                           std::isfinite(hdr.pixels[i + 2]) && std::isfinite(hdr.pixels[i + 3]));
            ADD_FAILURE() << count << " of " << size.x * size.y << " pixels not finite";
            ++bad;
        }
    }
    std::printf("fuzz: %d loaded cases %s, %zu rendered at %dx%d in %d atmosphere groups, %d the same as one "
                "rendered, %d not rendered (blind mutations of the atmosphere beyond every 4th), %d with non-finite "
                "pixels; %.1f s\n",
                loadedCount, wantOwnAtmosphere ? "with an atmosphere of their own" : "with their preset's atmosphere",
                jobs.size(), size.x, size.y, groups, same, skipped, bad, secondsSince(start));
    return jobs.size();
}

// The two halves are two tests so that ctest runs them side by side.
TEST_F(FuzzAssetsRender, LoadedFilesRenderFinitePixels) { EXPECT_GE(renderLoadedCases(false), 150u); }

TEST_F(FuzzAssetsRender, LoadedFilesWithAnAtmosphereOfTheirOwnRenderFinitePixels) {
    EXPECT_GE(renderLoadedCases(true), 30u);
}

}  // namespace
}  // namespace planet
