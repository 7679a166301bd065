// The preset's ocean: [ocean] parameters generate the waves; a [[ocean.wave]] list replaces
// them, read with file:line errors and written back exactly when the waves were edited.
#include <gtest/gtest.h>

#include <string>

#include "ocean/wave_spectrum.h"
#include "scene/preset.h"
#include "scene/preset_waves.h"
#include "scene/scene_params.h"
#include "test_util.h"

namespace planet {
namespace {

using test::contains;
using test::expectInputError;

const char* kTwoWaves = R"(name = "two waves"
[ocean]
wave_count = 7

[[ocean.wave]]
origin = [0.0, 0.0, 2.0]
amplitude_m = 0.4
wavelength_m = 30.0
steepness = 0.3

[[ocean.wave]]
latitude_deg = 10.0
longitude_deg = -20.0
amplitude_m = 1.5
wavelength_m = 120.0
steepness = 0.1
speed_mps = 3.0
phase_rad = 1.25
)";

}  // namespace

TEST(PresetWaves, WithoutAListTheParametersGenerateTheWaves) {
    const PresetLoad load = parsePreset("[ocean]\nwave_count = 12\nseed = 5\n", "gen.toml");
    OceanParams p;
    p.wave_count = 12;
    p.seed = 5;
    EXPECT_TRUE(sameWaves(load.scene.waves, ocean::generateWaves(p)));
    EXPECT_EQ(load.scene.waves.size(), 12u);
    EXPECT_TRUE(load.warnings.empty());
}

TEST(PresetWaves, AListReplacesTheGeneratedSet) {
    const PresetLoad load = parsePreset(kTwoWaves, "two.toml");
    ASSERT_EQ(load.scene.waves.size(), 2u);  // not wave_count's 7
    EXPECT_TRUE(load.warnings.empty());
    const ocean::GerstnerWave& a = load.scene.waves[0];
    EXPECT_EQ(a.origin, glm::dvec3(0.0, 0.0, 1.0));  // normalised
    EXPECT_EQ(a.amplitude_m, 0.4);
    EXPECT_EQ(a.steepness, 0.3);
    EXPECT_DOUBLE_EQ(a.speed_mps, ocean::deepWaterSpeed(30.0));  // absent: deep-water dispersion
    EXPECT_EQ(a.phase_rad, 0.0);
    const ocean::GerstnerWave& b = load.scene.waves[1];
    const glm::dvec3 expected = directionFromLatLon(10.0, -20.0);
    EXPECT_NEAR(glm::length(b.origin - expected), 0.0, 1e-15);
    EXPECT_EQ(b.speed_mps, 3.0);
    EXPECT_EQ(b.phase_rad, 1.25);
}

TEST(PresetWaves, EditedWavesAreWrittenAndReadBackExactly) {
    Scene s = parsePreset(kTwoWaves, "two.toml").scene;
    s.waves[1].amplitude_m = 1.0 / 3.0;
    s.waves[0].origin = glm::normalize(glm::dvec3(0.1, -0.2, 0.3));
    const std::string text = presetToToml(s, "edited", "");
    EXPECT_TRUE(contains(text, "[[ocean.wave]]"));
    const PresetLoad back = parsePreset(text, "edited.toml");
    EXPECT_TRUE(sameWaves(back.scene.waves, s.waves));
    EXPECT_TRUE(back.warnings.empty());
}

TEST(PresetWaves, GeneratedWavesAreNotListed) {
    const std::string text = presetToToml(Scene{}, "default", "");
    EXPECT_FALSE(contains(text, "[[ocean.wave]]"));
    EXPECT_TRUE(contains(text, "\n[ocean]\n"));
}

TEST(PresetWaves, BadEntriesNameFileLineAndField) {
    const std::string steep = std::string(kTwoWaves) + "\n[[ocean.wave]]\norigin = [1.0, 0.0, 0.0]\namplitude_m = 1.0\n"
                                                       "wavelength_m = 10.0\nsteepness = 1.5\n";
    const InputError e = expectInputError([&] { parsePreset(steep, "bad.toml"); });
    EXPECT_EQ(e.file, "bad.toml");
    EXPECT_EQ(e.field, "ocean.wave[2].steepness");
    EXPECT_EQ(e.line, 24);
    const InputError zero = expectInputError(
        [&] { parsePreset("[[ocean.wave]]\norigin = [0.0, 0.0, 0.0]\namplitude_m = 1.0\nwavelength_m = 5.0\n", "z.toml"); });
    EXPECT_EQ(zero.field, "ocean.wave[0].origin");
    EXPECT_EQ(zero.line, 2);
    const InputError noWavelength =
        expectInputError([&] { parsePreset("[[ocean.wave]]\norigin = [0.0, 0.0, 1.0]\namplitude_m = 1.0\n", "w.toml"); });
    EXPECT_EQ(noWavelength.field, "ocean.wave[0].wavelength_m");
    const InputError typo = expectInputError([&] {
        parsePreset("[[ocean.wave]]\norigin = [0.0, 0.0, 1.0]\namplitude_m = 1.0\nwavelength_m = 5.0\nwavelenth = 3\n",
                    "t.toml");
    });
    EXPECT_EQ(typo.field, "ocean.wave[0].wavelenth");
    EXPECT_EQ(typo.line, 5);
    const InputError notTables = expectInputError([&] { parsePreset("[ocean]\nwave = 3\n", "n.toml"); });
    EXPECT_EQ(notTables.field, "ocean.wave");
}

TEST(PresetWaves, LoopingCrestsAreRefused) {
    // One wave with Q A k = 1.0 x 3 m x 2 pi / 10 m = 1.9 > 1: its crests would loop.
    const InputError e = expectInputError([&] {
        parsePreset("[[ocean.wave]]\norigin = [0.0, 0.0, 1.0]\namplitude_m = 3.0\nwavelength_m = 10.0\nsteepness = 1.0\n",
                    "steep.toml");
    });
    EXPECT_EQ(e.field, "ocean.wave");
    EXPECT_TRUE(contains(e.what(), "loop")) << e.what();
    // Two waves, each fine alone (0.6), together too sharp (1.2).
    Scene s;
    s.waves.assign(2, ocean::GerstnerWave{});
    for (ocean::GerstnerWave& w : s.waves) {
        w.wavelength_m = 6.283185307179586;  // k = 1
        w.amplitude_m = 0.6;
        w.steepness = 1.0;
    }
    ASSERT_FALSE(validateScene(s).empty());
    EXPECT_EQ(validateScene(s).front().field, "ocean.wave");
    s.waves.pop_back();
    EXPECT_TRUE(validateScene(s).empty());
}

TEST(PresetWaves, FadeEndMustExceedFadeStart) {
    const InputError e = expectInputError([&] { parsePreset("[ocean]\nfade_start = 0.01\nfade_end = 0.001\n", "f.toml"); });
    EXPECT_EQ(e.field, "ocean.fade_end");
    EXPECT_EQ(e.line, 3);
    Scene s;
    s.ocean.fade_end = s.ocean.fade_start;
    ASSERT_FALSE(validateScene(s).empty());
    EXPECT_EQ(validateScene(s).front().field, "ocean.fade_end");
}

TEST(PresetWaves, InvalidWavesInTheSceneAreRefused) {
    Scene s;
    s.waves.front().wavelength_m = -1.0;  // e.g. an edit gone wrong
    const std::vector<SceneProblem> problems = validateScene(s);
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems.front().field, "ocean.wave");
}

}  // namespace planet
