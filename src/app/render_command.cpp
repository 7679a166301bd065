// `planet render`: one still from a preset and a view, headless (EGL), to PNG
// (display-ready sRGB) and/or OpenEXR (linear HDR); with --samples 1 the same pixels
// the explorer's window shows for the same inputs.
//
// Anti-aliasing (issue 13): a still is the mean of --samples frames (default
// kStillSamples), each rendered with its projection moved by a sub-pixel offset
// (stillSampleJitter: Halton (2, 3) centred on the pixel; Renderer::setJitter) --
// a box filter over the pixel, estimated with N points. Each sample is a whole frame
// at full rate: the history is dropped before it, so the temporal cloud march never
// mixes one sample's sky into another's (a reprojected jittered history would blur by
// the jitter, and the mean would no longer be the mean of N stills). The mean is
// taken in linear HDR radiance, then tone mapped once (Renderer::tonemapRadiance):
// averaging after the tone curve would darken bright edges. One sample is the
// unjittered frame, exactly as before.
#include <algorithm>
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

constexpr int kMaxSamples = 256;

void checkOutputs(const std::vector<std::string>& outputs) {
    if (outputs.empty()) throw InputError("--out: give at least one output file (.png or .exr)");
    for (const std::string& out : outputs) {
        const std::string ext = fs::path(out).extension().string();
        if (ext != ".png" && ext != ".exr")
            throw InputError("--out '" + out + "': unknown image type '" + ext + "' (use .png or .exr)");
    }
    checkOutputsWritable(outputs);
}

// `radiance`, when given, is the accumulated HDR image the renderer's ldr() was tone mapped from.
void writeOutputs(const Renderer& renderer, const std::vector<std::string>& outputs, glm::ivec2 size,
                  double exposure, const ImageRGBAF* radiance = nullptr) {
    for (const std::string& out : outputs) {
        if (fs::path(out).extension() == ".png")
            writePng(readTextureRGBA8(renderer.targets().ldr(), size.x, size.y), out);
        else
            writeExr(radiance ? *radiance : readTextureRGBAF(renderer.targets().hdr(), size.x, size.y), out, exposure);
        std::cout << "wrote " << fs::absolute(out).lexically_normal().string() << "\n";
    }
}

std::string formatSeconds(double s) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f s", s);
    return buffer;
}

// Renders the scene as `samples` jittered full-rate frames and leaves their mean, tone
// mapped, in renderer.targets().ldr(); returns the mean linear radiance. With `report`, a
// line on stderr after each sample, after `prefix`.
ImageRGBAF renderAccumulated(Renderer& renderer, const Scene& scene, const Camera& camera, glm::ivec2 size,
                             int samples, bool report, const std::string& prefix) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    ImageRGBAF sum{size.x, size.y, std::vector<float>(static_cast<std::size_t>(size.x) * size.y * 4, 0.0f)};
    for (int i = 0; i < samples; ++i) {
        renderer.dropHistory();  // each sample a full-rate still (see the top of this file)
        renderer.setJitter(stillSampleJitter(i, samples));
        renderer.render(scene, camera, size);
        const ImageRGBAF frame = readTextureRGBAF(renderer.targets().hdr(), size.x, size.y);
        for (std::size_t k = 0; k < sum.pixels.size(); ++k) sum.pixels[k] += frame.pixels[k];
        if (report) {
            const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
            std::cerr << prefix << "sample " << (i + 1) << " of " << samples << ": elapsed " << formatSeconds(elapsed)
                      << ", about " << formatSeconds(elapsed / (i + 1) * (samples - i - 1)) << " left\n";
        }
    }
    renderer.setJitter(glm::dvec2(0.0));
    const float scale = 1.0f / static_cast<float>(samples);
    for (float& v : sum.pixels) v *= scale;
    renderer.tonemapRadiance(sum);
    return sum;
}

void checkSamples(int samples) {
    if (samples < 1 || samples > kMaxSamples)
        throw InputError("--samples must be in [1, " + std::to_string(kMaxSamples) + "]");
}

void applyExposure(std::optional<double> exposure, Scene& scene) {
    if (!exposure) return;
    // Same range as the preset's render.exposure.
    if (!(*exposure >= 1e-3 && *exposure <= 1e3)) throw InputError("--exposure must be in [0.001, 1000]");
    scene.render.exposure = *exposure;
}

}  // namespace

void renderStill(const CommonOptions& common, const std::vector<std::string>& outputs,
                 std::optional<double> exposure, int samples) {
    checkSamples(samples);
    checkOutputs(outputs);
    const glm::ivec2 size = parseSize(common.size);
    const DataPaths paths = findDataPaths(common.root);
    Session session = loadSession(paths, common.preset, common.view, common.noTemporal);
    session.scene.time_s = common.time;
    applyExposure(exposure, session.scene);

    gl::DebugMessages messages;  // outlives the context that reports into it
    gl::HeadlessContext context(common.glDebug);
    gl::installDebugOutput(&messages, common.glDebug);  // always to the log; --gl-debug: debug context, synchronous
    logInfo("rendering " + std::to_string(size.x) + "x" + std::to_string(size.y) +
            (samples > 1 ? ", " + std::to_string(samples) + " jittered samples," : std::string()) + " on " +
            gl::rendererDescription() + " via " + context.platform());
    Renderer renderer(paths.shaders(), atmosphere::tableSizesFor(common.tables, gl::rendererDescription()), session.continents);
    if (samples == 1) {  // the unjittered frame, as the explorer's window shows it
        renderer.render(session.scene, session.camera, size);
        writeOutputs(renderer, outputs, size, session.scene.render.exposure);
        return;
    }
    const ImageRGBAF mean = renderAccumulated(renderer, session.scene, session.camera, size, samples, true, "");
    writeOutputs(renderer, outputs, size, session.scene.render.exposure, &mean);
}

void renderPath(const CommonOptions& common, const std::vector<std::string>& outputs,
                std::optional<double> exposure, const std::string& pathName, std::optional<int> frames,
                int samples) {
    checkSamples(samples);
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
        std::vector<std::string> names;
        for (const std::string& out : outputs) names.push_back(frameFileName(out, i));
        if (samples == 1) {  // with the history of the frames before, as the explorer plays it
            renderer.render(session.scene, session.camera, size);
            writeOutputs(renderer, names, size, session.scene.render.exposure);
        } else {
            const ImageRGBAF mean = renderAccumulated(renderer, session.scene, session.camera, size, samples,
                                                      samples >= 8, "frame " + std::to_string(i + 1) + ": ");
            writeOutputs(renderer, names, size, session.scene.render.exposure, &mean);
        }

        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        const double remaining = elapsed / (i + 1) * (frameCount - i - 1);
        std::cerr << "frame " << (i + 1) << " of " << frameCount << " (t = " << formatSeconds(t - file.startTime())
                  << "): elapsed " << formatSeconds(elapsed) << ", about " << formatSeconds(remaining) << " left\n";
    }
}

int runRender(const RenderOptions& options) {
    if (!options.path.empty()) {
        renderPath(options.common, options.outputs, options.exposure, options.path, options.frames,
                   options.samples.value_or(1));
        return 0;
    }
    if (options.frames) throw InputError("--frames needs --path (a still is one frame)");
    renderStill(options.common, options.outputs, options.exposure, options.samples.value_or(kStillSamples));
    return 0;
}

}  // namespace planet
