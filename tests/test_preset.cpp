// Tests for presets (scene/preset.h) and the TOML input helpers (scene/toml_error.h):
// the shipped presets, defaults, range/type/syntax errors with file, line and
// field, unknown-key warnings, the exact write/read round trip and atomic saves.
#include <gtest/gtest.h>

#include "test_util.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <unistd.h>

#include "scene/preset.h"
#include "scene/scene_params.h"
#include "scene/toml_error.h"
#include "util/file_util.h"

namespace planet {
namespace {

namespace fs = std::filesystem;

const fs::path kAssets = fs::path(PLANET_SOURCE_DIR) / "assets";

// Exact (bitwise-value) comparison of every parameter in the table.
::testing::AssertionResult sameScene(const Scene& a, const Scene& b) {
    Scene ca = a, cb = b;
    for (const ParamSpec& spec : sceneParams()) {
        const ParamRef ra = spec.field(ca), rb = spec.field(cb);
        bool equal = false;
        if (auto* p = std::get_if<double*>(&ra)) equal = **p == *std::get<double*>(rb);
        if (auto* p = std::get_if<int*>(&ra)) equal = **p == *std::get<int*>(rb);
        if (auto* p = std::get_if<bool*>(&ra)) equal = **p == *std::get<bool*>(rb);
        if (auto* p = std::get_if<glm::dvec3*>(&ra)) equal = **p == *std::get<glm::dvec3*>(rb);
        if (!equal) return ::testing::AssertionFailure() << spec.path() << " differs";
    }
    return ::testing::AssertionSuccess();
}

using test::contains;
using test::expectInputError;

// A fresh, empty folder under the system temp dir, removed at the end of the test.
struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& tag) {
        path = fs::temp_directory_path() / ("planet_" + tag + "_" + std::to_string(::getpid()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::permissions(path, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(path, ec);
    }
};

TEST(Preset, ShippedPresetsLoadWithoutWarnings) {
    for (const char* name : {"earth", "mars", "hazy"}) {
        const PresetLoad load = loadPreset(resolvePreset(name, kAssets));
        EXPECT_TRUE(load.warnings.empty()) << name << ": " << joinNames(load.warnings);
        EXPECT_FALSE(load.name.empty()) << name;
        EXPECT_FALSE(load.description.empty()) << name;
    }
    EXPECT_EQ(availablePresets(kAssets), (std::vector<std::string>{"earth", "hazy", "mars"}));
}

TEST(Preset, EarthPresetIsTheDefaultsWithEveryParameter) {
    const fs::path path = kAssets / "presets" / "earth.toml";
    const PresetLoad load = loadPreset(path);
    EXPECT_EQ(load.name, "Earth");
    EXPECT_TRUE(sameScene(load.scene, Scene{}));
    const toml::table root = parseTomlFile(path);
    for (const ParamSpec& spec : sceneParams())
        EXPECT_TRUE(root.at_path(spec.path()).node() != nullptr) << spec.path() << " missing from earth.toml";
}

TEST(Preset, MarsAndHazyPresetValues) {
    const Scene mars = loadPreset(kAssets / "presets" / "mars.toml").scene;
    const Scene earth;
    EXPECT_EQ(mars.planet.radius_km, 3389.5);
    EXPECT_EQ(mars.planet.albedo, glm::dvec3(0.45, 0.28, 0.17));
    EXPECT_EQ(mars.sun.angular_radius_rad, 0.003075);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(mars.sun.irradiance[i], 0.43 * earth.sun.irradiance[i], 1e-12);
    const Scene hazy = loadPreset(kAssets / "presets" / "hazy.toml").scene;
    EXPECT_EQ(hazy.planet.radius_km, 6360.0);
    EXPECT_GT(hazy.planet.albedo.x, earth.planet.albedo.x);  // pale
}

TEST(Preset, AbsentKeysKeepDefaults) {
    const PresetLoad empty = parsePreset("", "empty.toml");
    EXPECT_TRUE(sameScene(empty.scene, Scene{}));
    EXPECT_TRUE(empty.warnings.empty());
    EXPECT_EQ(empty.name, "");

    const PresetLoad load = parsePreset("[planet]\nradius_km = 3000\n", "small.toml");  // integer accepted
    Scene expected;
    expected.planet.radius_km = 3000.0;
    EXPECT_TRUE(sameScene(load.scene, expected));
}

TEST(Preset, OutOfRangeNamesFileLineAndField) {
    const std::string text = "name = \"x\"\n[planet]\n\nradius_km = -5\n";
    const InputError e = expectInputError([&] { parsePreset(text, "assets/presets/earth.toml"); });
    EXPECT_EQ(e.file, "assets/presets/earth.toml");
    EXPECT_EQ(e.line, 4);
    EXPECT_EQ(e.field, "planet.radius_km");
    EXPECT_EQ(std::string(e.what()),
              "assets/presets/earth.toml:4: planet.radius_km: value -5 is out of range [1, 100000] km");
}

TEST(Preset, VectorComponentOutOfRangeNamesItsLine) {
    const std::string text = "[planet]\nalbedo = [\n  0.2,\n  1.5,\n  0.1,\n]\n";
    const InputError e = expectInputError([&] { parsePreset(text, "p.toml"); });
    EXPECT_EQ(e.line, 4);
    EXPECT_TRUE(contains(e.what(), "p.toml:4: planet.albedo")) << e.what();
    EXPECT_TRUE(contains(e.what(), "1.5")) << e.what();
    // NaN is never in range.
    EXPECT_THROW(parsePreset("[sun]\nirradiance = [1, nan, 1]\n", "p.toml"), InputError);
}

TEST(Preset, WrongTypesNameTheLine) {
    const InputError str = expectInputError([] { parsePreset("[render]\n\nexposure = \"bright\"\n", "t.toml"); });
    EXPECT_EQ(str.line, 3);
    EXPECT_EQ(str.field, "render.exposure");
    EXPECT_TRUE(contains(str.what(), "t.toml:3: render.exposure: expected a number")) << str.what();

    const InputError vec = expectInputError([] { parsePreset("[sun]\nirradiance = [1.0, 2.0]\n", "t.toml"); });
    EXPECT_EQ(vec.line, 2);
    EXPECT_TRUE(contains(vec.what(), "sun.irradiance: expected an array of 3 numbers")) << vec.what();

    const InputError section = expectInputError([] { parsePreset("name = \"a\"\nplanet = 5\n", "t.toml"); });
    EXPECT_EQ(section.line, 2);
    EXPECT_TRUE(contains(section.what(), "expected a table")) << section.what();

    const InputError name = expectInputError([] { parsePreset("name = 3\n", "t.toml"); });
    EXPECT_EQ(name.line, 1);
    EXPECT_EQ(name.field, "name");
}

TEST(Preset, MalformedTomlNamesFileAndLine) {
    const std::string unclosed = "[planet]\nradius_km = 6000\nalbedo = [0.1, 0.2\n\n[sun]\n";
    const InputError e = expectInputError([&] { parsePreset(unclosed, "bad.toml"); });
    EXPECT_EQ(e.file, "bad.toml");
    EXPECT_GE(e.line, 3);  // the parser notices at or after the unclosed array
    EXPECT_TRUE(contains(e.what(), "bad.toml:" + std::to_string(e.line) + ": TOML syntax error")) << e.what();

    const InputError header = expectInputError([] { parsePreset("name = \"a\"\n[planet\n", "bad.toml"); });
    EXPECT_EQ(header.line, 2);
}

TEST(Preset, UnknownKeysWarnWithLineAndSuggestion) {
    const std::string text = "name = \"x\"\n[planet]\nradius = 5\n\n[atmosphere]\ndensity = 1\n";
    const PresetLoad load = parsePreset(text, "earth.toml");
    ASSERT_EQ(load.warnings.size(), 2u);
    EXPECT_EQ(load.warnings[0],
              "earth.toml:3: unknown key 'planet.radius' (ignored); did you mean 'planet.radius_km'?");
    EXPECT_TRUE(contains(load.warnings[1], "earth.toml:5: unknown key 'atmosphere'")) << load.warnings[1];
    EXPECT_FALSE(contains(load.warnings[1], "did you mean")) << load.warnings[1];
    EXPECT_TRUE(sameScene(load.scene, Scene{}));  // unknown keys change nothing
}

TEST(Preset, RoundTripIsExact) {
    Scene s;
    s.planet.radius_km = 6360.000000001;
    s.planet.albedo = {0.1 + 0.2, 1.0 / 3.0, 0.0};
    s.sun.latitude_deg = -89.99999999999999;
    s.sun.longitude_deg = 179.9;
    s.sun.irradiance = {100.0, 1e-300, std::nextafter(1.0, 2.0)};
    s.sun.angular_radius_rad = 0.0001;
    s.render.exposure = 2.0 / 3.0;
    const std::string description = "line one\n\"quoted\" \\ tab\t end";
    const PresetLoad load = parsePreset(presetToToml(s, "Odd \"name\"", description), "rt.toml");
    EXPECT_TRUE(sameScene(load.scene, s));
    EXPECT_TRUE(load.warnings.empty());
    EXPECT_EQ(load.name, "Odd \"name\"");
    EXPECT_EQ(load.description, description);
}

TEST(Preset, WrittenTextIsShortAndCommented) {
    Scene scene;
    scene.planet.albedo = {0.2, 0.24, 0.16};  // short decimals must stay short
    const std::string text = presetToToml(scene, "Earth", "");
    EXPECT_TRUE(contains(text, "radius_km = 6360.0\n")) << text;
    EXPECT_TRUE(contains(text, "albedo = [0.2, 0.24, 0.16]\n")) << text;
    EXPECT_TRUE(contains(text, "# Radius of the solid planet (sea level). (km, [1, 100000])\nradius_km")) << text;
    for (const ParamSpec& spec : sceneParams()) {
        EXPECT_TRUE(contains(text, "# " + spec.help)) << spec.path();
        EXPECT_TRUE(contains(text, "\n" + spec.key + " = ")) << spec.path();
    }
    EXPECT_TRUE(contains(text, "\n[sun]\n"));
}

TEST(Preset, SaveThenLoadGivesTheSameScene) {
    TempDir dir("preset_save");
    Scene s;
    s.planet.radius_km = 1234.5;
    s.render.exposure = 0.1;
    const fs::path path = dir.path / "sub" / "mine.toml";
    savePreset(s, path, "Mine", "test");
    const PresetLoad load = loadPreset(path);
    EXPECT_TRUE(sameScene(load.scene, s));
    EXPECT_EQ(load.name, "Mine");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path / "sub"), fs::directory_iterator{}), 1);  // no temp left
}

TEST(Preset, FailedSaveThrowsAndLeavesNothing) {
    TempDir dir("preset_fail");
    // A regular file where a parent folder should be: nothing can be created below it.
    const fs::path blocker = dir.path / "blocker";
    std::ofstream(blocker) << "x";
    EXPECT_THROW(savePreset(Scene{}, blocker / "p.toml", "n", "d"), FileError);
    // The target is a folder: the rename fails and the temp file must be cleaned up.
    fs::create_directories(dir.path / "taken.toml");
    EXPECT_THROW(savePreset(Scene{}, dir.path / "taken.toml", "n", "d"), FileError);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator{}), 2);  // blocker + taken.toml
    // A read-only folder (permissions do not bind root, so only checked for other users).
    if (::geteuid() != 0) {
        const fs::path locked = dir.path / "locked";
        fs::create_directories(locked);
        fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
        EXPECT_THROW(savePreset(Scene{}, locked / "p.toml", "n", "d"), FileError);
        EXPECT_TRUE(fs::is_empty(locked));
    }
}

TEST(Preset, MissingFileIsAnInputError) {
    const InputError e = expectInputError([] { loadPreset("/nonexistent/planet/none.toml"); });
    EXPECT_EQ(e.file, "/nonexistent/planet/none.toml");
    EXPECT_EQ(std::string(e.what()), "/nonexistent/planet/none.toml: file not found");
}

TEST(Preset, ResolveByNameOrPath) {
    EXPECT_EQ(resolvePreset("mars", kAssets), kAssets / "presets" / "mars.toml");
    const fs::path direct = kAssets / "presets" / "hazy.toml";
    EXPECT_EQ(resolvePreset(direct.string(), fs::path("/nonexistent")), direct);
    const InputError e = expectInputError([] { resolvePreset("venus", kAssets); });
    EXPECT_TRUE(contains(e.what(), "'venus'")) << e.what();
    EXPECT_TRUE(contains(e.what(), "earth, hazy, mars")) << e.what();
}

TEST(TomlInput, NumbersPrintShortAndReadBack) {
    EXPECT_EQ(formatNumber(100000.0), "100000");
    EXPECT_EQ(formatNumber(1e-4), "0.0001");
    EXPECT_EQ(formatNumber(-5.0), "-5");
    EXPECT_EQ(formatNumber(6360.5), "6360.5");
    for (const double v : {0.1 + 0.2, 1.0 / 3.0, 1e-300, 6.02e23, -123456.789}) {
        EXPECT_EQ(std::stod(formatNumber(v)), v) << formatNumber(v);
    }
}

TEST(TomlInput, TypedReads) {
    const toml::table t = parseToml("i = 3\nf = 3.0\nh = 2.5\nb = true\ns = \"x\"\nv = [1, 2.5, 3]\n", "r.toml");
    EXPECT_EQ(readInt(*t.get("i"), "r.toml", "i"), 3);
    EXPECT_EQ(readInt(*t.get("f"), "r.toml", "f"), 3);
    const InputError half = expectInputError([&] { readInt(*t.get("h"), "r.toml", "h"); });
    EXPECT_EQ(half.line, 3);
    EXPECT_TRUE(contains(half.what(), "not a whole number")) << half.what();
    EXPECT_TRUE(readBool(*t.get("b"), "r.toml", "b"));
    EXPECT_EQ(expectInputError([&] { readBool(*t.get("i"), "r.toml", "i"); }).line, 1);
    EXPECT_EQ(readVec3(*t.get("v"), "r.toml", "v"), glm::dvec3(1.0, 2.5, 3.0));
    EXPECT_EQ(expectInputError([&] { readVec3(*t.get("s"), "r.toml", "s"); }).line, 5);
    EXPECT_EQ(expectInputError([&] { readNumber(*t.get("b"), "r.toml", "b"); }).line, 4);
}

TEST(TomlInput, MessageOmitsUnknownLine) {
    EXPECT_EQ(std::string(InputError("a.toml", 0, "k", "bad").what()), "a.toml: k: bad");
    EXPECT_EQ(std::string(InputError("a.toml", 7, "", "bad").what()), "a.toml:7: bad");
    EXPECT_EQ(std::string(InputError("", 0, "", "bad").what()), "bad");
}

}  // namespace
}  // namespace planet
