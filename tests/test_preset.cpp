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

using test::TempDir;

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
    const std::string text = "name = \"x\"\n[planet]\nradius = 5\n\n[volcanoes]\ndensity = 1\n";
    const PresetLoad load = parsePreset(text, "earth.toml");
    ASSERT_EQ(load.warnings.size(), 2u);
    EXPECT_EQ(load.warnings[0],
              "earth.toml:3: unknown key 'planet.radius' (ignored); did you mean 'planet.radius_km'?");
    EXPECT_TRUE(contains(load.warnings[1], "earth.toml:5: unknown key 'volcanoes'")) << load.warnings[1];
    EXPECT_FALSE(contains(load.warnings[1], "did you mean")) << load.warnings[1];
    EXPECT_TRUE(sameScene(load.scene, Scene{}));  // unknown keys change nothing
}

// ---- the [atmosphere] section and validateScene ----

TEST(Preset, TableOrderAndAtmosphereRows) {
    std::vector<std::string> sections;
    int atmosphereRows = 0;
    for (const ParamSpec& spec : sceneParams()) {
        if (sections.empty() || sections.back() != spec.section) sections.push_back(spec.section);
        if (spec.section != "atmosphere") continue;
        ++atmosphereRows;
        EXPECT_FALSE(spec.help.empty()) << spec.path();
        EXPECT_EQ(spec.help.find('\n'), std::string::npos) << spec.path();  // one comment line in presets
    }
    EXPECT_EQ(sections, (std::vector<std::string>{"planet", "atmosphere", "terrain", "ocean", "clouds", "sun", "render"}));
    EXPECT_EQ(atmosphereRows, 15);  // one per field of AtmosphereParams
    // Each row reaches its own field, with the type the panel needs.
    Scene s;
    auto ref = [&](const std::string& path) {
        for (const ParamSpec& spec : sceneParams())
            if (spec.path() == path) return spec.field(s);
        ADD_FAILURE() << path << " not in the table";
        return ParamRef{};
    };
    EXPECT_EQ(std::get<int*>(ref("atmosphere.scattering_orders")), &s.atmosphere.scattering_orders);
    EXPECT_EQ(std::get<bool*>(ref("atmosphere.elek_rayleigh_phase")), &s.atmosphere.elek_rayleigh_phase);
    EXPECT_EQ(std::get<double*>(ref("atmosphere.top_radius_km")), &s.atmosphere.top_radius_km);
    EXPECT_EQ(std::get<glm::dvec3*>(ref("atmosphere.mie_extinction_per_m")), &s.atmosphere.mie_extinction_per_m);
}

TEST(Preset, TopRadiusBelowPlanetRadiusNamesTheLine) {
    const std::string text = "[planet]\nradius_km = 6000\n\n[atmosphere]\nmie_g = 0.7\ntop_radius_km = 5000\n";
    const InputError e = expectInputError([&] { parsePreset(text, "low.toml"); });
    EXPECT_EQ(e.file, "low.toml");
    EXPECT_EQ(e.line, 6);
    EXPECT_EQ(e.field, "atmosphere.top_radius_km");
    EXPECT_TRUE(contains(e.what(), "low.toml:6: atmosphere.top_radius_km: ")) << e.what();
    EXPECT_TRUE(contains(e.message, "5000")) << e.message;
    EXPECT_TRUE(contains(e.message, "planet.radius_km 6000")) << e.message;
    // Equal radii leave no atmosphere: also refused.
    EXPECT_THROW(parsePreset("[planet]\nradius_km = 6420\n", "eq.toml"), InputError);
    // A bigger planet that leaves the default top below it: blamed on the top, which has no line.
    const InputError big = expectInputError([] { parsePreset("[planet]\nradius_km = 7000\n", "big.toml"); });
    EXPECT_EQ(big.field, "atmosphere.top_radius_km");
    EXPECT_EQ(big.line, 0);
    EXPECT_TRUE(contains(big.message, "6420")) << big.message;
    EXPECT_TRUE(contains(big.message, "7000")) << big.message;
    // Just above is fine (without clouds: 1 km of air, the least the tables take, has no room for the default layer).
    EXPECT_NO_THROW(parsePreset("[planet]\nradius_km = 7000\n[atmosphere]\ntop_radius_km = 7001\n[clouds]\nenabled = false\n",
                                "ok.toml"));
    const InputError clouds =
        expectInputError([] { parsePreset("[planet]\nradius_km = 7000\n[atmosphere]\ntop_radius_km = 7001\n", "c.toml"); });
    EXPECT_EQ(clouds.field, "clouds.top_altitude_km");
}

TEST(Preset, MieExtinctionBelowScatteringIsAnError) {
    const std::string text =
        "[atmosphere]\nmie_scattering_per_m = [4e-6, 5e-6, 4e-6]\nmie_extinction_per_m = [4.44e-6, 4.44e-6, 4.44e-6]\n";
    const InputError e = expectInputError([&] { parsePreset(text, "mie.toml"); });
    EXPECT_EQ(e.field, "atmosphere.mie_extinction_per_m");
    EXPECT_EQ(e.line, 3);
    EXPECT_TRUE(contains(e.message, "component 1")) << e.message;
    EXPECT_TRUE(contains(e.message, "atmosphere.mie_scattering_per_m")) << e.message;
    // Extinction equal to scattering (no absorption) is allowed.
    const PresetLoad ok =
        parsePreset("[atmosphere]\nmie_scattering_per_m = [1e-5, 1e-5, 1e-5]\nmie_extinction_per_m = [1e-5, 1e-5, 1e-5]\n",
                    "ok.toml");
    EXPECT_EQ(ok.scene.atmosphere.mie_extinction_per_m, glm::dvec3(1e-5));
}

TEST(Preset, MieGMustStayBelowOne) {
    const InputError e = expectInputError([] { parsePreset("[atmosphere]\nmie_g = 1.0\n", "g.toml"); });
    EXPECT_EQ(e.field, "atmosphere.mie_g");
    EXPECT_EQ(e.line, 2);
    EXPECT_EQ(e.message, "value 1 is out of range [-0.999, 0.999]");
    EXPECT_THROW(parsePreset("[atmosphere]\nmie_g = -1.0\n", "g.toml"), InputError);
    EXPECT_EQ(parsePreset("[atmosphere]\nmie_g = -0.999\n", "g.toml").scene.atmosphere.mie_g, -0.999);
}

TEST(Preset, NegativeRayleighNamesTheComponent) {
    const std::string text = "[atmosphere]\nrayleigh_scattering_per_m = [-1e-6, 1e-5, 3e-5]\n";
    const InputError e = expectInputError([&] { parsePreset(text, "r.toml"); });
    EXPECT_EQ(e.field, "atmosphere.rayleigh_scattering_per_m[0]");
    EXPECT_EQ(e.line, 2);
    EXPECT_TRUE(contains(e.message, "out of range [0, 0.01] 1/m")) << e.message;
}

TEST(Preset, ScatteringOrdersMustBeAWholeNumberInRange) {
    const InputError half = expectInputError([] { parsePreset("[atmosphere]\nscattering_orders = 2.5\n", "o.toml"); });
    EXPECT_EQ(half.field, "atmosphere.scattering_orders");
    EXPECT_EQ(half.line, 2);
    EXPECT_TRUE(contains(half.message, "not a whole number")) << half.message;
    EXPECT_THROW(parsePreset("[atmosphere]\nscattering_orders = 0\n", "o.toml"), InputError);
    EXPECT_THROW(parsePreset("[atmosphere]\nscattering_orders = 11\n", "o.toml"), InputError);
    EXPECT_EQ(parsePreset("[atmosphere]\nscattering_orders = 10\n", "o.toml").scene.atmosphere.scattering_orders, 10);
    EXPECT_THROW(parsePreset("[atmosphere]\nelek_rayleigh_phase = 1\n", "o.toml"), InputError);  // bool, not number
}

TEST(Preset, AtmosphereTyposWarnWithSuggestion) {
    const PresetLoad load = parsePreset("[atmosphere]\nmie_gg = 0.7\n", "t.toml");
    ASSERT_EQ(load.warnings.size(), 1u);
    EXPECT_EQ(load.warnings[0], "t.toml:2: unknown key 'atmosphere.mie_gg' (ignored); did you mean 'atmosphere.mie_g'?");
}

// Every field of the atmosphere away from its default, and odd doubles.
Scene modifiedAtmosphere() {
    Scene s;
    s.planet.radius_km = 3389.5;
    AtmosphereParams& a = s.atmosphere;
    a.top_radius_km = 3389.5 + 4.0 / 3.0;  // the tables take 1 km of air at the least
    a.rayleigh_scattering_per_m = {1.16e-6, 0.1 * 2.71e-5, 1e-4};  // optical depth <= 60 (atmosphere/parameters.h)
    a.rayleigh_scale_height_km = 11.1;
    a.mie_scattering_per_m = {6.0e-6, 4.5e-6, 0.0};
    a.mie_extinction_per_m = {6.0e-6, std::nextafter(4.5e-6, 1.0), 1e-300};
    a.mie_scale_height_km = 0.2;
    a.mie_g = -0.999;
    a.ozone_absorption_per_m = {0.0, 0.0, 0.0};
    a.ozone_peak_altitude_km = 0.0;
    a.ozone_width_km = 1000.0;
    a.ground_albedo = {0.3, 0.2, 0.1 + 0.02};
    a.scattering_orders = 7;
    s.clouds.enabled = false;  // no room for them in a km and a third of air
    a.min_sun_elevation_deg = -90.0;
    a.elek_rayleigh_phase = true;
    return s;
}

TEST(Preset, ModifiedAtmosphereRoundTripsExactly) {
    const Scene s = modifiedAtmosphere();
    ASSERT_TRUE(validateScene(s).empty());
    ASSERT_FALSE(sameScene(s, Scene{}));
    const PresetLoad load = parsePreset(presetToToml(s, "Odd air", ""), "rt.toml");
    EXPECT_TRUE(sameScene(load.scene, s));
    EXPECT_TRUE(load.warnings.empty());

    TempDir dir("preset_atmosphere");
    savePreset(s, dir.path / "odd.toml", "Odd air", "");
    EXPECT_TRUE(sameScene(loadPreset(dir.path / "odd.toml").scene, s));
}

TEST(Preset, SaveRefusesAnInvalidScene) {
    TempDir dir("preset_invalid");
    Scene low;
    low.atmosphere.top_radius_km = low.planet.radius_km - 1.0;
    const InputError e = expectInputError([&] { savePreset(low, dir.path / "low.toml", "n", "d"); });
    EXPECT_EQ(e.field, "atmosphere.top_radius_km");
    EXPECT_TRUE(contains(e.file, "low.toml")) << e.file;

    Scene mie;
    mie.atmosphere.mie_extinction_per_m.z = 0.5 * mie.atmosphere.mie_scattering_per_m.z;
    EXPECT_EQ(expectInputError([&] { savePreset(mie, dir.path / "mie.toml", "n", "d"); }).field,
              "atmosphere.mie_extinction_per_m");

    Scene range;  // out of a single row's range: would not load back either
    range.atmosphere.mie_g = 1.0;
    EXPECT_EQ(expectInputError([&] { savePreset(range, dir.path / "g.toml", "n", "d"); }).field, "atmosphere.mie_g");
    EXPECT_TRUE(fs::is_empty(dir.path));  // nothing written
}

TEST(Preset, ValidateSceneAgreesWithLoading) {
    EXPECT_TRUE(validateScene(Scene{}).empty());
    for (const char* name : {"earth", "mars", "hazy"})
        EXPECT_TRUE(validateScene(loadPreset(resolvePreset(name, kAssets)).scene).empty()) << name;

    Scene bad;
    bad.planet.radius_km = 7000.0;                          // above the default top
    bad.atmosphere.mie_scattering_per_m.x = 1e-5;           // above the default extinction
    bad.atmosphere.rayleigh_scattering_per_m.y = -1.0;      // out of range
    bad.atmosphere.scattering_orders = 0;                   // out of range
    const std::vector<SceneProblem> problems = validateScene(bad);
    ASSERT_EQ(problems.size(), 4u);
    EXPECT_EQ(problems[0].field, "atmosphere.rayleigh_scattering_per_m[1]");  // ranges first, table order
    EXPECT_EQ(problems[1].field, "atmosphere.scattering_orders");
    EXPECT_EQ(problems[2].field, "atmosphere.top_radius_km");
    EXPECT_EQ(problems[3].field, "atmosphere.mie_extinction_per_m");
    EXPECT_TRUE(contains(problems[3].message, "component 0")) << problems[3].message;
    // NaN breaks its range.
    Scene nan;
    nan.atmosphere.mie_g = std::numeric_limits<double>::quiet_NaN();
    ASSERT_EQ(validateScene(nan).size(), 1u);
    EXPECT_EQ(validateScene(nan)[0].field, "atmosphere.mie_g");
    // The writer emits it anyway, and the reader names the same first field.
    EXPECT_EQ(expectInputError([&] { parsePreset(presetToToml(bad, "b", ""), "b.toml"); }).field,
              problems[0].field);
}

TEST(Preset, MarsAndHazyAtmospheres) {
    const Scene earth;
    const PresetLoad mars = loadPreset(kAssets / "presets" / "mars.toml");
    const PresetLoad hazy = loadPreset(kAssets / "presets" / "hazy.toml");
    EXPECT_TRUE(mars.warnings.empty()) << joinNames(mars.warnings);
    EXPECT_TRUE(hazy.warnings.empty()) << joinNames(hazy.warnings);
    const AtmosphereParams& m = mars.scene.atmosphere;
    const AtmosphereParams& h = hazy.scene.atmosphere;
    const AtmosphereParams& e = earth.atmosphere;
    // Mars: thinner shell, sparser air, reddish dust (more Mie in red than blue), no ozone.
    EXPECT_LT(m.top_radius_km - mars.scene.planet.radius_km, e.top_radius_km - earth.planet.radius_km);
    EXPECT_GT(m.top_radius_km, mars.scene.planet.radius_km);
    for (int i = 0; i < 3; ++i) EXPECT_LT(m.rayleigh_scattering_per_m[i], e.rayleigh_scattering_per_m[i]) << i;
    EXPECT_GT(m.mie_scattering_per_m.r, m.mie_scattering_per_m.b);
    EXPECT_EQ(m.ozone_absorption_per_m, glm::dvec3(0.0));
    // Hazy: denser Rayleigh and Mie, haze reaching higher, Earth's ozone.
    for (int i = 0; i < 3; ++i) {
        EXPECT_GT(h.rayleigh_scattering_per_m[i], e.rayleigh_scattering_per_m[i]) << i;
        EXPECT_GT(h.mie_scattering_per_m[i], e.mie_scattering_per_m[i]) << i;
        EXPECT_NEAR(h.rayleigh_scattering_per_m[i], 5.0 * e.rayleigh_scattering_per_m[i], 1e-12) << i;
    }
    EXPECT_GT(h.mie_scale_height_km, e.mie_scale_height_km);
    EXPECT_EQ(h.ozone_absorption_per_m, e.ozone_absorption_per_m);
    EXPECT_GT(h.top_radius_km - hazy.scene.planet.radius_km, e.top_radius_km - earth.planet.radius_km);
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

// Found by the fuzzing (test_fuzz_assets.cpp): a sea with every wave removed (the explorer's
// Waves panel, or `wave = []` in a preset) was written without its empty list and read back
// with the generated waves.
TEST(Preset, NoWavesAtAllRoundTrip) {
    const PresetLoad calm = parsePreset("[ocean]\nwave = []\n", "calm.toml");
    EXPECT_TRUE(calm.scene.waves.empty());
    EXPECT_FALSE(Scene{}.ocean.wave_count == 0);  // the default generates waves: the list is the preset's own
    Scene edited;
    edited.waves.clear();
    for (const Scene& s : {calm.scene, edited}) {
        const std::string text = presetToToml(s, "", "");
        EXPECT_TRUE(contains(text, "\nwave = []\n")) << text;
        EXPECT_FALSE(contains(text, "[[ocean.wave]]")) << text;
        const PresetLoad back = parsePreset(text, "back.toml");
        EXPECT_TRUE(back.scene.waves.empty()) << back.scene.waves.size() << " waves read back";
        EXPECT_TRUE(back.warnings.empty());
    }
    // A calm sea the parameters already give (wave_count = 0) needs no list.
    Scene none;
    none.ocean.wave_count = 0;
    none.waves.clear();
    EXPECT_FALSE(contains(presetToToml(none, "", ""), "wave = []"));
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

TEST(Preset, GridExponentMustBeTwoOrFour) {
    try {
        parsePreset("[terrain]\ngrid_exponent = 3\n", "g.toml");
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "g.toml:2: terrain.grid_exponent")) << e.what();
    }
    EXPECT_NO_THROW(parsePreset("[terrain]\ngrid_exponent = 2\n", "g.toml"));
}

}  // namespace
}  // namespace planet
