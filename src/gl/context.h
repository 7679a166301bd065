// GL contexts: a headless one through EGL (no display, no window), and the
// checks every context must pass (OpenGL 4.5 core).
//
// The headless context tries, in order: the EGL device platform (NVIDIA and
// other GPUs without a display server), Mesa's surfaceless platform (llvmpipe
// on CI), then the default display. It renders only into framebuffer objects.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace planet::gl {

struct ContextError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class HeadlessContext {
public:
    explicit HeadlessContext(bool debug = true);  // throws ContextError with the reason
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    const std::string& platform() const { return platform_; }

private:
    void release();

    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string platform_;
};

// Throws ContextError naming the version and renderer found when the current
// context is not OpenGL >= 4.5.
void requireGL45();

// "renderer (vendor), OpenGL version" of the current context.
std::string rendererDescription();

// Whether a renderer description names a software renderer (llvmpipe, softpipe, swrast): the
// GPU is the CPU there (coarse timestamps; smaller default tables and render scale).
bool softwareRenderer(std::string_view glRenderer);

}  // namespace planet::gl
