#include "render/profiler.h"

#include <algorithm>
#include <ctime>

namespace planet {

namespace {
double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
// This thread's CPU time, ms (user + system; not the time it slept or waited).
double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}
}  // namespace

const char* softwareTimingNote() {
    return "software renderer (the GPU is the CPU): GPU timestamps are coarse, taken when the driver's threads reach "
           "them rather than when the work is done (a draw that kept llvmpipe busy 168 ms read 15 ms), so read CPU + "
           "wait; bench and the explorer finish each pass on such a renderer (--finish-each-pass, the checkbox), so that a "
           "pass's CPU + wait is its own work; vertex and tessellation stages run inside the draw call, as CPU time";
}

Profiler::Scope::Scope(Profiler& profiler, int pass) : profiler_(profiler), pass_(pass) {
    if (profiler_.finishEachPass_) glFinish();
    start_ = std::chrono::steady_clock::now();
    cpuStartMs_ = threadCpuMs();
    FrameSlot& slot = profiler_.slots_[static_cast<std::size_t>(profiler_.current_)];
    if (slot.used == slot.samples.size()) slot.samples.emplace_back();
    slot.samples[slot.used].pass = pass;
    glQueryCounter(slot.samples[slot.used].begin.id(), GL_TIMESTAMP);
}

Profiler::Scope::~Scope() {
    FrameSlot& slot = profiler_.slots_[static_cast<std::size_t>(profiler_.current_)];
    if (profiler_.finishEachPass_) glFinish();
    glQueryCounter(slot.samples[slot.used].end.id(), GL_TIMESTAMP);
    slot.used++;
    const double wall = msSince(start_);
    const double cpu = std::clamp(threadCpuMs() - cpuStartMs_, 0.0, wall);
    profiler_.addCpu(pass_, cpu, wall - cpu);
}

Profiler::Profiler() = default;

int Profiler::passIndex(std::string_view name) {
    for (std::size_t i = 0; i < passes_.size(); ++i)
        if (passes_[i].name == name) return static_cast<int>(i);
    passes_.emplace_back();
    passes_.back().name = std::string(name);
    return static_cast<int>(passes_.size()) - 1;
}

Profiler::Scope Profiler::pass(std::string_view name) { return Scope(*this, passIndex(name)); }

void Profiler::addCpu(int pass, double cpuMs, double waitMs) {
    PassTimings& p = passes_[static_cast<std::size_t>(pass)];
    p.cpuMs.push(cpuMs);
    p.waitMs.push(waitMs);
    if (recording_) {
        p.recordedCpuMs.push_back(cpuMs);
        p.recordedWaitMs.push_back(waitMs);
    }
}

void Profiler::beginFrame() {
    // Read every older frame whose results are in, oldest first.
    for (int i = 1; i <= kFramesInFlight; ++i) {
        FrameSlot& slot = slots_[static_cast<std::size_t>((current_ + i) % kFramesInFlight)];
        if (slot.pending) collect(slot, false);
    }
    current_ = static_cast<int>(frameIndex_ % kFramesInFlight);
    FrameSlot& slot = slots_[static_cast<std::size_t>(current_)];
    if (slot.pending) {  // the GPU is kFramesInFlight frames behind: drop, never wait
        slot.pending = false;
        droppedFrames_++;
    }
    slot.used = 0;
    inFrame_ = true;
    frameStart_ = std::chrono::steady_clock::now();
    frameCpuStartMs_ = threadCpuMs();
}

void Profiler::endFrame() {
    if (!inFrame_) return;
    inFrame_ = false;
    FrameSlot& slot = slots_[static_cast<std::size_t>(current_)];
    slot.pending = slot.used > 0;
    const double wall = msSince(frameStart_);
    const double cpu = std::clamp(threadCpuMs() - frameCpuStartMs_, 0.0, wall);
    frameCpuMs_.push(cpu);
    frameWaitMs_.push(wall - cpu);
    frameIndex_++;
}

void Profiler::collect(FrameSlot& slot, bool block) {
    if (!slot.pending || slot.used == 0) return;
    if (!block) {
        GLint available = GL_FALSE;
        glGetQueryObjectiv(slot.samples[slot.used - 1].end.id(), GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) return;  // later queries finish later: if the last is ready, all are
    }
    double frameMs = 0.0;
    for (std::size_t i = 0; i < slot.used; ++i) {
        GLuint64 t0 = 0, t1 = 0;
        glGetQueryObjectui64v(slot.samples[i].begin.id(), GL_QUERY_RESULT, &t0);
        glGetQueryObjectui64v(slot.samples[i].end.id(), GL_QUERY_RESULT, &t1);
        const double ms = t1 > t0 ? static_cast<double>(t1 - t0) * 1e-6 : 0.0;
        PassTimings& p = passes_[static_cast<std::size_t>(slot.samples[i].pass)];
        p.gpuMs.push(ms);
        if (recording_) p.recordedGpuMs.push_back(ms);
        frameMs += ms;
    }
    frameGpuMs_.push(frameMs);
    slot.pending = false;
}

void Profiler::waitForResults() {
    for (int i = 1; i <= kFramesInFlight; ++i)
        collect(slots_[static_cast<std::size_t>((current_ + i) % kFramesInFlight)], true);
}

void Profiler::setRecording(bool on) { recording_ = on; }

void Profiler::clearRecordings() {
    for (PassTimings& p : passes_) {
        p.recordedGpuMs.clear();
        p.recordedCpuMs.clear();
        p.recordedWaitMs.clear();
    }
}

}  // namespace planet
