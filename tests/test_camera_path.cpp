// Tests for camera paths (app/camera_path.h): parsing (the shipped path, errors
// with lines, times, too few keyframes, unknown keys), the interpolation (through
// the keyframes, continuous, C1 position, orthonormal orientation, altitude
// within its keyframes), frame patterns and counts, and `planet render --path`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <stb_image.h>

#include "app/camera_path.h"
#include "process.h"
#include "scene/scene.h"
#include "test_util.h"

namespace planet {
namespace {

namespace fs = std::filesystem;

constexpr double kRadius = 6360e3;

const std::string kTwoKeys = R"(description = "test"
fps = 10
[[keyframe]]
time_s = 0
latitude_deg = 10
longitude_deg = 20
altitude_m = 2
heading_deg = 0
pitch_deg = 0
[[keyframe]]
time_s = 2
latitude_deg = 10.01
longitude_deg = 20.01
altitude_m = 1000
heading_deg = 90
pitch_deg = 20
fov_deg = 40
)";

// A path file's text: keyframes of time, latitude, longitude, altitude, heading, pitch, sun
// elevation and sun azimuth, in the units of assets/paths (camera_path.h).
struct Key {
    double time_s, latitude_deg, longitude_deg, altitude_m, heading_deg, pitch_deg, sun_elevation_deg, sun_azimuth_deg;
};
std::string pathToml(const std::string& description, double fps, const std::vector<Key>& keys) {
    std::ostringstream text;
    text << "description = \"" << description << "\"\nfps = " << fps << "\n";
    for (const Key& k : keys)
        text << "[[keyframe]]\ntime_s = " << k.time_s << "\nlatitude_deg = " << k.latitude_deg
             << "\nlongitude_deg = " << k.longitude_deg << "\naltitude_m = " << k.altitude_m
             << "\nheading_deg = " << k.heading_deg << "\npitch_deg = " << k.pitch_deg
             << "\nsun_elevation_deg = " << k.sun_elevation_deg << "\nsun_azimuth_deg = " << k.sun_azimuth_deg << "\n";
    return text.str();
}

// A climb from 2 m to 400 km across five keyframes, turning, with a sun.
CameraPathFile climb() {
    CameraPathFile file;
    file.name = "climb";
    const double t[] = {0, 3, 7, 12, 20};
    const double alt[] = {2, 50, 2500, 20000, 400000};
    const double heading[] = {250, 260, 300, 20, 200};
    const double pitch[] = {-5, 10, 30, -10, 5};
    for (int i = 0; i < 5; ++i) {
        PathKeyframe k;
        k.time_s = t[i];
        k.latitude_deg = 43.0 + 0.1 * i;
        k.longitude_deg = 179.8 + 0.1 * i > 180.0 ? 179.8 + 0.1 * i - 360.0 : 179.8 + 0.1 * i;  // across 180
        k.altitude_m = alt[i];
        k.heading_deg = heading[i];
        k.pitch_deg = pitch[i];
        k.fov_deg = 50.0 + i;
        k.sun_elevation_deg = 10.0 * i;
        k.sun_azimuth_deg = i < 3 ? 350.0 + 5.0 * i : 5.0 * i - 10.0;  // across north
        file.keyframes.push_back(k);
    }
    return file;
}

std::string errorOf(const std::string& text) {
    try {
        parseCameraPath(text, "p.toml", "p");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(CameraPathParse, GoodFile) {
    std::vector<std::string> warnings;
    const CameraPathFile p = parseCameraPath(kTwoKeys, "p.toml", "p", &warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(p.description, "test");
    EXPECT_EQ(p.fps, 10.0);
    ASSERT_EQ(p.keyframes.size(), 2u);
    EXPECT_EQ(p.keyframes[0].fov_deg, 60.0);  // default
    EXPECT_EQ(p.keyframes[1].fov_deg, 40.0);
    EXPECT_EQ(p.keyframes[1].altitude_m, 1000.0);
    EXPECT_FALSE(p.hasSun());
    EXPECT_EQ(p.duration(), 2.0);
    EXPECT_EQ(pathFrameCount(p, std::nullopt), 21);
    EXPECT_EQ(pathFrameCount(p, 5), 5);
    EXPECT_EQ(pathFrameTime(p, 0, 5), 0.0);
    EXPECT_EQ(pathFrameTime(p, 2, 5), 1.0);
    EXPECT_EQ(pathFrameTime(p, 4, 5), 2.0);
}

TEST(CameraPathParse, ShippedTakeoffLoadsAndClimbsToOrbit) {
    const fs::path dir = fs::path(PLANET_SOURCE_DIR) / "assets" / "paths";
    std::vector<std::string> warnings;
    const CameraPathFile p = loadCameraPath(resolveCameraPath("takeoff", dir), &warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    EXPECT_EQ(p.name, "takeoff");
    EXPECT_GE(p.duration(), 20.0);
    EXPECT_LE(p.duration(), 30.0);
    EXPECT_EQ(p.keyframes.front().latitude_deg, 43.0);
    EXPECT_EQ(p.keyframes.front().longitude_deg, -6.5025);
    EXPECT_EQ(p.keyframes.front().altitude_m, 2.0);
    EXPECT_EQ(p.keyframes.back().altitude_m, 400000.0);
    EXPECT_THROW(resolveCameraPath("no-such-path", dir), InputError);
    try {
        resolveCameraPath("no-such-path", dir);
    } catch (const InputError& e) {
        EXPECT_TRUE(test::contains(e.what(), "takeoff")) << e.what();  // lists what there is
    }
}

TEST(CameraPathParse, ErrorsNameFileLineAndField) {
    std::string text = kTwoKeys;
    text.replace(text.find("altitude_m = 1000"), 17, "altitude_m = -5");
    EXPECT_TRUE(test::contains(errorOf(text), "p.toml:14: keyframe[1].altitude_m: value -5 is out of range"))
        << errorOf(text);

    text = kTwoKeys;
    text.replace(text.find("fov_deg = 40"), 12, "fov_deg = \"wide\"");
    EXPECT_TRUE(test::contains(errorOf(text), "p.toml:17: keyframe[1].fov_deg")) << errorOf(text);

    text = kTwoKeys;
    text.replace(text.find("pitch_deg = 20\n"), 15, "");
    EXPECT_TRUE(test::contains(errorOf(text), "keyframe[1].pitch_deg: required key is missing")) << errorOf(text);

    text = kTwoKeys;
    text.replace(text.find("fps = 10"), 8, "fps = 0");
    EXPECT_TRUE(test::contains(errorOf(text), "p.toml:2: fps")) << errorOf(text);

    EXPECT_TRUE(test::contains(errorOf("fps = 30\n[[keyframe\n"), "p.toml:2")) << errorOf("[[keyframe\n");
    EXPECT_TRUE(test::contains(errorOf("keyframe = 3\n"), "p.toml:1: keyframe: expected an array of tables"));

    // A sun on one keyframe only.
    text = kTwoKeys + "sun_elevation_deg = 10\nsun_azimuth_deg = 20\n";
    EXPECT_TRUE(test::contains(errorOf(text), "every keyframe places the sun, or none does")) << errorOf(text);
    text = kTwoKeys + "sun_elevation_deg = 10\n";
    EXPECT_TRUE(test::contains(errorOf(text), "p.toml:18: keyframe[1].sun_elevation_deg: needs 'sun_azimuth_deg'"))
        << errorOf(text);
}

TEST(CameraPathParse, TimesMustStrictlyIncrease) {
    std::string text = kTwoKeys;
    text.replace(text.find("time_s = 2"), 10, "time_s = 0");
    EXPECT_TRUE(test::contains(errorOf(text), "p.toml:11: keyframe[1].time_s: time 0 s is not after")) << errorOf(text);
    text = kTwoKeys;
    text.replace(text.find("time_s = 2"), 10, "time_s = -1");
    EXPECT_TRUE(test::contains(errorOf(text), "p.toml:11: keyframe[1].time_s")) << errorOf(text);
}

TEST(CameraPathParse, TooFewKeyframes) {
    const std::string one = kTwoKeys.substr(0, kTwoKeys.find("[[keyframe]]", 40));
    EXPECT_TRUE(test::contains(errorOf(one), "p.toml:3: keyframe: a path needs at least 2 keyframes, this one has 1"))
        << errorOf(one);
    EXPECT_TRUE(test::contains(errorOf("description = \"x\"\n"), "p.toml: keyframe: no keyframes"))
        << errorOf("description = \"x\"\n");
}

TEST(CameraPathParse, UnknownKeysAreWarnings) {
    std::vector<std::string> warnings;
    parseCameraPath("fsp = 3\n" + kTwoKeys + "headng_deg = 3\n", "p.toml", "p", &warnings);
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_TRUE(test::contains(warnings[0], "p.toml:1: unknown key 'fsp'")) << warnings[0];
    EXPECT_TRUE(test::contains(warnings[0], "'fps'")) << warnings[0];
    EXPECT_TRUE(test::contains(warnings[1], "p.toml:19: unknown key 'keyframe[1].headng_deg'")) << warnings[1];
}

TEST(CameraPathFrames, PatternsNameEachFrame) {
    EXPECT_EQ(frameFileName("seq/f_%04d.png", 7), "seq/f_0007.png");
    EXPECT_EQ(frameFileName("f%d.exr", 12), "f12.exr");
    EXPECT_EQ(frameFileName("100%%_%3d.png", 5), "100%_  5.png");
    EXPECT_FALSE(hasFramePattern("still.png"));
    EXPECT_FALSE(hasFramePattern("a%04d_%04d.png"));
    EXPECT_FALSE(hasFramePattern("a%s.png"));
    EXPECT_THROW(frameFileName("still.png", 0), InputError);
}

TEST(CameraPathInterp, PassesThroughTheKeyframes) {
    const CameraPathFile file = climb();
    const CameraPath path(file, kRadius);
    for (const PathKeyframe& k : file.keyframes) {
        const Camera expected = cameraAtGeographic(k.latitude_deg, k.longitude_deg, k.altitude_m, k.heading_deg,
                                                   k.pitch_deg, k.fov_deg, kRadius);
        const PathSample s = path.sample(k.time_s);
        EXPECT_LT(glm::length(s.camera.position - expected.position), 1e-6) << k.time_s;
        EXPECT_NEAR(s.camera.altitude(kRadius), k.altitude_m, 1e-6 * k.altitude_m);
        EXPECT_NEAR(glm::length(s.camera.forward() - expected.forward()), 0.0, 1e-9) << k.time_s;
        EXPECT_NEAR(glm::length(s.camera.up() - expected.up()), 0.0, 1e-9) << k.time_s;
        EXPECT_NEAR(s.camera.fovY_rad, glm::radians(k.fov_deg), 1e-12);
        EXPECT_NEAR(*s.sun_elevation_deg, *k.sun_elevation_deg, 1e-9);
        EXPECT_NEAR(std::remainder(*s.sun_azimuth_deg - *k.sun_azimuth_deg, 360.0), 0.0, 1e-9);
        EXPECT_NEAR(s.latitude_deg, k.latitude_deg, 1e-9);
        EXPECT_NEAR(std::remainder(s.longitude_deg - k.longitude_deg, 360.0), 0.0, 1e-9);
    }
    // Outside the path: clamped to its ends.
    EXPECT_EQ(path.sample(-5.0).camera.position, path.sample(0.0).camera.position);
    EXPECT_EQ(path.sample(100.0).camera.position, path.sample(20.0).camera.position);
}

TEST(CameraPathInterp, GroundRaisesTheKeyframes) {
    const CameraPathFile file = climb();
    const CameraPath path(file, kRadius, [](const glm::dvec3&) { return 300.0; });
    EXPECT_NEAR(path.sample(0.0).camera.altitude(kRadius), 302.0, 1e-6);
    EXPECT_NEAR(path.sample(20.0).camera.altitude(kRadius), 400300.0, 1e-3);
}

TEST(CameraPathInterp, ContinuousWithC1PositionAndOrthonormalOrientation) {
    const CameraPathFile file = climb();
    const CameraPath path(file, kRadius);
    const double eps = 1e-6;
    for (const PathKeyframe& k : file.keyframes) {
        const double t = k.time_s;
        const PathSample at = path.sample(t);
        const PathSample before = path.sample(t - eps), after = path.sample(t + eps);
        // Continuity: a microsecond moves the camera by about speed * 1e-6 (speed is < 1e6 m/s here).
        EXPECT_LT(glm::length(before.camera.position - at.camera.position), 1.0) << t;
        EXPECT_LT(glm::length(after.camera.position - at.camera.position), 1.0) << t;
        EXPECT_LT(glm::length(before.camera.forward() - after.camera.forward()), 1e-4) << t;
        if (t == file.startTime() || t == file.endTime()) continue;
        // C1: one-sided velocities either side of the keyframe agree (relative to the speed).
        const double h = 1e-4;
        const glm::dvec3 left = (at.camera.position - path.sample(t - h).camera.position) / h;
        const glm::dvec3 right = (path.sample(t + h).camera.position - at.camera.position) / h;
        const double speed = std::max(glm::length(left), 1e-3);
        EXPECT_LT(glm::length(left - right) / speed, 1e-2) << t;  // O(h) from the curvature
        // A finer step halves the gap: the left and right derivatives are the same.
        const double h2 = h / 8.0;
        const glm::dvec3 left2 = (at.camera.position - path.sample(t - h2).camera.position) / h2;
        const glm::dvec3 right2 = (path.sample(t + h2).camera.position - at.camera.position) / h2;
        EXPECT_LT(glm::length(left2 - right2), glm::length(left - right) / 4.0 + 1e-6 * speed) << t;
    }
    // Orthonormal frames and monotone altitude all along.
    double previousAltitude = 0.0;
    for (int i = 0; i <= 2000; ++i) {
        const double t = 20.0 * i / 2000.0;
        const Camera c = path.sample(t).camera;
        const glm::dmat3 m = c.worldFromView();
        const glm::dmat3 identity = glm::transpose(m) * m;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) ASSERT_NEAR(identity[a][b], a == b ? 1.0 : 0.0, 1e-12) << t;
        ASSERT_NEAR(glm::determinant(m), 1.0, 1e-12);
        const double altitude = c.altitude(kRadius);
        ASSERT_GE(altitude, previousAltitude - 1e-6) << t;  // the climb never dips
        ASSERT_GE(altitude, 2.0 - 1e-9) << t;
        previousAltitude = altitude;
    }
}

class RenderPathTest : public test::CliFixture {
protected:
    void SetUp() override {
        CliFixture::SetUp();
        shareCloudCache();
    }
};

TEST_F(RenderPathTest, RendersNumberedFramesOfAMovingCamera) {
    std::ofstream(dir / "tiny.toml") << pathToml("tiny", 1, {{0, 20, 10, 400000, 90, -20, 60, 180},
                                                           {10, 20, 10, 400000, 150, -50, 60, 180}});
    const auto r = test::runCommand(
        planet("render --path tiny.toml --frames 3 --size 32x18 --tables reduced --out seq/f_%04d.png "
               "--out seq/f_%02d.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(test::contains(r.output, "frame 3 of 3")) << r.output;
    EXPECT_TRUE(test::contains(r.output, "left")) << r.output;
    std::vector<std::vector<unsigned char>> frames;
    for (int i = 0; i < 3; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "seq/f_%04d.png", i);
        int w = 0, h = 0, n = 0;
        unsigned char* png = stbi_load((dir / name).c_str(), &w, &h, &n, 4);
        ASSERT_NE(png, nullptr) << name;
        EXPECT_EQ(w, 32);
        EXPECT_EQ(h, 18);
        frames.emplace_back(png, png + 32 * 18 * 4);
        stbi_image_free(png);
        std::snprintf(name, sizeof name, "seq/f_%02d.exr", i);
        EXPECT_TRUE(fs::exists(dir / name)) << name;
    }
    EXPECT_FALSE(fs::exists(dir / "seq" / "f_0003.png"));
    for (int i = 0; i + 1 < 3; ++i) {
        long difference = 0;
        for (std::size_t p = 0; p < frames[i].size(); ++p) difference += std::abs(frames[i][p] - frames[i + 1][p]);
        EXPECT_GT(difference, 32 * 18) << "frames " << i << " and " << i + 1 << " are (nearly) the same";
    }
}

TEST_F(RenderPathTest, BadSequenceArgumentsFail) {
    auto r = test::runCommand(planet("render --path takeoff --out still.png --size 32x18"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_TRUE(test::contains(r.output, "frame number")) << r.output;
    r = test::runCommand(planet("render --frames 3 --out f_%d.png --size 32x18"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_TRUE(test::contains(r.output, "--frames needs --path")) << r.output;
    r = test::runCommand(planet("render --path nowhere --out f_%d.png --size 32x18"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_TRUE(test::contains(r.output, "available paths: cumulus_wind, takeoff, twilight")) << r.output;
    EXPECT_FALSE(fs::exists(dir / "f_0.png"));
}

TEST_F(RenderPathTest, TheExplorerPlaysAPathAsRenderRendersIt) {
    // `explore --path` shows one path frame per window frame: with the panels hidden, its
    // third window frame is render --path's frame 2, pixel for pixel (the same camera, sun,
    // clock and frame history). Needs a window: Xvfb.
    std::ofstream(dir / "turn.toml") << pathToml("turn", 4, {{0, 20, 10, 400000, 90, -20, 40, 180},
                                                           {2, 22, 12, 300000, 150, -40, 50, 190}});
    const auto render = test::runCommand(planet("render --path turn.toml --size 160x90 --out f_%d.png"));
    ASSERT_EQ(render.exitCode, 0) << render.output;
    const auto r = test::runCommand("cd '" + dir.string() + "' && XDG_CONFIG_HOME='" + (dir / "config").string() +
                                    "' PLANET_TABLES=reduced xvfb-run -a -s '-screen 0 640x480x24' '" PLANET_EXE
                                    "' explore --no-panels --path turn.toml --size 160x90 --frames 3 --screenshot w.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(test::contains(r.output, "playing path 'turn': 9 frames")) << r.output;
    int w1, h1, n1, w2, h2, n2;
    unsigned char* a = stbi_load((dir / "f_2.png").c_str(), &w1, &h1, &n1, 4);
    unsigned char* b = stbi_load((dir / "w.png").c_str(), &w2, &h2, &n2, 4);
    unsigned char* first = stbi_load((dir / "f_0.png").c_str(), &w2, &h2, &n2, 4);
    ASSERT_TRUE(a && b && first);
    ASSERT_EQ(w1, w2);
    ASSERT_EQ(h1, h2);
    int differing = 0, moved = 0;
    for (int i = 0; i < w1 * h1 * 4; ++i) {
        differing += a[i] != b[i];
        moved += a[i] != first[i];
    }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(moved, w1 * h1);  // the camera did move between frames 0 and 2
    stbi_image_free(a);
    stbi_image_free(b);
    stbi_image_free(first);
}

}  // namespace
}  // namespace planet
