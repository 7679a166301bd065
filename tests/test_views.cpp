// Tests for view bookmarks (app/views.h): the shipped views, required and
// paired keys, range errors, unknown-key warnings, lookup by name, a broken
// file among good ones (skipped unless asked for, also through the commands),
// and the sun placement math against analytic local frames.
#include <gtest/gtest.h>

#include "test_util.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <unistd.h>

#include "app/views.h"
#include "process.h"
#include "util/file_util.h"
#include "scene/toml_error.h"

namespace planet {
namespace {

namespace fs = std::filesystem;

const fs::path kViews = fs::path(PLANET_SOURCE_DIR) / "assets" / "views";
const std::string kRequired = "latitude_deg = 10\nlongitude_deg = 20\naltitude_m = 2\n";

using test::contains;
using test::expectInputError;
using test::runCommand;

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

View sunView(double lat, double lon, double elevation, double azimuth) {
    View v;
    v.latitude_deg = lat;
    v.longitude_deg = lon;
    v.sun_elevation_deg = elevation;
    v.sun_azimuth_deg = azimuth;
    return v;
}

TEST(Views, ShippedViewsLoadWithoutWarnings) {
    std::vector<std::string> warnings;
    const std::vector<View> views = loadViews(kViews, &warnings);
    EXPECT_TRUE(warnings.empty()) << joinNames(warnings);
    std::vector<std::string> names;
    for (const View& v : views) {
        names.push_back(v.name);
        EXPECT_TRUE(v.hasSun()) << v.name;
        EXPECT_FALSE(v.description.empty()) << v.name;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"aircraft", "beach", "cloud_sunset", "clouds", "cumulus", "deck", "ground",
                                               "mountains", "orbit", "sea", "space", "sunset"}));
    EXPECT_EQ(findView(views, "ground").altitude_m, 2.0);
    EXPECT_EQ(findView(views, "ground").sun_elevation_deg, 40.0);
    EXPECT_EQ(findView(views, "clouds").altitude_m, 2500.0);
    EXPECT_EQ(findView(views, "orbit").altitude_m, 400000.0);
    EXPECT_EQ(findView(views, "space").altitude_m, 3e7);
    EXPECT_EQ(findView(views, "space").pitch_deg, -90.0);
    EXPECT_EQ(findView(views, "sunset").sun_elevation_deg, 2.0);
    EXPECT_EQ(findView(views, "sunset").heading_deg, 270.0);
    EXPECT_LT(findView(views, "beach").pitch_deg, 0.0);
}

TEST(Views, OptionalKeysTakeDefaults) {
    const View v = parseView(kRequired, "v.toml", "plain");
    EXPECT_EQ(v.name, "plain");
    EXPECT_EQ(v.latitude_deg, 10.0);
    EXPECT_EQ(v.longitude_deg, 20.0);
    EXPECT_EQ(v.altitude_m, 2.0);
    EXPECT_EQ(v.heading_deg, 0.0);
    EXPECT_EQ(v.pitch_deg, 0.0);
    EXPECT_EQ(v.fov_deg, 60.0);
    EXPECT_FALSE(v.sun_elevation_deg.has_value());
    EXPECT_FALSE(v.sun_azimuth_deg.has_value());
}

TEST(Views, MissingRequiredKeyIsAnError) {
    const InputError e = expectInputError([] { parseView("latitude_deg = 1\nlongitude_deg = 2\n", "v.toml", "v"); });
    EXPECT_EQ(e.field, "altitude_m");
    EXPECT_TRUE(contains(e.what(), "v.toml: altitude_m: required key is missing")) << e.what();
}

TEST(Views, SunKeysComeInPairs) {
    const InputError elevationOnly =
        expectInputError([] { parseView(kRequired + "sun_elevation_deg = 30\n", "v.toml", "v"); });
    EXPECT_EQ(elevationOnly.line, 4);
    EXPECT_TRUE(contains(elevationOnly.what(), "sun_azimuth_deg")) << elevationOnly.what();
    const InputError azimuthOnly =
        expectInputError([] { parseView(kRequired + "\nsun_azimuth_deg = 30\n", "v.toml", "v"); });
    EXPECT_EQ(azimuthOnly.line, 5);
    EXPECT_TRUE(contains(azimuthOnly.what(), "sun_elevation_deg")) << azimuthOnly.what();
    const View both = parseView(kRequired + "sun_azimuth_deg = 30\nsun_elevation_deg = -5\n", "v.toml", "v");
    EXPECT_EQ(both.sun_elevation_deg, -5.0);
    EXPECT_EQ(both.sun_azimuth_deg, 30.0);
}

TEST(Views, OutOfRangeAndWrongTypeNameTheLine) {
    const InputError lat = expectInputError(
        [] { parseView("longitude_deg = 0\nlatitude_deg = 95\naltitude_m = 2\n", "assets/views/x.toml", "x"); });
    EXPECT_EQ(std::string(lat.what()), "assets/views/x.toml:2: latitude_deg: value 95 is out of range [-90, 90] deg");
    // fov is an open range (1, 170).
    EXPECT_EQ(expectInputError([] { parseView(kRequired + "fov_deg = 170\n", "v.toml", "v"); }).line, 4);
    EXPECT_THROW(parseView(kRequired + "fov_deg = 1\n", "v.toml", "v"), InputError);
    EXPECT_EQ(parseView(kRequired + "fov_deg = 169.5\n", "v.toml", "v").fov_deg, 169.5);
    EXPECT_THROW(parseView("latitude_deg = 1\nlongitude_deg = 2\naltitude_m = 0.05\n", "v.toml", "v"), InputError);
    const InputError str = expectInputError([] { parseView(kRequired + "pitch_deg = \"up\"\n", "v.toml", "v"); });
    EXPECT_EQ(str.line, 4);
    EXPECT_TRUE(contains(str.what(), "pitch_deg: expected a number")) << str.what();
}

TEST(Views, UnknownKeyWarnsButLoads) {
    std::vector<std::string> warnings;
    const View v = parseView(kRequired + "headng_deg = 45\n", "v.toml", "v", &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "v.toml:4: unknown key 'headng_deg' (ignored); did you mean 'heading_deg'?");
    EXPECT_EQ(v.heading_deg, 0.0);
}

TEST(Views, FolderErrors) {
    const fs::path dir = fs::temp_directory_path() / ("planet_views_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "readme.txt") << "not a view";
    const InputError empty = expectInputError([&] { loadViews(dir); });
    EXPECT_TRUE(contains(empty.what(), dir.string())) << empty.what();
    std::ofstream(dir / "b.toml") << kRequired;
    std::ofstream(dir / "a.toml") << kRequired << "fov_deg = 40\n";
    const std::vector<View> views = loadViews(dir);
    ASSERT_EQ(views.size(), 2u);
    EXPECT_EQ(views[0].name, "a");
    EXPECT_EQ(views[0].fov_deg, 40.0);
    EXPECT_EQ(views[1].name, "b");
    fs::remove_all(dir);
    EXPECT_THROW(loadViews(dir), InputError);
}

// One bad file among good ones: left out with a warning naming file:line, its own error
// only when it is the view asked for.
TEST(Views, ABrokenFileIsSkippedUnlessItIsTheOneAskedFor) {
    const fs::path dir = fs::temp_directory_path() / ("planet_broken_views_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "a.toml") << kRequired << "headng_deg = 3\n";
    std::ofstream(dir / "b.toml") << "latitude_deg = 1\nlongitude_deg = 2\naltitude_m = [\n";  // syntax, line 3
    std::ofstream(dir / "c.toml") << "latitude_deg = 1\nlongitude_deg = 200\naltitude_m = 2\nbogus = 1\n";  // range, line 2
    std::ofstream(dir / "d.toml") << kRequired;
    std::vector<std::string> warnings;
    std::vector<BrokenView> broken;
    const std::vector<View> views = loadViews(dir, &warnings, &broken);
    ASSERT_EQ(views.size(), 2u);
    EXPECT_EQ(views[0].name, "a");
    EXPECT_EQ(views[1].name, "d");
    // In name order: a's unknown key, then b and c skipped (c's unknown key not worth a word).
    ASSERT_EQ(warnings.size(), 3u) << joinNames(warnings);
    EXPECT_TRUE(contains(warnings[0], (dir / "a.toml").string() + ":4: unknown key 'headng_deg'")) << warnings[0];
    EXPECT_TRUE(warnings[1].starts_with((dir / "b.toml").string() + ":3: TOML syntax error")) << warnings[1];
    EXPECT_TRUE(warnings[1].ends_with(" (view skipped)")) << warnings[1];
    EXPECT_EQ(warnings[2], (dir / "c.toml").string() +
                               ":2: longitude_deg: value 200 is out of range [-180, 180] deg (view skipped)");
    ASSERT_EQ(broken.size(), 2u);
    EXPECT_EQ(broken[0].name, "b");
    EXPECT_EQ(broken[1].name, "c");

    EXPECT_EQ(findView(views, "d", broken).name, "d");
    const InputError b = expectInputError([&] { findView(views, "b", broken); });
    EXPECT_EQ(b.file, (dir / "b.toml").string());
    EXPECT_EQ(b.line, 3);
    const InputError c = expectInputError([&] { findView(views, "c", broken); });
    EXPECT_EQ(std::string(c.what()), (dir / "c.toml").string() + ":2: longitude_deg: value 200 is out of range [-180, 180] deg");
    const InputError none = expectInputError([&] { findView(views, "e", broken); });
    EXPECT_TRUE(contains(none.what(), "unknown view 'e'; available views: a, d; skipped as broken: b, c")) << none.what();

    // Every file broken: no view, no exception; asking for one gives its error.
    fs::remove(dir / "a.toml");
    fs::remove(dir / "d.toml");
    const std::vector<View> left = loadViews(dir, nullptr, &broken);
    EXPECT_TRUE(left.empty());
    EXPECT_EQ(expectInputError([&] { findView(left, "b", broken); }).line, 3);
    fs::remove_all(dir);
}

class ViewsCli : public test::CliFixture {};

// The bug of issue 12: one invalid file in assets/views made every command fail. Now only
// the command that asks for it fails (with its file:line, writing nothing); the others warn
// once and go on: render with another view, bench over the folder.
TEST_F(ViewsCli, ABrokenViewFileFailsOnlyTheCommandThatAsksForIt) {
    const fs::path root = dir / "root";
    fs::create_directories(root / "assets" / "views");
    fs::create_directory_symlink(fs::path(PLANET_SOURCE_DIR) / "shaders", root / "shaders");
    fs::create_directory_symlink(kViews.parent_path() / "presets", root / "assets" / "presets");
    for (const char* name : {"orbit", "space"}) fs::copy_file(kViews / (std::string(name) + ".toml"), root / "assets" / "views" / (std::string(name) + ".toml"));
    const fs::path broken = root / "assets" / "views" / "broken.toml";
    std::ofstream(broken) << "latitude_deg = 10\nlongitude_deg = 20\naltitude_m = \"high\"\n";
    const std::string message = broken.string() + ":3: altitude_m: expected a number, got a string";
    // Small and cheap: no clouds to bake, a small continents map.
    std::ofstream(dir / "light.toml") << "[clouds]\nenabled = false\n[terrain]\ncontinent_map_size = 16\n";
    const std::string common = "--root '" + root.string() + "' --preset light.toml --size 8x8 --tables reduced ";

    const test::ProcessResult asked = runCommand(planet("render " + common + "--view broken --out out/a.png"));
    EXPECT_EQ(asked.exitCode, 1) << asked.output;
    EXPECT_EQ(asked.output, "planet: error: " + message + "\n");
    EXPECT_FALSE(fs::exists(dir / "out" / "a.png"));

    const test::ProcessResult other = runCommand(planet("render " + common + "--view space --out out/b.png"));
    EXPECT_EQ(other.exitCode, 0) << other.output;
    EXPECT_TRUE(fs::exists(dir / "out" / "b.png"));
    const std::string warning = "[planet warning] " + message + " (view skipped)\n";
    EXPECT_TRUE(contains(other.output, warning)) << other.output;
    EXPECT_EQ(other.output.find(warning), other.output.rfind(warning)) << "warned more than once:\n" << other.output;

    const test::ProcessResult bench = runCommand(
        planet("bench " + common + "--views '" + (root / "assets" / "views").string() +
               "' --frames 1 --warmup 0 --csv out/b.csv --plot out/b.png"));
    EXPECT_EQ(bench.exitCode, 0) << bench.output;
    EXPECT_TRUE(contains(bench.output, warning)) << bench.output;
    EXPECT_EQ(bench.output.find(warning), bench.output.rfind(warning)) << "warned more than once:\n" << bench.output;
    const std::string csv = readFile(dir / "out" / "b.csv");
    EXPECT_TRUE(contains(csv, ",orbit,") && contains(csv, ",space,")) << csv;
    EXPECT_FALSE(contains(csv, "broken")) << csv;
    // Without --views: the session's folder, warned about once too.
    const std::string benchDefault = runCommand(planet("bench " + common + "--frames 1 --warmup 0 --csv out/c.csv --plot out/c.png")).output;
    EXPECT_EQ(benchDefault.find(warning), benchDefault.rfind(warning)) << benchDefault;
    EXPECT_TRUE(contains(benchDefault, warning)) << benchDefault;
}

TEST(Views, FindViewListsAvailableNames) {
    std::vector<View> views(2);
    views[0].name = "beach";
    views[1].name = "orbit";
    EXPECT_EQ(&findView(views, "orbit"), &views[1]);
    const InputError e = expectInputError([&] { findView(views, "moon"); });
    EXPECT_TRUE(contains(e.what(), "'moon'")) << e.what();
    EXPECT_TRUE(contains(e.what(), "beach, orbit")) << e.what();
}

TEST(Views, SunAtZenithIsLocalUp) {
    for (const auto& [lat, lon] : {std::pair{0.0, 0.0}, {36.5, -4.9}, {-60.0, 170.0}, {89.0, 45.0}}) {
        const glm::dvec3 up(std::cos(glm::radians(lat)) * std::cos(glm::radians(lon)),
                            std::cos(glm::radians(lat)) * std::sin(glm::radians(lon)), std::sin(glm::radians(lat)));
        expectNear(subsolarDirection(sunView(lat, lon, 90.0, 123.0), Scene{}), up, 1e-12);
    }
}

TEST(Views, SunOnHorizonAtAzimuth90IsLocalEast) {
    // At (0, 0): east is +Y, north is +Z, up is +X.
    expectNear(subsolarDirection(sunView(0.0, 0.0, 0.0, 90.0), Scene{}), {0.0, 1.0, 0.0}, 1e-12);
    expectNear(subsolarDirection(sunView(0.0, 0.0, 0.0, 0.0), Scene{}), {0.0, 0.0, 1.0}, 1e-12);
    // At (45 N, 90 E): east is -X whatever the latitude.
    expectNear(subsolarDirection(sunView(45.0, 90.0, 0.0, 90.0), Scene{}), {-1.0, 0.0, 0.0}, 1e-12);
    // At (30 N, 0): north is (-sin 30, 0, cos 30), so azimuth 0 points there.
    expectNear(subsolarDirection(sunView(30.0, 0.0, 0.0, 0.0), Scene{}), {-0.5, 0.0, std::sqrt(0.75)}, 1e-12);
}

TEST(Views, ElevationIsTheAngleAboveTheHorizon) {
    const glm::dvec3 up = directionFromLatLon(-20.0, 75.0);
    for (const double elevation : {-45.0, 0.0, 10.0, 60.0}) {
        const glm::dvec3 d = subsolarDirection(sunView(-20.0, 75.0, elevation, 200.0), Scene{});
        EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(d, up), std::sin(glm::radians(elevation)), 1e-12);
    }
}

TEST(Views, ApplyViewSunGivesTheSameDirection) {
    for (const View& v : {sunView(36.5, -4.9, 30.0, 100.0), sunView(0.0, 179.0, 5.0, 90.0),
                          sunView(89.9, 0.0, 89.0, 10.0), sunView(-45.0, -170.0, -10.0, 270.0),
                          sunView(10.0, 20.0, 90.0, 0.0)}) {
        Scene scene;
        applyViewSun(v, scene);
        expectNear(scene.sunDirection(), subsolarDirection(v, Scene{}), 1e-9);
        EXPECT_LE(std::abs(scene.sun.latitude_deg), 90.0);
        EXPECT_LE(std::abs(scene.sun.longitude_deg), 180.0);
    }
}

TEST(Views, NoSunKeysLeaveTheSceneAlone) {
    View v;
    Scene scene;
    scene.sun.latitude_deg = -33.0;
    scene.sun.longitude_deg = 12.0;
    applyViewSun(v, scene);
    EXPECT_EQ(scene.sun.latitude_deg, -33.0);
    EXPECT_EQ(scene.sun.longitude_deg, 12.0);
    expectNear(subsolarDirection(v, scene), scene.sunDirection(), 0.0);
}

}  // namespace
}  // namespace planet
