// Presets: a Scene as a TOML file, read and written by walking sceneParams().
//
// A preset has an optional top-level `name` and `description` (strings) and
// one table per parameter section:
//
//     name = "Earth"
//     [planet]
//     radius_km = 6360.0
//     albedo = [0.2, 0.24, 0.16]
//
// Reading starts from Scene{} so absent keys keep their defaults; present
// keys are type- and range-checked (every component of a vector) and a bad
// one is an InputError naming file, line and key path. After all keys are
// read the scene must pass validateScene (scene_params.h: cross-field rules
// such as atmosphere.top_radius_km > planet.radius_km); the first problem is
// an InputError at the blamed key's line (0 when the file leaves it default).
// Keys and tables the parameter table does not know are not errors: each
// becomes a warning ("earth.toml:7: unknown key 'planet.radius' (ignored);
// did you mean 'planet.radius_km'?") so an old binary can still read a newer
// preset.
//
// The ocean's waves (Scene::waves) are the one list in a preset: [[ocean.wave]] tables
// (scene/preset_waves.h) replace the set the [ocean] parameters generate; without them
// the waves are generated on load, and only waves that differ from that set are written.
//
// Writing emits every parameter, grouped by section, each with a
// "# help (unit, range)" comment, and numbers in the shortest form that reads
// back bit for bit, so parsePreset(presetToToml(s)) reproduces s exactly.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"
#include "scene/toml_error.h"

namespace planet {

struct PresetLoad {
    Scene scene;
    std::string name;         // top-level `name`, "" when absent
    std::string description;  // top-level `description`, "" when absent
    std::vector<std::string> warnings;  // unknown keys, one "file:line: ..." line each
};

// Parses preset text; sourceName is used in messages. Throws InputError.
PresetLoad parsePreset(std::string_view tomlText, const std::string& sourceName);

// Reads and parses a preset file. Throws InputError (also for a missing file).
PresetLoad loadPreset(const std::filesystem::path& path);

// An existing file path is returned as is; otherwise assetsDir/presets/<name>.toml.
// Throws InputError listing the available preset names when neither exists.
std::filesystem::path resolvePreset(const std::string& nameOrPath, const std::filesystem::path& assetsDir);

// Stems of the *.toml files in assetsDir/presets, sorted ("earth", "mars", ...).
std::vector<std::string> availablePresets(const std::filesystem::path& assetsDir);

// Every parameter of the table as TOML text (see the file header).
std::string presetToToml(const Scene& scene, const std::string& name, const std::string& description);

// presetToToml written with writeFileAtomic; throws FileError on failure,
// leaving any existing file untouched. A scene validateScene rejects is not
// written: InputError naming the path and the blamed field.
void savePreset(const Scene& scene, const std::filesystem::path& path, const std::string& name,
                const std::string& description);

}  // namespace planet
