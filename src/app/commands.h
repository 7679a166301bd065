// The subcommands of `planet` and their options (parsed in main.cpp with CLI11).
#pragma once

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
    std::string tables = "auto";   // atmosphere table sizes: full, reduced, auto (reduced on software GL)
};

struct ExploreOptions {
    CommonOptions common;
    int frames = 0;                    // quit after this many frames (0: run until closed)
    std::string screenshot;            // PNG of the window (UI included) after the last frame
    bool noPanels = false;             // start with the panels hidden (F1 shows them)
    std::string headlessOut = "out/planet.png";  // still written when there is no display
};

struct RenderOptions {
    CommonOptions common;
    std::vector<std::string> outputs;  // .png (display-ready) and/or .exr (linear HDR)
    std::optional<double> exposure;
};

struct BenchOptions {
    CommonOptions common;
    std::vector<std::string> views;  // view files or folders of them
    int frames = 60;
    int warmup = 10;
    std::string csv = "out/bench.csv";
    std::string plot = "out/bench.png";
};

int runExplore(const ExploreOptions& options);
int runRender(const RenderOptions& options);
int runBench(const BenchOptions& options);

// Renders one still headlessly (shared by `render` and explore's no-display fallback).
void renderStill(const CommonOptions& common, const std::vector<std::string>& outputs,
                 std::optional<double> exposure);

}  // namespace planet
