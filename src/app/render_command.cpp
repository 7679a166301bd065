// `planet render`: one still from a preset and a view, headless (EGL), to PNG
// (display-ready sRGB) and/or OpenEXR (linear HDR), the same pixels the
// explorer's window shows for the same inputs.
#include <iostream>

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

}  // namespace

void renderStill(const CommonOptions& common, const std::vector<std::string>& outputs,
                 std::optional<double> exposure) {
    checkOutputs(outputs);
    const glm::ivec2 size = parseSize(common.size);
    const DataPaths paths = findDataPaths(common.root);
    Session session = loadSession(paths, common.preset, common.view);
    session.scene.time_s = common.time;
    if (exposure) {
        // Same range as the preset's render.exposure.
        if (!(*exposure >= 1e-3 && *exposure <= 1e3)) throw InputError("--exposure must be in [0.001, 1000]");
        session.scene.render.exposure = *exposure;
    }

    gl::DebugMessages messages;  // outlives the context that reports into it
    gl::HeadlessContext context(common.glDebug);
    gl::installDebugOutput(&messages, common.glDebug);  // always to the log; --gl-debug: debug context, synchronous
    logInfo("rendering " + std::to_string(size.x) + "x" + std::to_string(size.y) + " on " +
            gl::rendererDescription() + " via " + context.platform());
    Renderer renderer(paths.shaders(), atmosphere::tableSizesFor(common.tables, gl::rendererDescription()), session.continents);
    renderer.render(session.scene, session.camera, size);

    for (const std::string& out : outputs) {
        if (fs::path(out).extension() == ".png")
            writePng(readTextureRGBA8(renderer.targets().ldr(), size.x, size.y), out);
        else
            writeExr(readTextureRGBAF(renderer.targets().hdr(), size.x, size.y), out, session.scene.render.exposure);
        std::cout << "wrote " << fs::absolute(out).lexically_normal().string() << "\n";
    }
}

int runRender(const RenderOptions& options) {
    renderStill(options.common, options.outputs, options.exposure);
    return 0;
}

}  // namespace planet
