// Presets: reading (validate, warn on unknown keys) and writing (commented,
// round-trippable TOML) by walking the parameter table. See preset.h.
//
// Organisation: the reader first checks the file's shape (top-level keys,
// sections, unknown keys), then walks sceneParams() and reads each present
// key into a Scene{} and finally checks the cross-field rules of
// validateScene; the writer walks the same table section by section and
// refuses a scene validateScene rejects.
#include "scene/preset.h"

#include <algorithm>
#include <utility>
#include <variant>

#include "ocean/wave_spectrum.h"
#include "scene/preset_waves.h"
#include "scene/scene_params.h"
#include "util/file_util.h"

namespace planet {

namespace {

namespace fs = std::filesystem;

template <class... Fs>
struct Overloaded : Fs... {
    using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;  // clang 14 deduces no aggregate's arguments without it

// Top-level keys a preset may hold besides the parameter sections.
const std::vector<std::string>& headerKeys() {
    static const std::vector<std::string> keys = {"name", "description"};
    return keys;
}

std::vector<std::string> sectionNames() {
    std::vector<std::string> sections;
    for (const ParamSpec& spec : sceneParams())
        if (std::find(sections.begin(), sections.end(), spec.section) == sections.end())
            sections.push_back(spec.section);
    return sections;
}

bool isSection(const std::string& name) {
    const std::vector<std::string> sections = sectionNames();
    return std::find(sections.begin(), sections.end(), name) != sections.end();
}

bool isParam(const std::string& section, const std::string& key) {
    const auto& table = sceneParams();
    return std::any_of(table.begin(), table.end(),
                       [&](const ParamSpec& s) { return s.section == section && s.key == key; });
}

// Every name a misspelt key might have meant: parameter paths, sections, header keys.
std::vector<std::string> knownNames() {
    std::vector<std::string> names = headerKeys();
    for (const std::string& section : sectionNames()) names.push_back(section);
    for (const ParamSpec& spec : sceneParams()) names.push_back(spec.path());
    return names;
}

int keyLine(const toml::key& key, const toml::node& value) {
    const int line = static_cast<int>(key.source().begin.line);
    return line > 0 ? line : sourceLine(value);
}

using Warnings = std::vector<std::pair<int, std::string>>;  // (line, text), sorted by line at the end

void checkSection(const std::string& section, const toml::node& node, const std::string& file, Warnings& warnings) {
    const toml::table* table = node.as_table();
    if (!table) {
        throw InputError(file, sourceLine(node), section, "expected a table [" + section + "], got " + typeName(node));
    }
    for (auto&& [key, value] : *table) {
        const std::string name(key.str());
        if (isParam(section, name)) continue;
        if (section == "ocean" && name == "wave") continue;  // the [[ocean.wave]] list (preset_waves.h)
        const int line = keyLine(key, value);
        warnings.emplace_back(line, unknownKeyWarning(file, line, section + "." + name, knownNames()));
    }
}

// Checks the file's shape; returns the unknown-key warnings in line order.
std::vector<std::string> checkShape(const toml::table& root, const std::string& file) {
    Warnings warnings;
    for (auto&& [key, value] : root) {
        const std::string name(key.str());
        if (isSection(name)) {
            checkSection(name, value, file, warnings);
        } else if (std::find(headerKeys().begin(), headerKeys().end(), name) == headerKeys().end()) {
            const int line = keyLine(key, value);
            warnings.emplace_back(line, unknownKeyWarning(file, line, name, knownNames()));
        }
    }
    std::stable_sort(warnings.begin(), warnings.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::string> texts;
    for (auto& warning : warnings) texts.push_back(std::move(warning.second));
    return texts;
}

void readVec3InRange(const ParamSpec& spec, const toml::node& node, const std::string& file, glm::dvec3& out) {
    const glm::dvec3 v = readVec3(node, file, spec.path());
    for (int i = 0; i < 3; ++i) {
        const toml::node& element = *node.as_array()->get(static_cast<size_t>(i));
        const std::string field = spec.path() + "[" + std::to_string(i) + "]";
        checkRange(v[i], spec.min, spec.max, spec.unit, locate(element, file, field));
    }
    out = v;
}

// Reads one parameter into the scene field the table row points at.
void readParam(const ParamSpec& spec, const toml::node& node, const std::string& file, Scene& scene) {
    const std::string field = spec.path();
    const InputLocation where = locate(node, file, field);
    std::visit(Overloaded{
                   [&](double* p) {
                       const double v = readNumber(node, file, field);
                       checkRange(v, spec.min, spec.max, spec.unit, where);
                       *p = v;
                   },
                   [&](int* p) {
                       const int v = readInt(node, file, field);
                       checkRange(v, spec.min, spec.max, spec.unit, where);
                       *p = v;
                   },
                   [&](glm::dvec3* p) { readVec3InRange(spec, node, file, *p); },
                   [&](bool* p) { *p = readBool(node, file, field); },
               },
               spec.field(scene));
}

// ---- writing ----

std::string tomlQuoted(const std::string& text) {
    static const char* hex = "0123456789ABCDEF";
    std::string out = "\"";
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') out += std::string("\\") + c;
        else if (c == '\n') out += "\\n";
        else if (c == '\t') out += "\\t";
        else if (u < 0x20 || u == 0x7F) out += std::string("\\u00") + hex[u >> 4] + hex[u & 15];
        else out += c;
    }
    return out + "\"";
}

// A TOML float that reads back as exactly this double: shortest digits, with
// ".0" added where the shortest form would read as an integer.
std::string tomlFloat(double value) {
    std::string text = formatNumber(value);
    if (text.find_first_of(".eni") == std::string::npos) text += ".0";  // not 1e5, nan, inf
    return text;
}

std::string valueText(const ParamRef& ref) {
    return std::visit(Overloaded{
                          [](double* p) { return tomlFloat(*p); },
                          [](int* p) { return std::to_string(*p); },
                          [](glm::dvec3* p) {
                              // Appended piecewise: "[" + temporary trips GCC 12's -Wrestrict false positive at -O3.
                              std::string text = "[";
                              text += tomlFloat(p->x) + ", " + tomlFloat(p->y) + ", " + tomlFloat(p->z);
                              return text + "]";
                          },
                          [](bool* p) { return std::string(*p ? "true" : "false"); },
                      },
                      ref);
}

// "# help (unit, [min, max])", one comment line per help line.
std::string commentFor(const ParamSpec& spec, const ParamRef& ref) {
    std::string range;
    if (std::holds_alternative<bool*>(ref)) {
        range = "true or false";
    } else {
        range = (spec.unit.empty() ? "dimensionless" : spec.unit) + ", ";
        if (std::holds_alternative<int*>(ref)) range += "integer, ";
        range += "[" + formatNumber(spec.min) + ", " + formatNumber(spec.max) + "]";
        if (std::holds_alternative<glm::dvec3*>(ref)) range += " per component";
    }
    std::string help = spec.help;
    for (size_t at = help.find('\n'); at != std::string::npos; at = help.find('\n', at + 3)) {
        help.replace(at, 1, "\n# ");
    }
    return "# " + help + " (" + range + ")\n";
}

}  // namespace

PresetLoad parsePreset(std::string_view tomlText, const std::string& sourceName) {
    const toml::table root = parseToml(tomlText, sourceName);
    PresetLoad out;
    out.warnings = checkShape(root, sourceName);
    if (const toml::node* n = root.get("name")) out.name = readString(*n, sourceName, "name");
    if (const toml::node* n = root.get("description")) out.description = readString(*n, sourceName, "description");
    for (const ParamSpec& spec : sceneParams()) {
        const toml::table* section = root[spec.section].as_table();
        const toml::node* node = section ? section->get(spec.key) : nullptr;
        if (node) readParam(spec, *node, sourceName, out.scene);
    }
    // The waves: the preset's own list, or generated from the [ocean] parameters.
    if (const toml::node* list = root.at_path("ocean.wave").node())
        out.scene.waves = readWaveList(*list, sourceName);
    else
        out.scene.waves = ocean::generateWaves(out.scene.ocean);
    const std::vector<SceneProblem> problems = validateScene(out.scene);
    if (!problems.empty()) {
        // Blame the field's line when the file sets it; a default it left alone has none.
        const SceneProblem& first = problems.front();
        const toml::node* node = root.at_path(first.field).node();
        throw InputError(sourceName, node ? sourceLine(*node) : 0, first.field, first.message);
    }
    return out;
}

PresetLoad loadPreset(const std::filesystem::path& path) { return parsePreset(readInputFile(path), path.string()); }

std::vector<std::string> availablePresets(const std::filesystem::path& assetsDir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(assetsDir / "presets", ec))
        if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::filesystem::path resolvePreset(const std::string& nameOrPath, const std::filesystem::path& assetsDir) {
    std::error_code ec;
    const fs::path direct(nameOrPath);
    if (!nameOrPath.empty() && fs::exists(direct, ec)) {
        // Given as a path: say why it cannot be read rather than that no such name exists.
        if (const std::string why = whyNotReadableFile(direct); !why.empty())
            throw InputError("", 0, "", "preset '" + nameOrPath + "': " + why);
        return direct;
    }
    const fs::path named = assetsDir / "presets" / (nameOrPath + ".toml");
    if (fs::is_regular_file(named, ec)) return named;
    throw InputError("", 0, "",
                     "unknown preset '" + nameOrPath + "': no such file, and no " + named.string() +
                         "; available presets: " + joinNames(availablePresets(assetsDir)));
}

std::string presetToToml(const Scene& scene, const std::string& name, const std::string& description) {
    Scene copy = scene;  // the table's accessors take a mutable Scene
    std::string text = "# Planet preset: every parameter of the scene, grouped by section.\n"
                       "# Absent keys take the built-in (Earth) defaults; unknown keys are ignored with a warning.\n";
    text += "name = " + tomlQuoted(name) + "\n";
    text += "description = " + tomlQuoted(description) + "\n";
    // Waves the [ocean] parameters would not generate (edited, or read from a list) are listed.
    const bool ownWaves = !sameWaves(scene.waves, ocean::generateWaves(scene.ocean));
    for (const std::string& section : sectionNames()) {
        text += "\n[" + section + "]\n";
        for (const ParamSpec& spec : sceneParams()) {
            if (spec.section != section) continue;
            const ParamRef ref = spec.field(copy);
            text += commentFor(spec, ref) + spec.key + " = " + valueText(ref) + "\n";
        }
        // No waves at all (every wave removed) where the parameters generate some: an empty list,
        // which only a key inside [ocean] can say ([[ocean.wave]] tables hold one wave each).
        if (section == "ocean" && ownWaves && scene.waves.empty())
            text += "# No waves (an empty list replaces the generated set).\nwave = []\n";
    }
    if (ownWaves && !scene.waves.empty()) {
        text += "\n# The individual waves (they replace the set the [ocean] parameters would generate).\n";
        text += waveListToToml(scene.waves);
    }
    return text;
}

void savePreset(const Scene& scene, const std::filesystem::path& path, const std::string& name,
                const std::string& description) {
    // A preset that would not load back is not written; the file (no line yet) is the target.
    const std::vector<SceneProblem> problems = validateScene(scene);
    if (!problems.empty()) {
        const SceneProblem& first = problems.front();
        throw InputError(path.string(), 0, first.field, first.message);
    }
    writeFileAtomic(path, presetToToml(scene, name, description));
}

}  // namespace planet
