// The `planet` executable end to end: help, render to PNG and EXR, bench,
// the explorer (headless fallback, and a real window under Xvfb), and bad
// input that must fail with a clear message and write nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <stb_image.h>

#include "process.h"
#include "test_util.h"
#include "render/image_io.h"

namespace fs = std::filesystem;
using planet::test::runCommand;

namespace {

// The commands with the default preset: its clouds come from one shared cache.
class CliTest : public planet::test::CliFixture {
protected:
    void SetUp() override {
        CliFixture::SetUp();
        shareCloudCache();
    }
};

using planet::test::contains;

}  // namespace

TEST_F(CliTest, HelpDescribesEveryCommandAndOption) {
    const auto top = runCommand(planet("--help"));
    EXPECT_EQ(top.exitCode, 0);
    for (const char* word : {"explore", "render", "bench"}) EXPECT_TRUE(contains(top.output, word)) << word;
    const auto render = runCommand(planet("render --help"));
    EXPECT_EQ(render.exitCode, 0);
    for (const char* word : {"--out", "--size", "--view", "--preset", "--exposure"})
        EXPECT_TRUE(contains(render.output, word)) << word;
    const auto bench = runCommand(planet("bench --help"));
    for (const char* word : {"--views", "--frames", "--csv", "--plot", "--warmup"})
        EXPECT_TRUE(contains(bench.output, word)) << word;
}

TEST_F(CliTest, RenderWritesPngAndExrOfTheRequestedSize) {
    const auto r = runCommand(planet("render --preset earth --view orbit --size 96x54 --out still.png --out still.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, (dir / "still.png").string())) << r.output;

    int w = 0, h = 0, n = 0;
    unsigned char* png = stbi_load((dir / "still.png").c_str(), &w, &h, &n, 4);
    ASSERT_NE(png, nullptr);
    EXPECT_EQ(w, 96);
    EXPECT_EQ(h, 54);
    const unsigned char* bottom = png + ((h - 1) * w + w / 2) * 4;  // ground below the horizon is lit
    const unsigned char* top = png + (w / 2) * 4;                     // space above is black
    EXPECT_GT(bottom[0] + bottom[1] + bottom[2], 60);
    EXPECT_EQ(top[0] + top[1] + top[2], 0);
    stbi_image_free(png);

    const planet::ImageRGBAF exr = planet::readExr(dir / "still.exr");
    EXPECT_EQ(exr.width, 96);
    EXPECT_EQ(exr.height, 54);
    for (float v : exr.pixels) ASSERT_TRUE(std::isfinite(v));
    const float* ground = &exr.pixels[((53) * 96 + 48) * 4];
    EXPECT_GT(ground[1], 0.0f);
}

TEST_F(CliTest, BadArgumentsFailWithAMessageAndWriteNothing) {
    struct Case {
        std::string args, message;
    };
    const Case cases[] = {
        {"render --size huge --out a.png", "--size"},
        {"render --size 0x10 --out a.png", "--size"},
        {"render --view nowhere --out a.png", "orbit"},  // lists the views there are
        {"render --preset nosuch --out a.png", "earth"},  // lists the presets there are
        {"render --out a.jpg", ".png or .exr"},
        {"render", "--out"},
        {"bench --frames 0", "--frames"},
        {"frobnicate", "frobnicate"},
    };
    for (const Case& c : cases) {
        const auto r = runCommand(planet(c.args));
        EXPECT_NE(r.exitCode, 0) << c.args;
        EXPECT_TRUE(contains(r.output, c.message)) << c.args << ":\n" << r.output;
    }
    EXPECT_FALSE(fs::exists(dir / "a.png"));
}

TEST_F(CliTest, ParserErrorsHaveThePrefixAndExitStatusOfEveryOtherError) {
    // CLI11's own exit codes were 104-114, without "planet: error:".
    const char* cases[][2] = {
        {"render --time nan --out a.png", "--time"},
        {"render --tables huge --out a.png", "--tables"},
        {"render --bogus --out a.png", "--bogus"},
        {"render --exposure '' --out a.png", "--exposure"},
        {"bake --size 15", "--size"},
        {"bake --seed -1", "--seed"},
        {"bake --preview a.jpg", ".png"},
        {"bench --plot a.jpg", ".png"},
        {"explore --screenshot a.jpg", ".png"},
    };
    for (const auto& [args, message] : cases) {
        const auto r = runCommand(planet(args));
        EXPECT_EQ(r.exitCode, 1) << args;
        EXPECT_TRUE(r.output.starts_with("planet: error: ")) << args << ":\n" << r.output;
        EXPECT_TRUE(contains(r.output, message)) << args << ":\n" << r.output;
    }
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename(), "cache") << "written: " << entry.path();  // the shared cloud cache's link
    EXPECT_EQ(runCommand(planet("render --help")).exitCode, 0);
    // An empty PNG output is "none", not a bad name.
    EXPECT_FALSE(contains(runCommand(planet("bench --plot '' --frames 0")).output, "--plot")) << "empty --plot refused";
}

TEST_F(CliTest, AFolderGivenForAFileIsNamedAsSuchAndNothingIsLeftBeside) {
    fs::create_directories(dir / "out.png");
    fs::create_directories(dir / "preset.toml");
    fs::create_directories(dir / "cases.csv");
    const char* cases[][2] = {
        {"render --size 16x9 --out out.png", "'out.png': it is a folder"},
        {"render --size 16x9 --preset preset.toml --out a.png", "'preset.toml': it is a folder"},
        {"render --size 16x9 --path preset.toml --out f_%02d.png", "'preset.toml': it is a folder"},
        {"sky-probe --in cases.csv --out a.csv", "cases.csv': it is a folder"},
    };
    for (const auto& [args, message] : cases) {
        const auto r = runCommand(planet(args));
        EXPECT_EQ(r.exitCode, 1) << args;
        EXPECT_TRUE(contains(r.output, message)) << args << ":\n" << r.output;
    }
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename().string());
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, (std::vector<std::string>{"cache", "cases.csv", "out.png", "preset.toml"}));  // no write-test probe
}

TEST_F(CliTest, BadPresetNamesFileLineAndField) {
    std::ofstream(dir / "bad.toml") << "name = \"bad\"\n[planet]\nradius_km = -5.0\n";
    const auto r = runCommand(planet("render --preset bad.toml --size 32x18 --out a.png"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_TRUE(contains(r.output, "bad.toml:3")) << r.output;
    EXPECT_TRUE(contains(r.output, "planet.radius_km")) << r.output;
    EXPECT_FALSE(fs::exists(dir / "a.png"));

    std::ofstream(dir / "broken.toml") << "[planet\nradius_km = 1\n";
    const auto m = runCommand(planet("render --preset broken.toml --size 32x18 --out a.png"));
    EXPECT_NE(m.exitCode, 0);
    EXPECT_TRUE(contains(m.output, "broken.toml:")) << m.output;
}

TEST_F(CliTest, UnknownPresetKeyWarnsButRenders) {
    std::ofstream(dir / "extra.toml") << "[planet]\nradius_km = 6360.0\nmountains = 3\n";
    const auto r = runCommand(planet("render --preset extra.toml --size 32x18 --out a.png"));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "planet.mountains")) << r.output;
    EXPECT_TRUE(fs::exists(dir / "a.png"));
}

TEST_F(CliTest, BenchWritesTableCsvAndPlot) {
    const auto r = runCommand(planet("bench --size 48x27 --frames 3 --warmup 1 --views '" PLANET_SOURCE_DIR
                                     "/assets/views/orbit.toml' --views '" PLANET_SOURCE_DIR
                                     "/assets/views/space.toml' --csv b.csv --plot b.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "planet bench on ")) << r.output;  // names the GL renderer
    EXPECT_TRUE(contains(r.output, "gpu med ms")) << r.output;

    std::ifstream csv(dir / "b.csv");
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header, "renderer,width,height,view,pass,frames,gpu_median_ms,gpu_p95_ms,cpu_median_ms,cpu_p95_ms,"
                      "cloud_steps_per_pixel,cloud_skipped_share,wait_median_ms,wait_p95_ms");
    // A software renderer is named as one, with what its timings mean.
    if (contains(r.output, "llvmpipe")) {
        EXPECT_TRUE(contains(r.output, "software renderer (the GPU is the CPU)")) << r.output;
        // and its passes are finished one by one (--finish-each-pass auto), so CPU + wait is each one's own work
        EXPECT_TRUE(contains(r.output, "each pass waits for the work before it")) << r.output;
    }
    int rows = 0;
    bool sawSpaceTonemap = false;
    while (std::getline(csv, line)) {
        ++rows;
        sawSpaceTonemap = sawSpaceTonemap || contains(line, ",space,tonemap,3,");
    }
    // (prepare, terrain, terrain shadow, surface light, ocean, terrain reflection, sky march, sky temporal, sky
    // refine, tonemap, frame) x 2 views: the warm-up frame of each view is the full-rate one (the view jumped), the
    // recorded ones reduced-rate
    EXPECT_EQ(rows, 2 * 11);
    EXPECT_TRUE(sawSpaceTonemap);

    int w = 0, h = 0, n = 0;
    ASSERT_TRUE(stbi_info((dir / "b.png").c_str(), &w, &h, &n));
    EXPECT_GT(w, 100);
}

TEST_F(CliTest, BenchShowsItsLinesWhileItRunsIntoAPipe) {
    // Into a pipe (`planet bench ... | tee log`) the bench's lines come as they are written, not all at
    // its end: its first line (written before it builds the renderer, compiles its programs and renders
    // its frames: seconds on llvmpipe) reaches the reader well before the pipe closes. Fully buffered,
    // every line comes at the exit, a few milliseconds before the end.
    const std::string times = (dir / "times").string();
    const auto r = runCommand(planet("bench --size 48x27 --frames 2 --warmup 1 --views '" PLANET_SOURCE_DIR
                                     "/assets/views/orbit.toml' --csv '' --plot ''") +
                              " | { IFS= read -r line; date +%s.%N > '" + times + "'; cat > /dev/null; date +%s.%N >> '" +
                              times + "'; }");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(times);
    double firstLine = 0.0, end = 0.0;
    ASSERT_TRUE(in >> firstLine >> end);
    EXPECT_GT(end - firstLine, 0.5) << "the bench's first line reached the pipe only as it ended";
}

TEST_F(CliTest, BenchAntialiasTimesTheExplorersFrames) {
    // --antialias: each frame jittered and blended as the explorer does, so the pass "antialias"
    // runs and is timed (the bench's frames are otherwise unjittered, without it).
    const auto r = runCommand(planet("bench --antialias --size 48x27 --frames 2 --warmup 1 --views '" PLANET_SOURCE_DIR
                                     "/assets/views/orbit.toml' --csv a.csv --plot ''"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "anti-aliased as in the explorer")) << r.output;
    std::ifstream csv(dir / "a.csv");
    std::string text((std::istreambuf_iterator<char>(csv)), {});
    EXPECT_TRUE(contains(text, ",orbit,antialias,2,")) << text;
}

TEST_F(CliTest, BenchTerrainSuiteSweepsGridSizeAndOctaves) {
    const auto r = runCommand(planet("bench --suite terrain --size 32x18 --frames 1 --warmup 0 --views '" PLANET_SOURCE_DIR
                                     "/assets/views/orbit.toml' --csv t.csv --plot ''"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream csv(dir / "t.csv");
    std::string text((std::istreambuf_iterator<char>(csv)), {});
    for (const char* config : {"g50/continents", "g50/o1", "g100/o5", "g200/o10"})
        EXPECT_TRUE(contains(text, std::string(",") + config + ",terrain,1,")) << config << "\n" << text;
    std::size_t configurations = 0;  // one terrain row per configuration, whatever the other passes
    for (std::size_t at = text.find(",terrain,"); at != std::string::npos; at = text.find(",terrain,", at + 1))
        ++configurations;
    EXPECT_EQ(configurations, 12u);  // grid 50/100/200 x continents only, 1, 5, 10 noise layers
}

TEST_F(CliTest, BenchCloudsSuiteSweepsStepAndSunSamplesAndCountsMarchSteps) {
    const auto r = runCommand(planet("bench --suite clouds --size 32x18 --frames 1 --warmup 0 --csv c.csv --plot ''"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream csv(dir / "c.csv");
    std::string text((std::istreambuf_iterator<char>(csv)), {});
    // The five cloud views at the reduced rate (still, and with the clock running) and at the
    // full rate and the 3 x 4 sweep on the first, each with a frame row holding the march's
    // steps per pixel and skipped share.
    std::map<std::string, std::pair<double, double>> frames;
    std::istringstream lines(text);
    std::string line;
    std::getline(lines, line);
    EXPECT_TRUE(contains(line, "cloud_steps_per_pixel,cloud_skipped_share")) << line;
    while (std::getline(lines, line)) {
        std::vector<std::string> f;
        std::stringstream fields(line);
        for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
        ASSERT_GE(f.size(), 14u) << line;  // the renderer's name, quoted, may hold commas: count from the end
        const std::size_t n = f.size();  // ..., steps per pixel, skipped share, wait median, wait p95
        if (f[n - 10] != "frame") continue;
        frames[f[n - 11]] = {std::stod(f[n - 4]), std::stod(f[n - 3])};
    }
    for (const char* view : {"cumulus", "clouds", "deck", "orbit", "space", "cumulus/clock", "space/clock",
                             "cumulus/full-rate", "space/full-rate", "cumulus/step0.2km/sun0", "cumulus/step0.05km/sun12"})
        EXPECT_TRUE(frames.count(view)) << view << "\n" << text;
    EXPECT_EQ(frames.size(), 5u + 5u + 5u + 12u) << text;
    // The reduced rate marches one pixel of each 4x4 block: about a 16th of the steps per
    // pixel of the image (the blocks at the edges and the jitter make it not exactly that).
    EXPECT_GT(frames["cumulus/full-rate"].first, 8.0 * frames["cumulus"].first);
    EXPECT_LT(frames["cumulus/full-rate"].first, 32.0 * frames["cumulus"].first);
    EXPECT_TRUE(contains(r.output, "ms clock running; full rate")) << r.output;
    // No warm-up: the frame that seeds the history is drawn before the recorded one, and its
    // timings must not land among the recorded (a pass with GPU times and no CPU times: nan).
    EXPECT_FALSE(contains(r.output, "nan")) << r.output;
    EXPECT_TRUE(contains(r.output, "of the full-rate march")) << r.output;
    for (const auto& [view, m] : frames) {
        EXPECT_GE(m.second, 0.0) << view;
        EXPECT_LE(m.second, 1.0) << view;
    }
    // Looking up into a cumulus field takes more steps than the disc seen from space, and a
    // halved step more steps than the preset's.
    EXPECT_GT(frames["cumulus/full-rate"].first, frames["space/full-rate"].first);
    EXPECT_GT(frames["cumulus/step0.05km/sun6"].first, frames["cumulus/step0.1km/sun6"].first);
    // The sun samples do not change the view march.
    EXPECT_EQ(frames["cumulus/step0.1km/sun0"].first, frames["cumulus/step0.1km/sun12"].first);
}

TEST_F(CliTest, BenchOceanSuiteSweepsWaveCounts) {
    const auto r = runCommand(planet("bench --suite ocean --size 32x18 --frames 1 --warmup 0 --csv o.csv --plot ''"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream csv(dir / "o.csv");
    std::string text((std::istreambuf_iterator<char>(csv)), {});
    for (const char* config : {"20 waves", "50 waves", "100 waves", "1000 waves"})  // Michelic Table 2
        EXPECT_TRUE(contains(text, std::string(",") + config + ",ocean,1,")) << config << "\n" << text;
    std::size_t configurations = 0;
    for (std::size_t at = text.find(",ocean,"); at != std::string::npos; at = text.find(",ocean,", at + 1)) ++configurations;
    EXPECT_EQ(configurations, 4u);
}

TEST_F(CliTest, ExploreWithoutDisplayRendersAStillAndSaysWhere) {
    const auto r = runCommand(planet("explore --size 64x36 --headless-out still.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "No display")) << r.output;
    EXPECT_TRUE(contains(r.output, (dir / "still.png").string())) << r.output;
    EXPECT_TRUE(fs::exists(dir / "still.png"));
}

TEST_F(CliTest, TimeMustBeAFiniteNumber) {
    for (const char* bad : {"nan", "inf", "1e10", "soon"}) {
        const auto r = runCommand(planet(std::string("render --size 16x9 --time ") + bad + " --out t.png"));
        EXPECT_NE(r.exitCode, 0) << bad;
        EXPECT_TRUE(contains(r.output, "--time")) << r.output;
        EXPECT_FALSE(fs::exists(dir / "t.png")) << bad;
    }
    const auto ok = runCommand(planet("render --size 16x9 --time 12.5 --out t.png"));
    EXPECT_EQ(ok.exitCode, 0) << ok.output;
}

TEST_F(CliTest, OneBadOutputMeansNoOutputAtAll) {
    // The second output cannot be written: the first must not be left behind.
    const auto r = runCommand(planet("render --size 32x18 --out good.png --out /proc/no/such/x.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_TRUE(contains(r.output, "/proc/no/such/x.exr")) << r.output;
    EXPECT_FALSE(fs::exists(dir / "good.png"));
    const auto b = runCommand(planet("bench --size 16x9 --frames 1 --warmup 0 --csv b.csv --plot /proc/no/plot.png"));
    EXPECT_NE(b.exitCode, 0);
    EXPECT_FALSE(fs::exists(dir / "b.csv"));
}

TEST_F(CliTest, ExposureIsRangeCheckedAndStoredInTheExr) {
    for (const char* bad : {"0", "-1", "inf", "1e30", "nan"}) {
        const auto r = runCommand(planet(std::string("render --size 16x9 --exposure ") + bad + " --out a.exr"));
        EXPECT_NE(r.exitCode, 0) << bad;
        EXPECT_TRUE(contains(r.output, "--exposure")) << bad << ": " << r.output;
    }
    const auto r = runCommand(planet("render --size 16x9 --exposure 3.5 --out a.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_DOUBLE_EQ(planet::readExrExposure(dir / "a.exr"), 3.5);
}

TEST_F(CliTest, ContextWithoutOpenGL45GetsAClearMessage) {
    const auto r = runCommand("cd '" + dir.string() + "' && MESA_GL_VERSION_OVERRIDE=3.3 '" PLANET_EXE
                              "' render --size 16x9 --out a.png");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_TRUE(contains(r.output, "OpenGL 4.5")) << r.output;
    EXPECT_FALSE(fs::exists(dir / "a.png"));
}

TEST_F(CliTest, WindowShowsTheSamePixelsAsTheStill) {
    // With the panels hidden and the temporal march off, the window's frame is the still
    // `render` writes (with it on, the explorer's first frame is reconstructed from a 16th of
    // the pixels and converges over the next ones: tests/test_temporal.cpp).
    for (const char* view : {"orbit", "space"}) {
        const std::string still = std::string(view) + ".png", shot = std::string(view) + "-window.png";
        ASSERT_EQ(runCommand(planet(std::string("render --no-temporal --samples 1 --view ") + view + " --size 160x90 --out " + still))
                      .exitCode,
                  0);
        const auto r = runCommand("cd '" + dir.string() + "' && XDG_CONFIG_HOME='" + (dir / "config").string() +
                                  "' PLANET_TABLES=reduced xvfb-run -a -s '-screen 0 640x480x24' '" PLANET_EXE
                                  "' explore --no-panels --no-temporal --view " + view + " --size 160x90 --frames 3 --screenshot " +
                                  shot);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        int w1, h1, n1, w2, h2, n2;
        unsigned char* a = stbi_load((dir / still).c_str(), &w1, &h1, &n1, 4);
        unsigned char* b = stbi_load((dir / shot).c_str(), &w2, &h2, &n2, 4);
        ASSERT_TRUE(a && b);
        ASSERT_EQ(w1, w2);
        ASSERT_EQ(h1, h2);
        int differing = 0;
        for (int i = 0; i < w1 * h1 * 4; ++i) differing += a[i] != b[i];
        EXPECT_EQ(differing, 0) << view;
        stbi_image_free(a);
        stbi_image_free(b);
    }
}

TEST_F(CliTest, WindowAtARenderScaleShowsTheSmallerFrameScaledUp) {
    // --render-scale 0.5 (what auto picks on llvmpipe for this window: about 320x180 pixels
    // whatever the window) renders a 640x360 window's frame at 320x180 and the window shows it
    // scaled up, bilinearly: the
    // window is the still of that size, each pixel the bilinear mix of the still's four
    // nearest (the GL blit's sample positions, edges clamped), to the blit's rounding.
    ASSERT_EQ(runCommand(planet("render --no-temporal --samples 1 --view orbit --size 320x180 --out still.png")).exitCode,
              0);
    const auto r = runCommand("cd '" + dir.string() + "' && XDG_CONFIG_HOME='" + (dir / "config").string() +
                              "' PLANET_TABLES=reduced xvfb-run -a -s '-screen 0 800x600x24' '" PLANET_EXE
                              "' explore --no-panels --no-temporal --view orbit --size 640x360 --render-scale 0.5 --frames 3 --screenshot "
                              "window.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "the frame is 320x180, shown at 640x360 (render scale 0.5)")) << r.output;
    int sw, sh, n, w, h;
    unsigned char* still = stbi_load((dir / "still.png").c_str(), &sw, &sh, &n, 4);
    unsigned char* window = stbi_load((dir / "window.png").c_str(), &w, &h, &n, 4);
    ASSERT_TRUE(still && window);
    ASSERT_EQ(sw, 320);
    ASSERT_EQ(w, 640);
    ASSERT_EQ(h, 360);
    const auto texel = [&](int x, int y, int c) {
        return static_cast<double>(still[4 * (std::clamp(y, 0, sh - 1) * sw + std::clamp(x, 0, sw - 1)) + c]);
    };
    int off = 0;
    double lit = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double u = (x + 0.5) * sw / w - 0.5, v = (y + 0.5) * sh / h - 0.5;
            const int x0 = static_cast<int>(std::floor(u)), y0 = static_cast<int>(std::floor(v));
            const double fx = u - x0, fy = v - y0;
            int worst = 0;
            for (int c = 0; c < 3; ++c) {
                const double bilinear = (1 - fy) * ((1 - fx) * texel(x0, y0, c) + fx * texel(x0 + 1, y0, c)) +
                                        fy * ((1 - fx) * texel(x0, y0 + 1, c) + fx * texel(x0 + 1, y0 + 1, c));
                worst = std::max(worst, static_cast<int>(std::lround(std::abs(bilinear - window[4 * (y * w + x) + c]))));
                lit += window[4 * (y * w + x) + c];
            }
            off += worst > 2;
        }
    std::printf("%d of %d window pixels more than 2 levels off the still scaled up\n", off, w * h);
    EXPECT_GT(lit / (3.0 * w * h), 10.0);  // a picture, not a black window
    EXPECT_LE(off, w * h / 200);
    stbi_image_free(still);
    stbi_image_free(window);
}

TEST_F(CliTest, ExplorerWindowRunsUnderXvfbAndShowsPanels) {
    // The one test that needs a window: Xvfb provides an X server (GLX on llvmpipe). At
    // 1280x720 the panels start compact (the frame-time panel open, the others collapsed):
    // against the still of the same view, at most 30 % of the pixels differ (every pixel
    // rendered: --render-scale 1, not auto's 320x180 on llvmpipe). The layout is
    // kept in the user's config folder ($XDG_CONFIG_HOME/planet/imgui.ini), not here.
    // The still first: it caches the tables, so the window starts from them rather than from
    // starter tables (whose sky would count as covered pixels).
    const auto still = runCommand(planet("render --view space --size 1280x720 --out still.png"));
    ASSERT_EQ(still.exitCode, 0) << still.output;
    const std::string cmd = "cd '" + dir.string() + "' && XDG_CONFIG_HOME='" + (dir / "config").string() +
                            "' PLANET_TABLES=reduced xvfb-run -a -s '-screen 0 1400x900x24' '" PLANET_EXE
                            "' explore --view space --size 1280x720 --render-scale 1 --frames 4 --screenshot window.png";
    const auto r = runCommand(cmd);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "atmosphere tables from the cache")) << r.output;
    int w = 0, h = 0, n = 0, sw = 0, sh = 0;
    unsigned char* png = stbi_load((dir / "window.png").c_str(), &w, &h, &n, 4);
    unsigned char* ref = stbi_load((dir / "still.png").c_str(), &sw, &sh, &n, 4);
    ASSERT_NE(png, nullptr) << r.output;
    ASSERT_NE(ref, nullptr) << still.output;
    EXPECT_EQ(w, 1280);
    EXPECT_EQ(h, 720);
    ASSERT_EQ(sw, w);
    ASSERT_EQ(sh, h);
    // The space view leaves the top-left corner black in the still; in the
    // window the "Frame time" panel covers it, so it is not black there.
    const unsigned char* p = png + (20 * w + 20) * 4;
    EXPECT_GT(p[0] + p[1] + p[2], 0);
    int covered = 0;
    for (int i = 0; i < w * h; ++i)
        covered += std::abs(png[4 * i] - ref[4 * i]) + std::abs(png[4 * i + 1] - ref[4 * i + 1]) +
                       std::abs(png[4 * i + 2] - ref[4 * i + 2]) > 24;
    const double share = static_cast<double>(covered) / (w * h);
    std::printf("the panels cover %.1f %% of the 1280x720 view at start\n", 100.0 * share);
    EXPECT_LE(share, 0.30);
    EXPECT_GT(share, 0.03);
    stbi_image_free(png);
    stbi_image_free(ref);
    std::ifstream ini(dir / "config" / "planet" / "imgui.ini");
    const std::string layout((std::istreambuf_iterator<char>(ini)), {});
    EXPECT_TRUE(contains(layout, "[Window][Frame time]")) << layout;
    EXPECT_FALSE(fs::exists(dir / "imgui.ini"));
}
