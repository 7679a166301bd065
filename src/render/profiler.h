// Per-pass GPU and CPU timing.
//
// GPU time comes from a pair of GL_TIMESTAMP queries around each pass. Query
// results are read kFramesInFlight frames later, and only once the driver says
// they are available, so the profiler never waits for the GPU. If the GPU falls
// so far behind that a frame slot must be reused before its results arrived,
// that frame's GPU samples are dropped (counted in droppedFrames()) rather than
// stalling. CPU time is the wall time spent in the pass's scope on the CPU.
//
// Each pass keeps a rolling window for the UI (min / median / max) and, when
// recording is on (planet bench), every sample.
#pragma once

#include <array>
#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "gl/handle.h"
#include "render/stats.h"

namespace planet {

struct PassTimings {
    std::string name;
    RollingStats gpuMs;
    RollingStats cpuMs;
    std::vector<double> recordedGpuMs;  // every sample while recording
    std::vector<double> recordedCpuMs;
};

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
    };

    Profiler();

    void beginFrame();  // collects whatever results are ready, never blocks
    [[nodiscard]] Scope pass(std::string_view name);
    void endFrame();
    void waitForResults();  // blocks until every issued query is read (bench, tests)

    void setRecording(bool on);
    void clearRecordings();

    const std::vector<PassTimings>& passes() const { return passes_; }
    const RollingStats& frameGpuMs() const { return frameGpuMs_; }
    const RollingStats& frameCpuMs() const { return frameCpuMs_; }
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
    void addCpu(int pass, double ms);

    std::vector<PassTimings> passes_;
    std::array<FrameSlot, kFramesInFlight> slots_;
    int current_ = 0;
    long long frameIndex_ = 0;
    long long droppedFrames_ = 0;
    bool recording_ = false;
    bool inFrame_ = false;
    std::chrono::steady_clock::time_point frameStart_;
    double frameCpuAccum_ = 0.0;
    RollingStats frameGpuMs_;
    RollingStats frameCpuMs_;
};

}  // namespace planet
