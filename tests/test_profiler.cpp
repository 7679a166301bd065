// Issue 15: the profiler's CPU column is what a pass itself spends on the CPU, not the time it
// waited for earlier GPU work; waits are reported apart; software renderers are named.
#include <functional>
#include <string>

#include "gl/context.h"
#include "gl_test_support.h"
#include "render/profiler.h"

using namespace planet;

namespace {

GLuint compile(GLenum stage, const char* source) {
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE);
    return shader;
}

// A full-screen triangle whose fragments each run a long loop: GPU work with next to no CPU work.
GLuint heavyProgram() {
    const GLuint vs = compile(GL_VERTEX_SHADER, R"(#version 450
        void main() { gl_Position = vec4(vec2(gl_VertexID & 1, gl_VertexID >> 1) * 4.0 - 1.0, 0.0, 1.0); })");
    const GLuint fs = compile(GL_FRAGMENT_SHADER, R"(#version 450
        layout(location = 0) out vec4 colour;
        void main() {
            float x = gl_FragCoord.x * 1e-3;
            for (int i = 0; i < 1500; ++i) x = fract(sin(x * 12.9898 + float(i)) * 43758.5453);
            colour = vec4(x);
        })");
    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    return program;
}

}  // namespace

class ProfilerTest : public test::GLTest {};

namespace {

// Four frames of two passes into a 160x160 target: "draw" (a heavy full-screen draw: GPU work
// with next to no CPU work), then a pass named `second` doing `secondWork`; the profiler's
// results are in when it returns.
void profileDrawThen(Profiler& profiler, const char* second, const std::function<void()>& secondWork) {
    gl::Texture target(GL_TEXTURE_2D);
    glTextureStorage2D(target.id(), 1, GL_RGBA8, 160, 160);
    gl::Framebuffer framebuffer;
    glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
    gl::VertexArray vertices;
    const GLuint program = heavyProgram();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glViewport(0, 0, 160, 160);
    glBindVertexArray(vertices.id());
    glUseProgram(program);
    for (int frame = 0; frame < 4; ++frame) {
        profiler.beginFrame();
        {
            auto scope = profiler.pass("draw");
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        {
            auto scope = profiler.pass(second);
            secondWork();
        }
        profiler.endFrame();
        profiler.waitForResults();
    }
    glFinish();
    glUseProgram(0);
    glDeleteProgram(program);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// The "draw" pass then a "clear" pass (next to no work), with the profiler's finish-each-pass
// as given.
struct DrawThenClear {
    Profiler profiler;
    explicit DrawThenClear(bool finishEachPass) {
        profiler.setFinishEachPass(finishEachPass);
        profileDrawThen(profiler, "clear", [] {
            const float zero[4] = {0, 0, 0, 0};
            glClearBufferfv(GL_COLOR, 0, zero);
        });
    }
    double wallMs(int pass) const {
        const PassTimings& p = profiler.passes().at(static_cast<std::size_t>(pass));
        return p.cpuMs.median() + p.waitMs.median();
    }
};

}  // namespace

TEST(ProfilerSoftware, NamesSoftwareRenderers) {
    EXPECT_TRUE(softwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(softwareRenderer("softpipe"));
    EXPECT_FALSE(softwareRenderer("NVIDIA H200/PCIe/SSE2"));
    EXPECT_NE(std::string(softwareTimingNote()).find("software renderer"), std::string::npos);
}

TEST_F(ProfilerTest, AWaitIsNotCountedAsCpuTime) {
    // Pass "draw" submits heavy GPU work; pass "wait" does nothing on the CPU but wait for it
    // (glFinish, as a pass that reads what an earlier one drew must). Its wall time is the
    // GPU's work; its CPU time must be next to nothing, the wait reported apart.
    Profiler profiler;
    profileDrawThen(profiler, "wait", [] { glFinish(); });

    const PassTimings& draw = profiler.passes().at(0);
    const PassTimings& wait = profiler.passes().at(1);
    ASSERT_EQ(wait.name, "wait");
    std::printf("%s\n", gl::rendererDescription().c_str());
    for (const PassTimings* p : {&draw, &wait})
        std::printf("%-5s GPU %.3f ms, CPU %.3f ms, wait %.3f ms (medians of %zu)\n", p->name.c_str(),
                    p->gpuMs.median(), p->cpuMs.median(), p->waitMs.median(), p->cpuMs.size());
    std::printf("frame GPU %.3f ms, CPU %.3f ms, wait %.3f ms\n", profiler.frameGpuMs().median(),
                profiler.frameCpuMs().median(), profiler.frameWaitMs().median());
    // The GPU's work as the frame's wall time: a software renderer's timestamps are coarse (they
    // read 4.7 ms for this draw on a busy machine, against 57 ms of waiting for it).
    const double gpuWork = profiler.frameCpuMs().median() + profiler.frameWaitMs().median();
    ASSERT_GT(gpuWork, 5.0) << "the heavy draw is not heavy enough to tell";
    // The wait pass waited for most of the GPU's work and spent next to nothing on the CPU.
    EXPECT_GT(wait.waitMs.median(), 0.5 * gpuWork);
    EXPECT_LT(wait.cpuMs.median(), 0.1 * wait.waitMs.median());
    EXPECT_LT(wait.cpuMs.median(), 0.1 * gpuWork);
    // The frame's CPU and wait split its wall time the same way.
    EXPECT_GT(profiler.frameWaitMs().median(), 0.5 * gpuWork);
    EXPECT_LT(profiler.frameCpuMs().median(), profiler.frameWaitMs().median());
}

TEST_F(ProfilerTest, FinishingEachPassKeepsEachPassItsOwnWork) {
    // With finish-each-pass (bench on software renderers), the heavy draw's own pass holds its
    // work in its wall time, and the light pass after it holds next to none. Without it, on a
    // renderer that defers the draw (llvmpipe bins it and shades at the next flush), the draw's
    // pass returns at once and its work lands in whichever pass waits next.
    const DrawThenClear finished(true);
    std::printf("finish each pass: draw %.3f ms, clear %.3f ms (wall, medians)\n", finished.wallMs(0),
                finished.wallMs(1));
    ASSERT_GT(finished.wallMs(0), 5.0) << "the heavy draw is not heavy enough to tell";
    EXPECT_LT(finished.wallMs(1), 0.1 * finished.wallMs(0));
    const double gpuDraw = finished.profiler.passes().at(0).gpuMs.median();
    const double gpuClear = finished.profiler.passes().at(1).gpuMs.median();
    std::printf("GPU timestamps: draw %.3f ms, clear %.3f ms\n", gpuDraw, gpuClear);
    EXPECT_LT(gpuClear, 0.5 * gpuDraw);

    const DrawThenClear overlapped(false);
    std::printf("overlapped: draw %.3f ms, clear %.3f ms (wall, medians)\n", overlapped.wallMs(0), overlapped.wallMs(1));
    if (softwareRenderer(gl::rendererDescription())) {
        EXPECT_LT(overlapped.wallMs(0), 0.5 * finished.wallMs(0)) << "llvmpipe no longer defers a draw: the option's "
                                                                    "reason to exist is gone";
    }
}
