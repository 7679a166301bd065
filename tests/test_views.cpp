// Tests for view bookmarks (app/views.h): the shipped views, required and
// paired keys, range errors, unknown-key warnings, lookup by name, and the
// sun placement math against analytic local frames.
#include <gtest/gtest.h>

#include "test_util.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <unistd.h>

#include "app/views.h"
#include "scene/toml_error.h"

namespace planet {
namespace {

namespace fs = std::filesystem;

const fs::path kViews = fs::path(PLANET_SOURCE_DIR) / "assets" / "views";
const std::string kRequired = "latitude_deg = 10\nlongitude_deg = 20\naltitude_m = 2\n";

using test::contains;
using test::expectInputError;

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
