// The subcommands of `planet` and their options (parsed in main.cpp with CLI11).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace planet {

struct CommonOptions {
    std::string root;              // data folder with shaders/ and assets/
    std::string preset = "earth";  // name under assets/presets or a path
    std::string view = "orbit";    // bookmark name under assets/views
    std::string size = "1280x720"; // WIDTHxHEIGHT
    bool glDebug = false;          // KHR_debug output (synchronous)
    std::string tables = "auto";   // atmosphere table sizes: full, reduced, auto, or explicit (tables.h)
    double time = 0.0;             // the ocean's clock at the first frame, s
    bool noTemporal = false;       // render.temporal off: every pixel marched every frame
};

struct ExploreOptions {
    CommonOptions common;
    int frames = 0;                    // quit after this many frames (0: run until closed)
    std::string screenshot;            // PNG of the window (UI included) after the last frame
    bool noPanels = false;             // start with the panels hidden (F1 shows them)
    std::string headlessOut = "out/planet.png";  // still written when there is no display
    std::string path;                  // camera path to play (name under assets/paths or a file); P pauses
    std::string renderScale = "auto";  // share of the window's width and height rendered (render_scale.h)
};

struct RenderOptions {
    CommonOptions common;
    std::vector<std::string> outputs;  // .png (display-ready) and/or .exr (linear HDR)
    std::optional<double> exposure;
    std::string path;                  // camera path (name under assets/paths or a file): a sequence instead of a still
    std::optional<int> frames;         // with path: this many frames evenly in time (default: duration x fps + 1)
    std::optional<int> samples;        // jittered frames averaged per image (default: kStillSamples, 1 with path)
};

// Jittered frames a still averages by default (render --samples; README "Anti-aliasing").
constexpr int kStillSamples = 4;

struct BenchOptions {
    CommonOptions common;
    std::vector<std::string> views;  // view files or folders of them
    std::string suite = "views";     // "views": each view as it is; "terrain" / "ocean": Michelic's Table 1 / 2 sweeps;
                                     // "clouds": the cloud views, step and sun samples swept, march statistics;
                                     // "temporal": the temporal march against the full rate along a path
    int frames = 60;
    int warmup = 10;
    std::string path = "takeoff";         // --suite temporal: the camera path
    std::optional<int> pathFrames;        // --suite temporal: frames over it (default: its natural count)
    std::string finishEachPass = "auto";  // on / off / auto (on for software renderers): Profiler::setFinishEachPass
    bool antialias = false;               // the explorer's anti-aliasing: a sub-pixel jitter each frame, blended over time
    std::string csv = "out/bench.csv";
    std::string plot = "out/bench.png";
};

struct PrecomputeOptions {
    CommonOptions common;
    bool reference = false;  // CPU double-precision reference instead of the GPU
    std::string cache;       // cache root (empty: $PLANET_CACHE, else cache/atmosphere)
    bool force = false;      // rebuild even when a valid cache entry exists
};

struct SkyProbeOptions {
    CommonOptions common;
    std::string in;          // CSV: altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg
    std::string out;         // the same columns + radiance_rgb (1/sr) + transmittance_rgb
    bool reference = false;  // Model (double) on CPU reference tables instead of the GPU
    std::string cache;       // as PrecomputeOptions::cache
    std::string against;     // a reference output CSV of the same rays: print the error (sky_accuracy.h)
};

struct BakeOptions {
    std::string root;                   // data folder with assets/ (as CommonOptions::root)
    std::string preset = "earth";       // the [terrain] parameters to bake for (name or .toml)
    std::optional<int> size;            // cube face size, texels, [16, 2048] (default: the preset's)
    std::optional<int> seed;            // noise domain offset (default: the preset's)
    std::optional<double> seaFraction;  // fraction of the surface under water, [0, 1] (default: the preset's)
    bool force = false;        // rebake even when a valid cache entry exists
    std::string cache;         // cache root (empty: noise::defaultContinentsCacheRoot())
    std::string preview;       // equirectangular PNG of the map (empty: none)
    std::string what = "all";  // "continents", "clouds" (volume and weather map) or "all"
    std::string cloudCache;    // the clouds' cache root (empty: noise::defaultCloudCacheRoot())
    std::string weatherPreview;  // equirectangular PNG of the weather map (empty: none)
};

struct CompareOptions {
    std::string test;       // A.exr: the image judged
    std::string reference;  // B.exr: the reference (errors are relative to its luminance)
    std::string diff;       // difference image, .png (false colour) or .exr (linear); empty: none
    int referenceScale = 1; // B is this many times A's size: box-averaged scale x scale down first
    // Limits, as fractions (0.005 = 0.5 %); unset: not checked.
    std::optional<double> maxMean;           // mean relative error
    std::optional<double> maxP99;            // 99th percentile of the relative error
    std::optional<double> maxP999;           // 99.9th percentile
    std::optional<double> maxMeanLuminance;  // |relative difference of the mean luminance|
};

int runExplore(const ExploreOptions& options);
int runRender(const RenderOptions& options);
int runBench(const BenchOptions& options);
int runPrecompute(const PrecomputeOptions& options);
int runSkyProbe(const SkyProbeOptions& options);
int runBake(const BakeOptions& options);
int runCompare(const CompareOptions& options);  // throws when a limit is exceeded or a pixel is NaN / Inf

// Renders one still headlessly (shared by `render` and explore's no-display fallback).
// `samples` jittered frames, each at full rate, averaged in linear HDR (1: one unjittered frame).
void renderStill(const CommonOptions& common, const std::vector<std::string>& outputs,
                 std::optional<double> exposure, int samples = 1);
// Renders a camera path's frames in sequence with one Renderer, to numbered files
// (each output a printf pattern such as seq/f_%04d.png); progress on stderr.
// With samples > 1 each frame is that many jittered full-rate frames averaged (no history).
void renderPath(const CommonOptions& common, const std::vector<std::string>& outputs,
                std::optional<double> exposure, const std::string& path, std::optional<int> frames,
                int samples = 1);

struct Scene;
namespace atmosphere {
struct AtmosphereTables;
struct TableSizes;
}  // namespace atmosphere

// The scene's atmosphere tables at `sizes` (shared by `precompute` and
// `sky-probe`): the cache entry under `cacheRoot` (empty: the default root) when
// it is valid and not `force`, else computed -- on the GPU of the current GL
// context, or by the CPU reference when `reference` -- and saved there. Reports
// each step's time, the total and the memory on `out`. Throws on failure,
// including tables with NaN / Inf (which are never cached).
// Table sizes for a --tables choice. Without a current GL context (the CPU
// reference), "auto" asks a short-lived headless one which renderer it gets, so
// that GPU and reference runs of the same command line use the same sizes.
atmosphere::TableSizes commandTableSizes(const std::string& choice, bool haveContext);

atmosphere::AtmosphereTables loadOrPrecomputeTables(const Scene& scene, const atmosphere::TableSizes& sizes,
                                                    const std::string& cacheRoot,
                                                    const std::filesystem::path& shaderRoot, bool reference,
                                                    bool force, std::ostream& out);

}  // namespace planet
