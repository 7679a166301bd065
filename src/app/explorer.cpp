// The explorer window (see explorer.h for the controls).
//
// Per frame: poll input -> camera controller -> Renderer::render (terrain,
// lighting, tonemap) -> blit the display image to the window -> UI pass ->
// swap. A minimised (0x0) window renders nothing and sleeps on events.
#include "app/explorer.h"

#include "gl/gl.h"  // before GLFW, so that GLFW does not pull in GL/gl.h
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>

#include "app/camera_controller.h"
#include "app/panels.h"
#include "app/render_scale.h"
#include "app/session.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "render/readback.h"
#include "render/renderer.h"
#include "scene/preset.h"
#include "scene/scene_params.h"
#include "scene/toml_error.h"
#include "util/log.h"

namespace planet {

namespace fs = std::filesystem;

bool displayAvailable() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

namespace {

struct GlfwLibrary {
    GlfwLibrary() {
        glfwSetErrorCallback([](int code, const char* text) {
            logError("GLFW error " + std::to_string(code) + ": " + text);
        });
        if (!glfwInit()) throw gl::ContextError("could not initialise GLFW (no usable display?)");
    }
    ~GlfwLibrary() { glfwTerminate(); }
    GlfwLibrary(const GlfwLibrary&) = delete;
    GlfwLibrary& operator=(const GlfwLibrary&) = delete;
};

struct WindowDeleter {
    void operator()(GLFWwindow* w) const { glfwDestroyWindow(w); }
};
using WindowPtr = std::unique_ptr<GLFWwindow, WindowDeleter>;

WindowPtr openWindow(glm::ivec2 size, bool debug) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);  // the tonemap pass writes encoded sRGB itself
    WindowPtr window(glfwCreateWindow(size.x, size.y, "planet", nullptr, nullptr));
    if (!window)
        throw gl::ContextError("could not open a window with an OpenGL 4.5 core context; this display's driver "
                               "does not offer one (see the GLFW error above)");
    glfwMakeContextCurrent(window.get());
    gl::requireGL45();
    glfwSwapInterval(1);
    return window;
}

// Where the panels' layout is kept between runs: $XDG_CONFIG_HOME/planet/imgui.ini, else
// ~/.config/planet/imgui.ini; never the working folder. Empty when there is no such folder
// and it cannot be made (the layout is then not kept).
std::string panelLayoutFile() {
    std::filesystem::path config;
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
        config = xdg;
    else if (const char* home = std::getenv("HOME"); home && *home)
        config = std::filesystem::path(home) / ".config";
    else
        return {};
    std::error_code ec;
    std::filesystem::create_directories(config / "planet", ec);
    if (ec) {
        logWarning("the panel layout will not be kept: cannot make " + (config / "planet").string() + ": " + ec.message());
        return {};
    }
    return (config / "planet" / "imgui.ini").string();
}

struct ImGuiLayer {
    explicit ImGuiLayer(GLFWwindow* window) : iniFile(panelLayoutFile()) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        // The layout the user left (ImGui reads it now and writes it back as it changes and at exit).
        ImGui::GetIO().IniFilename = iniFile.empty() ? nullptr : iniFile.c_str();
        ImGui::StyleColorsDark();
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 450 core");
    }
    ~ImGuiLayer() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;
    std::string iniFile;  // outlives the context, which keeps a pointer to it
};

// Input gathered between frames; GLFW reports scroll through a callback.
struct PendingInput {
    double scroll = 0.0;
    glm::dvec2 lastCursor{0.0};
    bool haveCursor = false;
    std::vector<int> keys;  // presses since the last frame
};

ControlInput pollControls(GLFWwindow* window, PendingInput& pending) {
    ControlInput in;
    const ImGuiIO& io = ImGui::GetIO();
    glm::dvec2 cursor;
    glfwGetCursorPos(window, &cursor.x, &cursor.y);
    const glm::dvec2 delta = pending.haveCursor ? cursor - pending.lastCursor : glm::dvec2(0.0);
    pending.lastCursor = cursor;
    pending.haveCursor = true;
    if (!io.WantCaptureKeyboard) {
        auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
        in.forward = down(GLFW_KEY_W);
        in.back = down(GLFW_KEY_S);
        in.left = down(GLFW_KEY_A);
        in.right = down(GLFW_KEY_D);
        in.up = down(GLFW_KEY_E);
        in.down = down(GLFW_KEY_Q);
        in.fast = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
        in.slow = down(GLFW_KEY_LEFT_CONTROL) || down(GLFW_KEY_RIGHT_CONTROL);
    }
    if (!io.WantCaptureMouse) {
        if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) {
            in.lookDx = delta.x;
            in.lookDy = delta.y;
        }
        if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) {
            in.orbitDx = delta.x;
            in.orbitDy = delta.y;
        }
        in.scroll = pending.scroll;
    }
    pending.scroll = 0.0;
    return in;
}

// The window does not wait for the atmosphere tables: unless the cache holds the target sizes,
// it starts with starter tables made at once and refines them in the background
// (atmosphere/atmosphere.h).
atmosphere::TablePlan explorerTables(const ExploreOptions& options, const DataPaths& paths, const Scene& scene) {
    const atmosphere::TableSizes target = atmosphere::tableSizesFor(options.common.tables, gl::rendererDescription());
    return atmosphere::startPlan(scene, target, atmosphere::defaultStarterTables(), paths.shaders());
}

// What the status line says while the tables are refined: which sizes, how far.
std::string refiningStatus(const atmosphere::Atmosphere& a) {
    if (!a.refining()) return {};
    const atmosphere::TableSizes& t = a.targetSizes();
    return "atmosphere: refining the tables to " + std::to_string(t.scattering_nu * t.scattering_mu_s) + "x" +
           std::to_string(t.scattering_mu) + "x" + std::to_string(t.scattering_r) + " in the background";
}

class Explorer {
public:
    Explorer(const ExploreOptions& options, GLFWwindow* window, const DataPaths& paths, Session session,
             std::chrono::steady_clock::time_point started)
        : options_(options), window_(window), session_(std::move(session)),
          renderer_(paths.shaders(), explorerTables(options, paths, session_.scene), session_.continents),
          started_(started),
          rendererName_(gl::rendererDescription()),
          presetPath_("out/presets/" + session_.presetName + ".toml"),  // never the shipped preset by default
          lastValidScene_(session_.scene),
          showUi_(!options.noPanels),
          renderScale_(parseRenderScale(options.renderScale)) {
        session_.scene.time_s = options.common.time;
        renderer_.setBackgroundBakes(true);  // a cloud rebake shows as progress in the Scene panel
        // A reset (a slider dragged, a jump) costs a reduced-rate frame and converges in 16; a
        // path plays as `planet render --path` renders it, its first frame at full rate.
        renderer_.setFullRateOnReset(!options.path.empty());
        // On a software renderer the passes do not overlap anyway: finish each one, so that the
        // Frame time panel's CPU + wait is each pass's own work (the panel's checkbox turns it off).
        renderer_.profiler().setFinishEachPass(softwareRenderer(rendererName_));
        if (!options.path.empty()) {
            path_.emplace(loadSessionPath(paths, options.path, session_));
            pathFrames_ = pathFrameCount(path_->file(), std::nullopt);
            pathPlaying_ = true;
            logInfo("playing path '" + path_->file().name + "': " + std::to_string(pathFrames_) +
                    " frames, one a window frame (P pauses)");
        }
        glfwSetWindowUserPointer(window_, &pending_);
        glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
            static_cast<PendingInput*>(glfwGetWindowUserPointer(w))->scroll += dy;
        });
        glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
            if (action == GLFW_PRESS) static_cast<PendingInput*>(glfwGetWindowUserPointer(w))->keys.push_back(key);
        });
    }

    void run();

private:
    void handleKeys();
    void drawUi(glm::ivec2 window);
    void acceptOrRevertEdit();
    void jumpToView(std::size_t index);
    void savePreset();
    void pollShaders();
    void followPath();
    glm::ivec2 frameSizeFor(glm::ivec2 window);

    const ExploreOptions& options_;
    GLFWwindow* window_;
    Session session_;
    Renderer renderer_;
    std::chrono::steady_clock::time_point started_;  // when the command started: the first frame's time
    CameraController controller_;
    std::string rendererName_;
    std::string presetPath_;
    std::string status_;
    Scene lastValidScene_;  // what the panels last produced that passed validateScene
    bool showUi_;
    bool screenshotRequested_ = false;
    WaveClock clock_;
    PendingInput pending_;
    std::chrono::steady_clock::time_point lastShaderPoll_{};
    std::vector<std::string> lastShaderErrors_;  // logged once each
    // Path playback (--path): the natural frames of render --path, one per window frame.
    std::optional<CameraPath> path_;
    int pathFrame_ = 0;
    int pathFrames_ = 0;
    bool pathPlaying_ = false;
    std::optional<double> renderScale_;  // nullopt: auto (render_scale.h)
    glm::ivec2 frameSize_{0};            // the last frame's size, to log a change once
};

void Explorer::handleKeys() {
    const bool typing = ImGui::GetIO().WantCaptureKeyboard;
    for (int key : pending_.keys) {
        if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window_, GLFW_TRUE);
        if (key == GLFW_KEY_F1) showUi_ = !showUi_;
        if (key == GLFW_KEY_F5) renderer_.reloadShaders(true);
        if (key == GLFW_KEY_F12) screenshotRequested_ = true;
        if (typing) continue;
        if (key == GLFW_KEY_TAB)
            controller_.mode = controller_.mode == CameraMode::Fly ? CameraMode::Orbit : CameraMode::Fly;
        if (key == GLFW_KEY_P && path_) {  // pause, resume, or play again from the start once ended
            if (!pathPlaying_ && pathFrame_ >= pathFrames_) pathFrame_ = 0;
            pathPlaying_ = !pathPlaying_;
        }
        const int index = key - GLFW_KEY_1;
        if (index >= 0 && index < 9 && index < static_cast<int>(session_.views.size()))
            jumpToView(static_cast<std::size_t>(index));
    }
    pending_.keys.clear();
}

// The path's next frame: the camera, the sun (when the path has one) and the clock, as
// render --path sets them for its frame of that number.
void Explorer::followPath() {
    const double t = pathFrameTime(path_->file(), pathFrame_, pathFrames_);
    const std::string fix = applyPathSample(*path_, t, options_.common.time, session_);
    if (!fix.empty()) logWarning("path '" + path_->file().name + "': " + fix);
    lastValidScene_ = session_.scene;  // the path's sun is not an edit to revert
    if (++pathFrame_ >= pathFrames_) {
        pathPlaying_ = false;
        logInfo("path '" + path_->file().name + "' ended (P plays it again)");
    }
}

// The frame's size for a window of `window` pixels at the render scale; logged when it changes
// (the first frame, a resize, the panel's slider): a new size also restarts the history.
glm::ivec2 Explorer::frameSizeFor(glm::ivec2 window) {
    const double scale = renderScaleFor(renderScale_, rendererName_, window);
    const glm::ivec2 size = scaledSize(window, scale);
    if (size != frameSize_) {
        frameSize_ = size;
        std::string line = "the frame is " + std::to_string(size.x) + "x" + std::to_string(size.y);
        if (size != window) {
            char scaleText[16];
            std::snprintf(scaleText, sizeof scaleText, "%.3g", scale);
            line += ", shown at " + std::to_string(window.x) + "x" + std::to_string(window.y) + " (render scale " +
                    scaleText + (renderScale_ ? "" : ", auto on a software renderer; --render-scale 1 for every pixel") +
                    ")";
        }
        logInfo(line);
    }
    return size;
}

void Explorer::pollShaders() {
    const auto now = std::chrono::steady_clock::now();
    if (now - lastShaderPoll_ < std::chrono::milliseconds(500)) return;
    lastShaderPoll_ = now;
    if (renderer_.reloadShaders()) logInfo("shaders reloaded");
    std::vector<std::string> errors = renderer_.shaderErrors();
    if (errors != lastShaderErrors_) {
        for (const std::string& e : errors) logError(e);
        lastShaderErrors_ = std::move(errors);
    }
}

void Explorer::savePreset() {
    try {
        planet::savePreset(session_.scene, presetPath_, session_.presetName, "saved from the explorer");
        status_ = "saved " + presetPath_;
    } catch (const std::exception& e) {
        status_ = std::string("not saved: ") + e.what();
    }
    logInfo(status_);
}

void Explorer::jumpToView(std::size_t index) {
    applyView(session_.views[index], session_);
    lastValidScene_ = session_.scene;  // the view's sun is part of the scene now
}

// A panel edit that breaks a rule between parameters (the atmosphere's top
// below the ground, say) is undone and explained, so the frame never renders
// an impossible scene.
void Explorer::acceptOrRevertEdit() {
    const std::vector<SceneProblem> problems = validateScene(session_.scene);
    if (problems.empty()) {
        lastValidScene_ = session_.scene;
        return;
    }
    const double time = session_.scene.time_s;  // the clock runs on
    session_.scene = lastValidScene_;
    session_.scene.time_s = time;
    status_ = "not applied: " + problems.front().field + ": " + problems.front().message;
    logWarning(status_);
}

void Explorer::drawUi(glm::ivec2 window) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const atmosphere::Atmosphere& air = renderer_.atmosphere();
    if (showUi_) {
        RenderScaleUi scale{renderScale_, renderScaleFor(renderScale_, rendererName_, window), frameSize_};
        drawProfilerPanel(renderer_.profiler(), rendererName_, &scale);
        if (drawSceneParams(session_.scene, air.rebuildProgress(), renderer_.cloudBakeProgress(),
                            air.refining() ? "refining tables" : "rebuilding tables"))
            acceptOrRevertEdit();
        if (session_.scene.terrain.ocean && drawWavePanel(session_.scene, clock_)) acceptOrRevertEdit();
        const CameraPanelResult r =
            drawCameraPanel(session_.camera, controller_, session_.scene, session_.views, presetPath_, status_);
        if (r.sunMoved) acceptOrRevertEdit();
        if (r.jumpToView >= 0) jumpToView(static_cast<std::size_t>(r.jumpToView));
        if (r.savePreset) savePreset();
    }
    drawShaderErrors(renderer_.shaderErrors());
    drawStatusLine(refiningStatus(air), air.rebuilding() ? air.rebuildProgress() : 0.0);  // 0 until it starts
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Explorer::run() {
    auto last = std::chrono::steady_clock::now();
    for (int frame = 0; !glfwWindowShouldClose(window_); ++frame) {
        glfwPollEvents();
        glm::ivec2 size;
        glfwGetFramebufferSize(window_, &size.x, &size.y);
        if (size.x <= 0 || size.y <= 0) {  // minimised: nothing to draw, wait for the window to come back
            glfwWaitEventsTimeout(0.25);
            last = std::chrono::steady_clock::now();
            continue;
        }
        const auto now = std::chrono::steady_clock::now();
        const double dt = std::chrono::duration<double>(now - last).count();
        last = now;

        pollShaders();
        handleKeys();
        if (pathPlaying_) {
            pollControls(window_, pending_);  // the path flies the camera: input is dropped, not queued
            followPath();
        } else {
            if (!clock_.paused) session_.scene.time_s += dt * clock_.rate;
            controller_.update(session_.camera, pollControls(window_, pending_), dt, session_.scene.planetRadiusM());
            keepAboveGround(session_);
        }
        // Anti-aliased edges: jittered frames blended over time, with the rest of the temporal
        // work (render.temporal; --no-temporal renders what a one-sample still shows). A path
        // plays as `render --path` renders it.
        renderer_.setTemporalAntialiasing(session_.scene.render.temporal && !pathPlaying_);
        const glm::ivec2 rendered = frameSizeFor(size);
        renderer_.render(session_.scene, session_.camera, rendered, [&] {
            glBlitNamedFramebuffer(renderer_.targets().ldrFramebuffer(), 0, 0, 0, rendered.x, rendered.y, 0, 0, size.x,
                                   size.y, GL_COLOR_BUFFER_BIT, rendered == size ? GL_NEAREST : GL_LINEAR);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, size.x, size.y);
            drawUi(size);
        });
        const bool lastFrame = options_.frames > 0 && frame + 1 >= options_.frames;
        if (screenshotRequested_ || (lastFrame && !options_.screenshot.empty())) {
            const std::string path = options_.screenshot.empty() ? "out/screenshot.png" : options_.screenshot;
            writePng(readFramebufferRGBA8(0, size.x, size.y), path);
            std::cout << "wrote " << fs::absolute(path).lexically_normal().string() << std::endl;
            screenshotRequested_ = false;
        }
        glfwSwapBuffers(window_);
        if (frame == 0)
            logInfo("first frame on screen " +
                    std::to_string(std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count()) +
                    " s after the start");
        if (lastFrame) break;
    }
}

}  // namespace

int runExplore(const ExploreOptions& options) {
    const auto started = std::chrono::steady_clock::now();
    if (options.frames < 0) throw InputError("--frames must be >= 0");
    if (!displayAvailable()) {
        std::cout << "No display found (DISPLAY and WAYLAND_DISPLAY are unset): rendering a still instead."
                  << std::endl;
        if (!options.path.empty())
            std::cout << "(--path needs a window; planet render --path renders its frames headlessly)" << std::endl;
        renderStill(options.common, {options.headlessOut}, std::nullopt);
        return 0;
    }
    const DataPaths paths = findDataPaths(options.common.root);
    Session session = loadSession(paths, options.common.preset, options.common.view, options.common.noTemporal);
    const glm::ivec2 size = parseSize(options.common.size);

    gl::DebugMessages messages;  // outlives the context that reports into it
    GlfwLibrary glfw;
    WindowPtr window = openWindow(size, options.common.glDebug);
    gl::installDebugOutput(&messages, options.common.glDebug);  // always to the log; --gl-debug: debug context, synchronous
    logInfo("OpenGL: " + gl::rendererDescription());
    Explorer explorer(options, window.get(), paths, std::move(session), started);  // installs callbacks before ImGui chains them
    ImGuiLayer imgui(window.get());
    explorer.run();
    return 0;
}

}  // namespace planet
