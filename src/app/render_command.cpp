// `planet render`: one still from a preset and a view, headless (EGL), to PNG
// (display-ready sRGB) and/or OpenEXR (linear HDR), the same pixels the
// explorer's window shows for the same inputs.
#include <chrono>
#include <cstdio>
#include <iostream>

#include "app/camera_path.h"
#include "app/commands.h"
#include "app/session.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "render/readback.h"
#include "render/renderer.h"
#include "scene/toml_error.h"
#include "util/log.h"

namespace planet {

namespace fs = std::filesystem;

namespace {

void checkOutputs(const std::vector<std::string>& outputs) {
    if (outputs.empty()) throw InputError("--out: give at least one output file (.png or .exr)");
    for (const std::string& out : outputs) {
        const std::string ext = fs::path(out).extension().string();
        if (ext != ".png" && ext != ".exr")
            throw InputError("--out '" + out + "': unknown image type '" + ext + "' (use .png or .exr)");
    }
    checkOutputsWritable(outputs);
}

void writeOutputs(const Renderer& renderer, const std::vector<std::string>& outputs, glm::ivec2 size,
                  double exposure) {
    for (const std::string& out : outputs) {
        if (fs::path(out).extension() == ".png")
            writePng(readTextureRGBA8(renderer.targets().ldr(), size.x, size.y), out);
        else
            writeExr(readTextureRGBAF(renderer.targets().hdr(), size.x, size.y), out, exposure);
        std::cout << "wrote " << fs::absolute(out).lexically_normal().string() << "\n";
    }
}

void applyExposure(std::optional<double> exposure, Scene& scene) {
    if (!exposure) return;
    // Same range as the preset's render.exposure.
    if (!(*exposure >= 1e-3 && *exposure <= 1e3)) throw InputError("--exposure must be in [0.001, 1000]");
    scene.render.exposure = *exposure;
}

std::string formatSeconds(double s) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f s", s);
    return buffer;
}

}  // namespace

void renderStill(const CommonOptions& common, const std::vector<std::string>& outputs,
                 std::optional<double> exposure) {
    checkOutputs(outputs);
    const glm::ivec2 size = parseSize(common.size);
    const DataPaths paths = findDataPaths(common.root);
    Session session = loadSession(paths, common.preset, common.view, common.noTemporal);
    session.scene.time_s = common.time;
    applyExposure(exposure, session.scene);

    gl::DebugMessages messages;  // outlives the context that reports into it
    gl::HeadlessContext context(common.glDebug);
    gl::installDebugOutput(&messages, common.glDebug);  // always to the log; --gl-debug: debug context, synchronous
    logInfo("rendering " + std::to_string(size.x) + "x" + std::to_string(size.y) + " on " +
            gl::rendererDescription() + " via " + context.platform());
    Renderer renderer(paths.shaders(), atmosphere::tableSizesFor(common.tables, gl::rendererDescription()), session.continents);
    renderer.render(session.scene, session.camera, size);
    writeOutputs(renderer, outputs, size, session.scene.render.exposure);
}

void renderPath(const CommonOptions& common, const std::vector<std::string>& outputs,
                std::optional<double> exposure, const std::string& pathName, std::optional<int> frames) {
    if (outputs.empty()) throw InputError("--out: give at least one output file pattern (.png or .exr)");
    for (const std::string& out : outputs) frameFileName(out, 0);  // each names the frame number
    const glm::ivec2 size = parseSize(common.size);
    const DataPaths paths = findDataPaths(common.root);
    Session session = loadSession(paths, common.preset, common.view, common.noTemporal);
    applyExposure(exposure, session.scene);
    const CameraPath path = loadSessionPath(paths, pathName, session);
    const CameraPathFile& file = path.file();
    const int frameCount = pathFrameCount(file, frames);
    std::vector<std::string> firstOutputs;
    for (const std::string& out : outputs) firstOutputs.push_back(frameFileName(out, 0));
    checkOutputs(firstOutputs);

    gl::DebugMessages messages;  // outlives the context that reports into it
    gl::HeadlessContext context(common.glDebug);
    gl::installDebugOutput(&messages, common.glDebug);
    logInfo("rendering path '" + file.name + "': " + std::to_string(frameCount) + " frames of " +
            std::to_string(size.x) + "x" + std::to_string(size.y) + " on " + gl::rendererDescription() + " via " +
            context.platform());
    // One renderer for the whole sequence: each frame has the history of the ones before it.
    Renderer renderer(paths.shaders(), atmosphere::tableSizesFor(common.tables, gl::rendererDescription()),
                      session.continents);
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    for (int i = 0; i < frameCount; ++i) {
        const double t = pathFrameTime(file, i, frameCount);
        const std::string fix = applyPathSample(path, t, common.time, session);
        if (!fix.empty()) logWarning("path '" + file.name + "' frame " + std::to_string(i) + ": " + fix);
        renderer.render(session.scene, session.camera, size);

        std::vector<std::string> names;
        for (const std::string& out : outputs) names.push_back(frameFileName(out, i));
        writeOutputs(renderer, names, size, session.scene.render.exposure);

        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        const double remaining = elapsed / (i + 1) * (frameCount - i - 1);
        std::cerr << "frame " << (i + 1) << " of " << frameCount << " (t = " << formatSeconds(t - file.startTime())
                  << "): elapsed " << formatSeconds(elapsed) << ", about " << formatSeconds(remaining) << " left\n";
    }
}

int runRender(const RenderOptions& options) {
    if (!options.path.empty()) {
        renderPath(options.common, options.outputs, options.exposure, options.path, options.frames);
        return 0;
    }
    if (options.frames) throw InputError("--frames needs --path (a still is one frame)");
    renderStill(options.common, options.outputs, options.exposure);
    return 0;
}

}  // namespace planet
