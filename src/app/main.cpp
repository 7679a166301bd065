// planet: command-line front end (CLI11). See README.md for every command.
#include <CLI/CLI.hpp>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <stdexcept>

#include "app/commands.h"
#include "app/render_scale.h"
#include "atmosphere/tables.h"

namespace {

// A finite number in [lo, hi]. CLI::Range lets NaN through (every comparison with it is false),
// and an empty argument would leave the option unset without a word.
CLI::Validator finiteIn(double lo, double hi, const std::string& what) {
    return CLI::Validator(
        [lo, hi, what](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (text.empty() || end == text.c_str() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
                return "must be " + what + ", not '" + text + "'";
            return {};
        },
        "NUMBER");
}

// What `parse` accepts: its std::invalid_argument's message is the option's error.
template <typename Parse>
std::function<std::string(const std::string&)> acceptedBy(Parse parse) {
    return [parse](const std::string& choice) -> std::string {
        try {
            parse(choice);
            return {};
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
    };
}

// An output that is written as PNG must be named so: PNG bytes under a .jpg name mislead.
const CLI::Validator kPngFile(
    [](std::string& text) -> std::string {
        if (text.empty()) return {};  // none (bench --plot '')
        const std::size_t dot = text.find_last_of('.');
        std::string extension = dot == std::string::npos ? "" : text.substr(dot);
        for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (extension != ".png") return "'" + text + "': only PNG is written here, name it .png";
        return {};
    },
    "FILE.png");

void addCommon(CLI::App& cmd, planet::CommonOptions& o) {
    cmd.add_option("--root", o.root, "Data folder holding shaders/ and assets/ (default: PLANET_ROOT or the source tree)");
    cmd.add_option("--preset", o.preset, "Preset name under assets/presets/ or a path to a .toml file")
        ->capture_default_str();
    cmd.add_option("--view", o.view, "View bookmark name under assets/views/ (ground, beach, clouds, orbit, space, ...)")
        ->capture_default_str();
    cmd.add_option("--size", o.size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd.add_option("--tables", o.tables,
                   "Atmosphere table sizes: full, medium, reduced, auto (medium on software renderers such as llvmpipe, "
                   "else full), or explicit RxMUxMU_SxNU[,TWxTH[,IWxIH]] (scattering r, mu, mu_s, nu; transmittance; "
                   "irradiance); default: $PLANET_TABLES, else auto")
        ->envname("PLANET_TABLES")
        ->check(acceptedBy([](const std::string& choice) { planet::atmosphere::tableSizesFor(choice, ""); }))
        ->capture_default_str();
    cmd.add_option("--time", o.time, "Clock of the first frame, s (the ocean's waves move with it)")
        ->check(finiteIn(-1e9, 1e9, "a finite number of seconds in [-1e9, 1e9]").name("SECONDS"))
        ->capture_default_str();
    cmd.add_flag("--no-temporal", o.noTemporal,
                 "March clouds and air in every pixel every frame (the preset's render.temporal off): reference frames");
    cmd.add_flag("--gl-debug", o.glDebug, "Ask for a debug GL context and report KHR_debug messages synchronously");
}

}  // namespace

int main(int argc, char** argv) {
    // Progress and table rows a line at a time even into a file or a pipe (`planet bench ... | tee log`):
    // a long suite would otherwise show nothing until it ends.
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    CLI::App app{"planet " PLANET_VERSION ": real-time procedural planets on OpenGL 4.5.\n"
                 "Run with no command to open the explorer (or render a still when there is no display)."};
    app.set_version_flag("--version", std::string("planet ") + PLANET_VERSION);

    planet::ExploreOptions explore;
    CLI::App* exploreCmd = app.add_subcommand("explore", "Interactive window: fly from the ground to space, tune "
                                                         "parameters, see per-pass frame time (the default)");
    addCommon(*exploreCmd, explore.common);
    exploreCmd->add_option("--frames", explore.frames, "Quit after this many frames (0: run until closed)");
    exploreCmd->add_option("--screenshot", explore.screenshot, "Write a PNG of the window, panels included, at the end")
        ->check(kPngFile);
    exploreCmd->add_flag("--no-panels", explore.noPanels, "Start with the panels hidden (F1 toggles them)");
    exploreCmd->add_option("--render-scale", explore.renderScale,
                           "Share of the window's width and height the frame is rendered at, shown scaled up: 0.1-1, "
                           "or auto (1 on a GPU; on a software renderer such as llvmpipe, about 320x180 pixels, so "
                           "the window stays interactive). The Frame time panel changes it live")
        ->check(acceptedBy([](const std::string& choice) { planet::parseRenderScale(choice); }))
        ->capture_default_str();
    exploreCmd->add_option("--path", explore.path,
                           "Play a camera path (name under assets/paths or a file), one path frame (1 / fps) per "
                           "window frame, as planet render --path renders it; P pauses and resumes, the camera is "
                           "yours while paused");
    exploreCmd->add_option("--headless-out", explore.headlessOut, "Where the still goes when there is no display")
        ->capture_default_str();

    planet::RenderOptions render;
    CLI::App* renderCmd = app.add_subcommand("render", "Render a still headlessly (EGL) to PNG and/or OpenEXR");
    addCommon(*renderCmd, render.common);
    renderCmd->add_option("--out,-o", render.outputs,
                          "Output file(s): .png = tone-mapped sRGB, .exr = linear HDR radiance (half RGBA)")
        ->required();
    renderCmd->add_option("--exposure", render.exposure, "Override the preset's exposure, [0.001, 1000]")
        ->check(finiteIn(1e-3, 1e3, "a number in [0.001, 1000]"));
    renderCmd->add_option("--path", render.path,
                          "Camera path (name under assets/paths/ or a .toml file): render its frames in sequence to "
                          "numbered files, each --out a printf pattern such as seq/f_%04d.png (--view is ignored)");
    renderCmd->add_option("--frames", render.frames,
                          "With --path: this many frames evenly over the whole path (default: duration x fps + 1)");
    renderCmd->add_option("--samples", render.samples,
                          "Anti-aliasing: average this many frames, each with the projection moved by a sub-pixel "
                          "offset and marched at full rate, in linear HDR before tone mapping, [1, 256] (default " +
                              std::to_string(planet::kStillSamples) +
                              " for a still, 1 with --path; 1 = one unjittered frame, what the explorer shows)")
        ->check(CLI::Range(1, 256));

    planet::BenchOptions bench;
    CLI::App* benchCmd = app.add_subcommand("bench", "Time each pass over scripted views; table, CSV and plot");
    addCommon(*benchCmd, bench.common);
    benchCmd->add_option("--views", bench.views, "View files or folders of them (default: assets/views)");
    benchCmd->add_option("--suite", bench.suite,
                         "views: every view as set up; terrain: grid 50/100/200 x continents only, 1, 5, 10 noise "
                         "layers on the first view (Michelic Table 1); ocean: 20/50/100/1000 waves on the view 'sea' "
                         "(Michelic Table 2); clouds: the views cumulus, clouds, deck, orbit, space, each at the "
                         "reduced and the full rate, then cloud step 0.2/0.1/0.05 km x 0/3/6/12 sun samples on the "
                         "first, with march steps per pixel and the share skipped through empty space; temporal: "
                         "every frame of --path with the temporal march against the full-rate march (errors per "
                         "frame to the CSV, the worst frame's images beside it); soak: --frames frames (e.g. 10000) along a path "
                         "through every view, an edit every 100 frames, resident memory and live GL objects "
                         "sampled to the CSV (exit 1 when either grows)")
        ->check(CLI::IsMember({"views", "terrain", "ocean", "clouds", "temporal", "soak"}))
        ->capture_default_str();
    benchCmd->add_option("--frames", bench.frames, "Recorded frames per view")->capture_default_str();
    benchCmd->add_option("--path", bench.path, "--suite temporal: the camera path (name under assets/paths or a file)")
        ->capture_default_str();
    benchCmd->add_option("--path-frames", bench.pathFrames,
                         "--suite temporal: this many frames evenly over the path (default: duration x fps + 1)");
    benchCmd->add_option("--finish-each-pass", bench.finishEachPass,
                         "Wait for the GPU before and after each pass, so that its time is its own work: on, off, or auto "
                         "(on for software renderers such as llvmpipe, where a pass's wait otherwise holds the passes "
                         "before it and the timestamps are coarse)")
        ->check(CLI::IsMember({"auto", "on", "off"}))
        ->capture_default_str();
    benchCmd->add_flag("--antialias", bench.antialias,
                       "Anti-alias every frame the bench renders (its full-rate ones too) as the explorer does while "
                       "its temporal march is on and no path plays: the projection moved by a sub-pixel jitter each "
                       "frame, the frames blended over time (the bench's frames are otherwise unjittered, as `planet "
                       "render` draws them)");
    benchCmd->add_option("--warmup", bench.warmup, "Unrecorded frames per view before recording")->capture_default_str();
    benchCmd->add_option("--csv", bench.csv, "CSV output (empty: none)")->capture_default_str();
    benchCmd->add_option("--plot", bench.plot, "Plot PNG output (empty: none)")->check(kPngFile)->capture_default_str();

    planet::PrecomputeOptions precompute;
    CLI::App* precomputeCmd = app.add_subcommand(
        "precompute", "Precompute the preset's atmosphere tables (GPU, headless) into the cache; time each step");
    addCommon(*precomputeCmd, precompute.common);
    precomputeCmd->add_flag("--reference", precompute.reference,
                            "Use the CPU reference (double precision, multi-threaded) instead of the GPU");
    precomputeCmd->add_option("--cache", precompute.cache,
                              "Cache root; tables go to DIR/<key>/ (default: $PLANET_CACHE, else cache/atmosphere)");
    precomputeCmd->add_flag("--force", precompute.force, "Rebuild even when valid cached tables exist");

    planet::SkyProbeOptions skyProbe;
    CLI::App* skyProbeCmd = app.add_subcommand(
        "sky-probe", "Evaluate sky radiance / solar irradiance (1/sr) and transmittance for rows of a CSV, through "
                     "the clouds when the preset has them on");
    addCommon(*skyProbeCmd, skyProbe.common);
    skyProbeCmd->footer(
        "Rays in a local frame: camera at (0, 0, planet radius + altitude), sun (sin sz, 0, cos sz), view "
        "(sin vz cos az, sin vz sin az, cos vz); no ground reflection, no sun disc.\n"
        "Clouds: with the preset's clouds.enabled = true each ray goes through the unified march of clouds and "
        "atmosphere (the sky pass's MarchView, no jitter, no far field), up to the ground where it hits it; the "
        "frame is then the planet's: the camera above the north pole, the sun towards longitude 0; --time drifts "
        "the clouds with the wind. The baked volume and weather map come from the cloud cache (baked there if "
        "missing). clouds.constant_density = true in the preset gives a uniform layer of density "
        "clouds.density_scale for analytic checks; clouds.enabled = false the clear sky.");
    skyProbeCmd->add_option("--in", skyProbe.in,
                            "Input CSV: altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg")
        ->required();
    skyProbeCmd->add_option("--out,-o", skyProbe.out,
                            "Output CSV: the input columns + radiance_r,g,b (1/sr) + transmittance_r,g,b")
        ->required();
    skyProbeCmd->add_flag("--reference", skyProbe.reference,
                          "Evaluate on the CPU (double) with CPU reference tables instead of the GPU (with clouds: "
                          "the same march compiled as C++, clouds/cloud_reference.h)");
    skyProbeCmd->add_option("--against", skyProbe.against,
                            "A reference output CSV of the same rays (e.g. from --reference --tables full): print "
                            "the radiance error's median and worst, daylight and twilight/horizon rays apart")
        ->check(CLI::ExistingFile);
    skyProbeCmd->add_option("--cache", skyProbe.cache,
                            "Table cache root (default: $PLANET_CACHE, else cache/atmosphere)");

    planet::BakeOptions bake;
    CLI::App* bakeCmd = app.add_subcommand(
        "bake", "Bake what a preset needs into the cache: the continents cube map (fBm simplex elevation and "
                "gradient) and, with clouds, the cloud density volume and the weather map; optional preview PNGs");
    bakeCmd->add_option("--preset", bake.preset, "Preset whose [terrain] parameters to bake for")->capture_default_str();
    bakeCmd->add_option("--root", bake.root,
                        "Data folder with shaders/ and assets/ (default: $PLANET_ROOT, else the source tree)");
    bakeCmd->add_option("--size", bake.size, "Cube face size in texels, [16, 2048] (default: the preset's "
                                             "terrain.continent_map_size)")
        ->check(CLI::Range(16, 2048));
    bakeCmd->add_option("--seed", bake.seed, "Noise seed, [0, 1000000] (default: the preset's terrain.seed)")
        ->check(CLI::Range(0, 1000000));
    bakeCmd->add_option("--sea-fraction", bake.seaFraction,
                        "Fraction of the surface under water, [0, 1] (default: the preset's terrain.sea_fraction)")
        ->check(CLI::Range(0.0, 1.0));
    bakeCmd->add_flag("--force", bake.force, "Rebake even when a valid cache entry exists");
    bakeCmd->add_option("--cache", bake.cache,
                        "Cache root; the map goes to DIR/<key>/ (default: cache/continents, or "
                        "continents beside $PLANET_CACHE)");
    bakeCmd->add_option("--preview", bake.preview, "Write an equirectangular preview PNG of the continents (1024x512)")
        ->check(kPngFile);
    bakeCmd->add_option("--what", bake.what, "What to bake: continents, clouds (volume and weather map) or all")
        ->check(CLI::IsMember({"all", "continents", "clouds"}))
        ->capture_default_str();
    bakeCmd->add_option("--cloud-cache", bake.cloudCache,
                        "The clouds' cache root (default: cache/clouds, or clouds beside $PLANET_CACHE)");
    bakeCmd->add_option("--weather-preview", bake.weatherPreview,
                        "Write an equirectangular preview PNG of the weather map (1024x512): coverage, tinted by type")
        ->check(kPngFile);

    planet::CompareOptions compare;
    CLI::App* compareCmd = app.add_subcommand(
        "compare", "Compare linear HDR stills A.exr against a reference B.exr in luminance: mean and 99th / 99.9th "
                   "percentile relative error, mean luminance difference; fail past the given limits");
    compareCmd->add_option("A", compare.test, "The still judged (.exr)")->required();
    compareCmd->add_option("B", compare.reference, "The reference (.exr); errors are relative to its luminance")
        ->required();
    compareCmd->add_option("--diff", compare.diff,
                           "Write the difference image: .png = false colour of the relative error (log scale), "
                           ".exr = linear A - B in RGB, the relative error in A");
    compareCmd->add_option("--reference-scale", compare.referenceScale,
                           "B is rendered at this many times A's size: average each KxK block of B first (the "
                           "aliasing check, scripts/aliasing.sh: a supersampled reference)")
        ->check(CLI::Range(1, 16))
        ->capture_default_str();
    compareCmd->add_option("--max-mean", compare.maxMean, "Fail when the mean relative error exceeds this fraction");
    compareCmd->add_option("--max-p99", compare.maxP99, "Fail when its 99th percentile exceeds this fraction");
    compareCmd->add_option("--max-p999", compare.maxP999, "Fail when its 99.9th percentile exceeds this fraction");
    compareCmd->add_option("--max-mean-luminance", compare.maxMeanLuminance,
                           "Fail when the mean luminances differ by more than this fraction of B's");

    app.require_subcommand(0, 1);
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --version
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // The same prefix and exit status as every other error (README "Errors").
        std::cerr << "planet: error: " << e.what() << " (see planet --help, or planet COMMAND --help)\n";
        return 1;
    }

    try {
        if (renderCmd->parsed()) return planet::runRender(render);
        if (benchCmd->parsed()) return planet::runBench(bench);
        if (precomputeCmd->parsed()) return planet::runPrecompute(precompute);
        if (skyProbeCmd->parsed()) return planet::runSkyProbe(skyProbe);
        if (bakeCmd->parsed()) return planet::runBake(bake);
        if (compareCmd->parsed()) return planet::runCompare(compare);
        return planet::runExplore(explore);
    } catch (const std::exception& e) {  // InputError, FileError, ContextError, ShaderError, ...
        std::cerr << "planet: error: " << e.what() << "\n";
    }
    return 1;
}
