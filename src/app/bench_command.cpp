// `planet bench`: scripted views, per-pass GPU and CPU timings.
//
// For each view: warm-up frames (not recorded), then N recorded frames. After
// every frame the profiler waits for that frame's timer queries, so no sample
// is dropped; GPU times are per pass from GL_TIMESTAMP pairs, CPU times the
// submitting thread's CPU time in each pass, and waits the rest of each pass's wall time
// (off the CPU: mostly waiting for earlier GPU work; render/profiler.h). On a software
// renderer a note says what its timings mean. Output: a table on stdout, a
// CSV (one row per view and pass, plus a "frame" row), and a stacked bar plot
// of the median GPU time per pass. Compare runs as ratios on the same machine.
// Suites: the views as they are; Michelic's terrain (Table 1) and ocean (Table 2) sweeps;
// the clouds (their views, then the march step and the sun samples swept, with the march's
// steps per pixel and the share the empty-space border skipped, counted in one extra frame).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "app/commands.h"
#include "app/session.h"
#include "app/soak.h"
#include "app/temporal_error.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "ocean/wave_spectrum.h"
#include "render/plot.h"
#include "render/renderer.h"
#include "render/stats.h"
#include "scene/toml_error.h"
#include "util/file_util.h"
#include "util/log.h"

namespace planet {

namespace fs = std::filesystem;

namespace {

struct BenchRow {
    std::string view, pass;
    std::size_t frames = 0;
    double gpuMedian = 0, gpuP95 = 0, cpuMedian = 0, cpuP95 = 0, waitMedian = 0, waitP95 = 0;
    // The clouds suite's frame rows: the sky pass's march steps (small and large) per pixel
    // of the image, and the share of them that were large steps through empty space.
    double cloudStepsPerPixel = -1, cloudSkippedShare = -1;
};

BenchRow benchRow(const std::string& view, const std::string& pass, const std::vector<double>& gpu,
                  const std::vector<double>& cpu, const std::vector<double>& wait) {
    BenchRow r;
    r.view = view;
    r.pass = pass;
    r.frames = gpu.size();
    r.gpuMedian = percentile(gpu, 50);
    r.gpuP95 = percentile(gpu, 95);
    r.cpuMedian = percentile(cpu, 50);
    r.cpuP95 = percentile(cpu, 95);
    r.waitMedian = percentile(wait, 50);
    r.waitP95 = percentile(wait, 95);
    return r;
}

// The views to measure: the session's (assets/views, loaded and warned about once, by
// loadSession) unless --views names files or folders. A broken file in a folder is
// skipped with a warning; one named on its own is an error.
std::vector<View> benchViews(const std::vector<std::string>& inputs, const DataPaths& paths, const Session& session) {
    if (inputs.empty()) return session.views;
    std::vector<View> views;
    for (const std::string& source : inputs) {
        std::error_code ec;
        if (fs::equivalent(source, paths.views(), ec)) {  // the session's folder: read and warned about already
            views.insert(views.end(), session.views.begin(), session.views.end());
        } else if (fs::is_directory(source)) {
            std::vector<std::string> warnings;
            std::vector<BrokenView> broken;
            std::vector<View> loaded = loadViews(source, &warnings, &broken);
            for (const std::string& w : warnings) logWarning(w);
            if (loaded.empty()) throw broken.front().error;  // every file broken: the first one's error
            for (View& v : loaded) views.push_back(std::move(v));
        } else {
            std::vector<std::string> warnings;
            views.push_back(loadView(source, &warnings));
            for (const std::string& w : warnings) logWarning(w);
        }
    }
    return views;
}

// `clockStep_s`: the scene's clock moves on by this much before each frame (the explorer's
// running clock: the wind drifts the clouds, the waves move), and is put back after; 0: a
// still frame, the same scene every time.
std::vector<BenchRow> measureView(Renderer& renderer, Session& session, glm::ivec2 size, const BenchOptions& o,
                                  double clockStep_s = 0.0) {
    Profiler& profiler = renderer.profiler();
    const double clockStart = session.scene.time_s;
    auto renderOne = [&] {
        session.scene.time_s += clockStep_s;
        renderer.render(session.scene, session.camera, size);
        profiler.waitForResults();
    };
    profiler.setRecording(false);
    for (int i = 0; i < o.warmup; ++i) renderOne();
    profiler.waitForResults();  // a frame drawn before this call (none warm-up) is not recorded
    profiler.clearRecordings();
    profiler.setRecording(true);
    for (int i = 0; i < o.frames; ++i) renderOne();
    profiler.setRecording(false);
    session.scene.time_s = clockStart;

    std::vector<BenchRow> rows;
    std::vector<double> totalGpu(static_cast<std::size_t>(o.frames), 0.0), totalCpu = totalGpu, totalWait = totalGpu;
    for (const PassTimings& p : profiler.passes()) {
        if (p.recordedGpuMs.empty()) continue;  // not drawn in this view (the sky's full- or reduced-rate passes)
        rows.push_back(benchRow(session.view.name, p.name, p.recordedGpuMs, p.recordedCpuMs, p.recordedWaitMs));
        for (std::size_t i = 0; i < totalGpu.size() && i < p.recordedGpuMs.size(); ++i) totalGpu[i] += p.recordedGpuMs[i];
        for (std::size_t i = 0; i < totalCpu.size() && i < p.recordedCpuMs.size(); ++i) totalCpu[i] += p.recordedCpuMs[i];
        for (std::size_t i = 0; i < totalWait.size() && i < p.recordedWaitMs.size(); ++i)
            totalWait[i] += p.recordedWaitMs[i];
    }
    rows.push_back(benchRow(session.view.name, "frame", totalGpu, totalCpu, totalWait));
    return rows;
}

// One more frame with the sky pass counting its cloud march steps, into the view's frame row.
void countCloudSteps(Renderer& renderer, const Session& session, glm::ivec2 size, std::vector<BenchRow>& rows) {
    renderer.setCloudStatistics(true);
    renderer.render(session.scene, session.camera, size);
    renderer.setCloudStatistics(false);
    const clouds::MarchStatistics m = renderer.clouds().marchStatistics();
    rows.back().cloudStepsPerPixel = m.stepsPerPixel(static_cast<std::uint64_t>(size.x) * static_cast<std::uint64_t>(size.y));
    rows.back().cloudSkippedShare = m.skippedShare();
}

// The sky's time in a view's rows: the full-rate pass ("sky"), or the reduced-rate march, its
// reconstruction and the pixels marched again ("sky march" + "sky temporal" + "sky refine");
// medians, ms. GPU time, or with `wall` (each pass finished: --finish-each-pass) its wall
// time, CPU + wait, which then holds the pass's own work and nothing else: a software
// renderer's timestamps miss most of it (tests/test_profiler.cpp: a draw that kept llvmpipe
// busy 168 ms read 15 ms).
double skyMs(const std::vector<BenchRow>& rows, const std::string& view, bool wall) {
    double ms = 0.0;
    for (const BenchRow& r : rows)
        if (r.view == view && (r.pass == "sky" || r.pass == "sky march" || r.pass == "sky temporal" ||
                                r.pass == "sky refine"))
            ms += wall ? r.cpuMedian + r.waitMedian : r.gpuMedian;
    return ms;
}

// What the sky's times are: the label for skyMs's figures.
const char* skyTimeLabel(bool wall) {
    return wall ? "wall time, CPU + wait, each pass finished" : "GPU timestamps";
}

// The clouds suite: each cloud view marched at the reduced rate (render.temporal, the
// frames after the first with history), still ("VIEW": the same scene every frame) and with the
// clock running at 30 frames a second ("VIEW/clock": as the explorer runs it, the clouds drifting
// with the wind, so the reconstruction's moving-frame work and the refine pass's pixels count),
// and at full rate ("VIEW/full-rate"), the ratios of their sky passes printed; then the march's
// small step and the samples towards the sun swept on the first view, at full rate (the march's
// own cost). Returns the lines of that comparison, for after the table.
std::vector<std::string> benchClouds(Renderer& frame, Session& session, const std::vector<View>& views, glm::ivec2 size,
                                     const BenchOptions& o, std::vector<BenchRow>& rows) {
    if (!session.scene.clouds.enabled) throw InputError("--suite clouds: the preset has no clouds ([clouds] enabled)");
    const Scene preset = session.scene;
    constexpr double kClockStep_s = 1.0 / 30.0;
    struct Run {
        const char* suffix;
        bool temporal;
        double clockStep_s;
    };
    std::vector<std::string> ratios;
    for (const View& view : views) {
        for (const Run& run : {Run{"", true, 0.0}, Run{"/clock", true, kClockStep_s}, Run{"/full-rate", false, 0.0}}) {
            applyView(view, session);
            session.scene.render.temporal = run.temporal;
            session.view.name += run.suffix;
            logInfo("bench clouds view '" + session.view.name + "'");
            // A frame that seeds the history, not recorded: the view jumped, and without it the
            // first reduced-rate frame would be a full-rate one.
            if (run.temporal) frame.render(session.scene, session.camera, size);
            for (BenchRow& r : measureView(frame, session, size, o, run.clockStep_s)) rows.push_back(std::move(r));
            countCloudSteps(frame, session, size, rows);
        }
        const bool wall = frame.profiler().finishEachPass();
        const double still = skyMs(rows, view.name, wall), clock = skyMs(rows, view.name + "/clock", wall),
                     full = skyMs(rows, view.name + "/full-rate", wall);
        char line[200];
        std::snprintf(line, sizeof line,
                      "%-12s reduced rate %9.3f ms still, %9.3f ms clock running; full rate %9.3f ms: %.3f, %.3f of the "
                      "full-rate march",
                      view.name.c_str(), still, clock, full, full > 0.0 ? still / full : 0.0, full > 0.0 ? clock / full : 0.0);
        ratios.push_back(line);
    }
    session.scene = preset;
    session.scene.render.temporal = false;
    applyView(views.front(), session);
    for (double step : {0.2, 0.1, 0.05}) {
        for (int sunSamples : {0, 3, 6, 12}) {
            session.scene.clouds = preset.clouds;
            session.scene.clouds.step_km = step;
            session.scene.clouds.sun_samples = sunSamples;
            char name[64];
            std::snprintf(name, sizeof name, "%s/step%gkm/sun%d", views.front().name.c_str(), step, sunSamples);
            session.view.name = name;
            logInfo(std::string("bench clouds ") + name);
            for (BenchRow& r : measureView(frame, session, size, o)) rows.push_back(std::move(r));
            countCloudSteps(frame, session, size, rows);
        }
    }
    session.scene = preset;
    ratios.insert(ratios.begin(), std::string("sky passes (medians of the ") + skyTimeLabel(frame.profiler().finishEachPass()) +
                                      "): the reduced-rate march + its reconstruction + the pixels marched again "
                                      "against the full-rate march");
    return ratios;
}

// The clouds suite's views unless --views names others: under the cumulus, inside the
// layer, above the deck, orbit and space.
std::vector<View> cloudViews(const std::vector<View>& views, const BenchOptions& o) {
    if (!o.views.empty()) return views;
    std::vector<View> chosen;
    for (const char* name : {"cumulus", "clouds", "deck", "orbit", "space"}) {
        const auto it = std::find_if(views.begin(), views.end(), [&](const View& v) { return v.name == name; });
        if (it != views.end()) chosen.push_back(*it);
    }
    return chosen.empty() ? views : chosen;
}

// A CSV field, quoted when it holds a comma, quote or newline (RFC 4180).
std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string quoted = "\"";
    for (char ch : s) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return quoted + "\"";
}

std::string csvText(const std::vector<BenchRow>& rows, const std::string& renderer, glm::ivec2 size) {
    std::ostringstream csv;
    csv << "renderer,width,height,view,pass,frames,gpu_median_ms,gpu_p95_ms,cpu_median_ms,cpu_p95_ms,"
           "cloud_steps_per_pixel,cloud_skipped_share,wait_median_ms,wait_p95_ms\n";
    for (const BenchRow& r : rows) {
        char line[512];
        std::snprintf(line, sizeof line, ",%d,%d,", size.x, size.y);
        csv << csvField(renderer) << line << csvField(r.view) << "," << csvField(r.pass);
        std::snprintf(line, sizeof line, ",%zu,%.4f,%.4f,%.4f,%.4f,", r.frames, r.gpuMedian, r.gpuP95, r.cpuMedian,
                      r.cpuP95);
        csv << line;
        if (r.cloudStepsPerPixel >= 0.0) {
            std::snprintf(line, sizeof line, "%.3f,%.4f", r.cloudStepsPerPixel, r.cloudSkippedShare);
            csv << line;
        } else {
            csv << ",";
        }
        std::snprintf(line, sizeof line, ",%.4f,%.4f", r.waitMedian, r.waitP95);
        csv << line << "\n";
    }
    return csv.str();
}

// What the sky passes cost along a whole path, summed over its frames (skyMs's measure): the
// temporal renderer's march, reconstruction and full-rate refinement against the full-rate
// renderer's sky.
void printPathSkyCost(Renderer& temporal, Renderer& fullRate) {
    const bool wall = temporal.profiler().finishEachPass();
    auto total = [wall](Renderer& r, const std::string& pass) {
        r.profiler().waitForResults();
        r.profiler().setRecording(false);
        double ms = 0.0;
        for (const PassTimings& p : r.profiler().passes())
            if (p.name == pass) {
                if (!wall)
                    for (double x : p.recordedGpuMs) ms += x;
                else
                    for (std::size_t i = 0; i < p.recordedCpuMs.size(); ++i) ms += p.recordedCpuMs[i] + p.recordedWaitMs[i];
            }
        return ms;
    };
    const double march = total(temporal, "sky march"), reconstruction = total(temporal, "sky temporal"),
                 refine = total(temporal, "sky refine"), reset = total(temporal, "sky"), full = total(fullRate, "sky");
    std::printf("sky passes along the path, ms summed over the frames (%s): temporal %.0f (sky march %.0f, sky "
                "temporal %.0f, sky refine %.0f, full-rate frames without history %.0f) against full rate %.0f: %.3f\n",
                skyTimeLabel(wall), march + reconstruction + refine + reset, march,
                reconstruction, refine, reset, full, (march + reconstruction + refine + reset) / std::max(full, 1.0e-9));
}

// The temporal suite: every frame of a camera path rendered with the temporal march (its
// history kept from frame to frame, as `planet render --path` and the explorer do) and at full
// rate, compared in linear luminance; one CSV row per frame, a summary, and the worst frame
// (highest 99th percentile) written as the two images and their difference beside the CSV.
void benchTemporal(Renderer& temporal, Renderer& fullRate, Session& session, const DataPaths& paths,
                   glm::ivec2 size, const BenchOptions& o) {
    if (!session.scene.render.temporal) throw InputError("--suite temporal: the temporal march is off (--no-temporal or render.temporal)");
    const CameraPath path = loadSessionPath(paths, o.path, session);
    const int frameCount = pathFrameCount(path.file(), o.pathFrames);
    std::printf("temporal march against the full rate along path '%s', %d frames\n", path.file().name.c_str(), frameCount);
    std::printf("%8s %9s %8s %10s %10s %10s %10s\n", "frame", "time s", "reduced", "mean %", "p99 %", "max %",
                "refined %");
    TemporalWorstFrame worst;
    for (Renderer* r : {&temporal, &fullRate}) {
        r->profiler().clearRecordings();
        r->profiler().setRecording(true);
    }
    const std::vector<TemporalFrameError> errors = measureTemporalError(
        temporal, fullRate, session, path, frameCount, 0, frameCount, size, &worst, [&](const TemporalFrameError& e) {
            if (e.frame % 10 == 0 || e.frame == frameCount - 1)
                std::printf("%8d %9.2f %8s %10.3f %10.2f %10.1f %10.1f\n", e.frame, e.time_s,
                            e.reducedRate ? "yes" : "no", 100 * e.meanRelative, 100 * e.p99Relative,
                            100 * e.maxRelative, 100 * e.refinedShare);
        });
    double worstMean = 0.0, sumMean = 0.0, sumRefined = 0.0;
    int overMean = 0, overP99 = 0;
    std::vector<double> p99s;
    for (const TemporalFrameError& e : errors) {
        worstMean = std::max(worstMean, e.meanRelative);
        sumMean += e.meanRelative;
        sumRefined += e.refinedShare;
        overMean += e.meanRelative >= 0.03 ? 1 : 0;
        overP99 += e.p99Relative >= 0.15 ? 1 : 0;
        p99s.push_back(e.p99Relative);
    }
    std::printf("frames: %zu; mean error: average %.3f %%, worst %.3f %% (%d frames at 3 %% or more); 99th percentile: "
                                "median %.2f %%, worst %.2f %% at frame %d, t = %.2f s (%d frames at 15 %% or more); marched again "
                "at full rate: %.1f %% of the pixels on average\n",
                errors.size(), 100 * sumMean / static_cast<double>(errors.size()), 100 * worstMean, overMean,
                100 * percentile(p99s, 50), 100 * worst.error.p99Relative, worst.error.frame, worst.error.time_s, overP99,
                100 * sumRefined / static_cast<double>(errors.size()));
    printPathSkyCost(temporal, fullRate);
    if (o.csv.empty()) return;
    std::ostringstream csv;
    csv << "renderer,width,height,path,frame,time_s,reduced_rate,mean_relative_error,p99_relative_error,max_relative_error,"
           "refined_share\n";
    for (const TemporalFrameError& e : errors) {
        char line[256];
        std::snprintf(line, sizeof line, ",%d,%d,%s,%d,%.4f,%d,%.6f,%.6f,%.6f,%.4f\n", size.x, size.y,
                      path.file().name.c_str(), e.frame, e.time_s, e.reducedRate ? 1 : 0, e.meanRelative,
                      e.p99Relative, e.maxRelative, e.refinedShare);
        csv << csvField(gl::rendererDescription()) << line;
    }
    writeFileAtomic(o.csv, csv.str());
    std::printf("wrote %s\n", fs::absolute(o.csv).lexically_normal().c_str());
    const fs::path stem = fs::path(o.csv).replace_extension();
    const std::string frame = "_worst_frame" + std::to_string(worst.error.frame);
    const fs::path a = stem.string() + frame + "_temporal.exr", b = stem.string() + frame + "_full_rate.exr",
                   d = stem.string() + frame + "_difference.png";
    writeExr(worst.temporal, a, session.scene.render.exposure);
    writeExr(worst.fullRate, b, session.scene.render.exposure);
    writeDifferenceImage(compareImages(worst.temporal, worst.fullRate), worst.temporal, worst.fullRate, d);
    for (const fs::path& f : {a, b, d}) std::printf("wrote %s\n", fs::absolute(f).lexically_normal().c_str());
}

void printTable(const std::vector<BenchRow>& rows) {
    const bool clouds = std::any_of(rows.begin(), rows.end(), [](const BenchRow& r) { return r.cloudStepsPerPixel >= 0.0; });
    std::printf("%-12s %-12s %8s %12s %12s %12s %12s %12s%s\n", "view", "pass", "frames", "gpu med ms", "gpu p95 ms",
                "cpu med ms", "cpu p95 ms", "wait med ms", clouds ? "  steps/px  skipped" : "");
    for (const BenchRow& r : rows) {
        std::printf("%-12s %-12s %8zu %12.3f %12.3f %12.3f %12.3f %12.3f", r.view.c_str(), r.pass.c_str(), r.frames,
                    r.gpuMedian, r.gpuP95, r.cpuMedian, r.cpuP95, r.waitMedian);
        if (r.cloudStepsPerPixel >= 0.0) std::printf(" %9.1f %7.1f%%", r.cloudStepsPerPixel, 100.0 * r.cloudSkippedShare);
        std::printf("\n");
    }
}

BarPlot gpuPlot(const std::vector<BenchRow>& rows, const std::string& renderer, glm::ivec2 size) {
    BarPlot plot;
    plot.title = "planet bench: median GPU time per pass, " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                 ", " + renderer;
    plot.yLabel = "ms";
    for (const BenchRow& r : rows) {
        if (r.pass == "frame") continue;
        if (plot.categories.empty() || plot.categories.back() != r.view) plot.categories.push_back(r.view);
        auto it = std::find_if(plot.series.begin(), plot.series.end(), [&](const BarSeries& s) { return s.name == r.pass; });
        if (it == plot.series.end()) it = plot.series.insert(plot.series.end(), BarSeries{r.pass, {}});
        it->values.resize(plot.categories.size(), 0.0);
        it->values.back() = r.gpuMedian;
    }
    for (BarSeries& s : plot.series) s.values.resize(plot.categories.size(), 0.0);
    return plot;
}

}  // namespace

int runBench(const BenchOptions& o) {
    if (o.frames < 1 || o.frames > 100000) throw InputError("--frames must be in [1, 100000]");
    if (o.warmup < 0 || o.warmup > 100000) throw InputError("--warmup must be in [0, 100000]");
    const glm::ivec2 size = parseSize(o.common.size);
    std::vector<std::string> outputs;
    for (const std::string& f : {o.csv, o.plot})
        if (!f.empty()) outputs.push_back(f);
    checkOutputsWritable(outputs);
    const DataPaths paths = findDataPaths(o.common.root);
    Session session = loadSession(paths, o.common.preset, o.common.view, o.common.noTemporal);
    const std::vector<View> views = benchViews(o.views, paths, session);

    gl::DebugMessages messages;  // outlives the context that reports into it
    gl::HeadlessContext context(o.common.glDebug);
    gl::installDebugOutput(&messages, o.common.glDebug);  // always to the log; --gl-debug: debug context, synchronous
    const std::string renderer = gl::rendererDescription();
    std::printf("planet bench on %s via %s, %dx%d, %d frames after %d warm-up\n", renderer.c_str(),
                context.platform().c_str(), size.x, size.y, o.frames, o.warmup);
    Renderer frame(paths.shaders(), atmosphere::tableSizesFor(o.common.tables, renderer), session.continents);
    const bool finishEachPass = o.finishEachPass == "on" || (o.finishEachPass == "auto" && softwareRenderer(renderer));
    frame.profiler().setFinishEachPass(finishEachPass);
    if (finishEachPass) std::printf("each pass waits for the work before it and for its own (--finish-each-pass)\n");
    frame.setTemporalAntialiasing(o.antialias);
    if (o.antialias) std::printf("anti-aliased as in the explorer: a sub-pixel jitter each frame (--antialias)\n");

    if (o.suite == "soak") return benchSoak(frame, session, size, o.frames, o);
    if (o.suite == "temporal") {
        Renderer fullRate(paths.shaders(), atmosphere::tableSizesFor(o.common.tables, renderer), session.continents);
        fullRate.profiler().setFinishEachPass(finishEachPass);
        fullRate.setTemporalAntialiasing(o.antialias);  // the same jitter, frame for frame
        benchTemporal(frame, fullRate, session, paths, size, o);
        return 0;
    }
    std::vector<BenchRow> rows;
    std::vector<std::string> notes;  // printed after the table
    if (o.suite == "terrain") {
        // Michelic Table 1: the same view, grid size x noise layers, from the continents alone
        // (the baked map, no mountain noise) to 10 layers of mountain noise.
        applyView(views.front(), session);
        for (int grid : {50, 100, 200}) {
            for (int octaves : {0, 1, 5, 10}) {
                session.scene.terrain.grid_size = grid;
                session.scene.terrain.noise_octaves = octaves;
                session.view.name =
                    "g" + std::to_string(grid) + (octaves == 0 ? "/continents" : "/o" + std::to_string(octaves));
                logInfo("bench terrain " + session.view.name + " on view '" + views.front().name + "'");
                for (BenchRow& r : measureView(frame, session, size, o)) rows.push_back(std::move(r));
            }
        }
    } else if (o.suite == "ocean") {
        // Michelic Table 2: the same view over open sea, 20, 50, 100 and 1000 waves generated
        // from the preset's [ocean] parameters. The view: "sea" unless --views names others.
        const auto sea = std::find_if(views.begin(), views.end(), [](const View& v) { return v.name == "sea"; });
        const View& view = o.views.empty() && sea != views.end() ? *sea : views.front();
        applyView(view, session);
        for (int count : {20, 50, 100, 1000}) {
            session.scene.ocean.wave_count = count;
            session.scene.waves = ocean::generateWaves(session.scene.ocean);
            session.view.name = std::to_string(count) + " waves";
            logInfo("bench ocean " + session.view.name + " on view '" + view.name + "'");
            for (BenchRow& r : measureView(frame, session, size, o)) rows.push_back(std::move(r));
        }
    } else if (o.suite == "clouds") {
        notes = benchClouds(frame, session, cloudViews(views, o), size, o, rows);
    } else {
        for (const View& view : views) {
            logInfo("bench view '" + view.name + "' (" + std::to_string(o.warmup + o.frames) + " frames)");
            applyView(view, session);
            for (BenchRow& r : measureView(frame, session, size, o)) rows.push_back(std::move(r));
        }
    }
    printTable(rows);
    std::printf("cpu: the pass's own CPU time (the submitting thread's); wait: the rest of its wall time, off the CPU "
                "(mostly waiting for earlier GPU work)\n");
    if (softwareRenderer(renderer)) std::printf("%s\n", softwareTimingNote());
    for (const std::string& line : notes) std::printf("%s\n", line.c_str());
    if (!o.csv.empty()) {
        writeFileAtomic(o.csv, csvText(rows, renderer, size));
        std::printf("wrote %s\n", fs::absolute(o.csv).lexically_normal().c_str());
    }
    if (!o.plot.empty()) {
        writePng(renderStackedBarPlot(gpuPlot(rows, renderer, size)), o.plot);
        std::printf("wrote %s\n", fs::absolute(o.plot).lexically_normal().c_str());
    }
    return 0;
}

}  // namespace planet
