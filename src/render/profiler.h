// Per-pass GPU and CPU timing.
//
// GPU time comes from a pair of GL_TIMESTAMP queries around each pass. Query
// results are read kFramesInFlight frames later, and only once the driver says
// they are available, so the profiler never waits for the GPU. If the GPU falls
// so far behind that a frame slot must be reused before its results arrived,
// that frame's GPU samples are dropped (counted in droppedFrames()) rather than
// stalling.
//
// CPU time is what the pass itself spends on the CPU: the submitting thread's CPU time
// (CLOCK_THREAD_CPUTIME_ID) over the pass's scope, not its wall time. The rest of the wall
// time, when the thread was off the CPU, is shown apart as the wait: mostly the driver
// blocking until earlier GPU work is done (a pass that reads what an earlier one drew, a
// copy, a readback), or the thread waiting for a core. Before issue 15 the CPU column was the
// wall time, so a pass that waited showed the wait as its CPU time (tonemap: 866 ms "CPU").
// A driver that spins while it waits counts the spin as CPU time.
//
// Software renderers (llvmpipe, softpipe, swrast; softwareRenderer()) run the whole GPU on
// the CPU: their timestamps are coarse (softwareTimingNote() says how), and the vertex and
// tessellation stages run inside the draw call on the submitting thread, in its CPU time.
//
// Each pass keeps a rolling window for the UI (min / median / max) and, when
// recording is on (planet bench), every sample.
#pragma once

#include <array>
#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "gl/context.h"
#include "gl/handle.h"
#include "render/stats.h"

namespace planet {

struct PassTimings {
    std::string name;
    RollingStats gpuMs;
    RollingStats cpuMs;   // the submitting thread's CPU time
    RollingStats waitMs;  // wall time less CPU time: off the CPU, mostly waiting for the GPU
    std::vector<double> recordedGpuMs;  // every sample while recording
    std::vector<double> recordedCpuMs;
    std::vector<double> recordedWaitMs;
};

// Whether the GL renderer string names a software renderer (gl/context.h).
using gl::softwareRenderer;
// One line for the profiler panel and bench: what a software renderer's timings mean.
const char* softwareTimingNote();

class Profiler {
public:
    static constexpr int kFramesInFlight = 4;

    class Scope {
    public:
        Scope(Profiler& profiler, int pass);
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        Profiler& profiler_;
        int pass_;
        std::chrono::steady_clock::time_point start_;
        double cpuStartMs_;
    };

    Profiler();

    void beginFrame();  // collects whatever results are ready, never blocks
    [[nodiscard]] Scope pass(std::string_view name);
    void endFrame();
    void waitForResults();  // blocks until every issued query is read (bench, tests)

    void setRecording(bool on);
    void clearRecordings();
    // Each pass waits for all work before it (glFinish) at its start and for its own at its end,
    // so its wall time (CPU + wait) holds its own work and nothing else; without it a pass's wait
    // holds the work of the passes before it. Off by default (it stops the GPU overlapping the
    // passes); bench and the explorer turn it on for software renderers, whose timestamps are
    // coarse besides (softwareTimingNote()).
    void setFinishEachPass(bool on) { finishEachPass_ = on; }
    bool finishEachPass() const { return finishEachPass_; }

    const std::vector<PassTimings>& passes() const { return passes_; }
    const RollingStats& frameGpuMs() const { return frameGpuMs_; }
    const RollingStats& frameCpuMs() const { return frameCpuMs_; }
    const RollingStats& frameWaitMs() const { return frameWaitMs_; }
    long long droppedFrames() const { return droppedFrames_; }

private:
    struct Sample {
        int pass = 0;
        gl::Query begin{GL_TIMESTAMP};
        gl::Query end{GL_TIMESTAMP};
    };
    struct FrameSlot {
        std::vector<Sample> samples;
        std::size_t used = 0;
        bool pending = false;
    };

    int passIndex(std::string_view name);
    void collect(FrameSlot& slot, bool block);
    void addCpu(int pass, double cpuMs, double waitMs);

    std::vector<PassTimings> passes_;
    std::array<FrameSlot, kFramesInFlight> slots_;
    int current_ = 0;
    long long frameIndex_ = 0;
    long long droppedFrames_ = 0;
    bool recording_ = false;
    bool finishEachPass_ = false;
    bool inFrame_ = false;
    std::chrono::steady_clock::time_point frameStart_;
    double frameCpuStartMs_ = 0.0;
    RollingStats frameGpuMs_;
    RollingStats frameCpuMs_;
    RollingStats frameWaitMs_;
};

}  // namespace planet
