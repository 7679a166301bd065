// Rendering a view in-process the way `planet render` does, for tests that compare
// stills (tests/test_reference_images.cpp): the one place to change when the
// Renderer's API or the render command's path changes.
//
// It mirrors renderStill (src/app/render_command.cpp) for `planet render --preset P
// --view V --size WxH --tables reduced`: the session as loadSession gives it, the
// clock at 0 (the default --time), a fresh Renderer (no frame history) with the
// reduced atmosphere tables, one frame, the linear HDR target read back.
// CliReferenceImages in test_reference_images.cpp checks that the command's EXR
// equals what this returns. Needs a current GL context (test::GLTest).
#pragma once

#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "app/session.h"
#include "gl_test_support.h"
#include "render/readback.h"
#include "render/renderer.h"

namespace planet::test {

// A suite that shares one Renderer (reduced tables) across its tests, made once the GL
// context is up and gone before it goes.
class SharedRendererTest : public GLTest {
protected:
    static void SetUpTestSuite() {
        GLTest::SetUpTestSuite();
        renderer = std::make_unique<Renderer>(repoPaths().shaders(), atmosphere::TableSizes::reduced());
    }
    static void TearDownTestSuite() {
        renderer.reset();
        GLTest::TearDownTestSuite();
    }
    static inline std::unique_ptr<Renderer> renderer;
};

struct HdrStill {
    ImageRGBAF radiance;  // linear HDR, row 0 at the top
    double exposure = 1.0;  // the preset's, for the EXR header (as `planet render` writes it)
};

inline HdrStill renderStillHdr(const std::string& preset, const std::string& view, glm::ivec2 size) {
    Session session = loadSession(repoPaths(), preset, view);
    session.scene.time_s = 0.0;
    Renderer renderer(repoPaths().shaders(), atmosphere::TableSizes::reduced());
    renderer.render(session.scene, session.camera, size);
    return {readTextureRGBAF(renderer.targets().hdr(), size.x, size.y), session.scene.render.exposure};
}

}  // namespace planet::test
