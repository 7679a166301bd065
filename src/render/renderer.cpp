#include "render/renderer.h"

#include "gl/debug.h"
#include "render/frame_uniforms.h"

namespace planet {

namespace {
gl::ShaderSources lightingSources(const std::filesystem::path& root, const atmosphere::TableSizes& sizes, bool elek) {
    return {root, gl::shaderPreamble() + atmosphere::atmosphereShaderDefines(sizes) +
                      "#define ELEK_TABLE " + (elek ? "1" : "0") + "\n"};
}
}  // namespace

Renderer::Renderer(const std::filesystem::path& shaderRoot, const atmosphere::TableSizes& atmosphereTables)
    : sources_{shaderRoot, gl::shaderPreamble()},
      atmosphere_(shaderRoot, atmosphereTables),
      terrain_(sources_),
      lighting4D_(lightingSources(shaderRoot, atmosphereTables, false), "atmosphere 4D", "render/lighting.frag"),
      lightingElek_(lightingSources(shaderRoot, atmosphereTables, true), "atmosphere Elek 3D", "render/lighting.frag"),
      ocean_(lightingSources(shaderRoot, atmosphereTables, false)),
      tonemap_(sources_, "tonemap", "render/tonemap.frag") {
    glNamedBufferStorage(frameUniforms_.id(), sizeof(FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    frameUniforms_.label("FrameUniforms");
    emptyVertexArray_.label("fullscreen triangle");
}

void Renderer::render(const Scene& scene, const Camera& camera, glm::ivec2 size,
                      const std::function<void()>& present) {
    if (size.x <= 0 || size.y <= 0) return;
    targets_.resize(size);
    profiler_.beginFrame();
    if (atmosphere_.rebuilding()) {
        gl::DebugGroup group("atmosphere tables");
        auto timing = profiler_.pass("atmosphere tables");
        atmosphere_.update(scene);
    } else {
        atmosphere_.update(scene);  // usually nothing to do; starts a rebuild when the atmosphere changed
    }

    const FrameUniforms uniforms = makeFrameUniforms(scene, camera, size);
    glNamedBufferSubData(frameUniforms_.id(), 0, sizeof uniforms, &uniforms);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, frameUniforms_.id());
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // reversed-Z needs [0, 1] clip depth
    glViewport(0, 0, size.x, size.y);
    glBindVertexArray(emptyVertexArray_.id());
    glDisable(GL_BLEND);

    {
        gl::DebugGroup group("terrain");
        auto timing = profiler_.pass("terrain");
        const GLuint fb = targets_.gbuffer().framebuffer.id();
        const float zero[4] = {0, 0, 0, 0};
        for (GLint i = 0; i < 3; ++i) glClearNamedFramebufferfv(fb, GL_COLOR, i, zero);
        const float farDepth = 0.0f;  // reversed-Z: 0 is infinitely far
        glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &farDepth);
        glBindFramebuffer(GL_FRAMEBUFFER, fb);
        terrain_.draw(scene, camera);
    }
    {
        gl::DebugGroup group("atmosphere");  // lighting + aerial perspective + sky, over the G-buffer
        auto timing = profiler_.pass("atmosphere");
        glBindFramebuffer(GL_FRAMEBUFFER, targets_.hdrFramebuffer());
        const GBuffer& g = targets_.gbuffer();
        const GLuint inputs[] = {g.normal.id(), g.albedo.id(), g.material.id(), g.depth.id()};
        glBindTextures(0, 4, inputs);
        atmosphere_.bind();
        (atmosphere_.usesElekTable() ? lightingElek_ : lighting4D_).draw();
    }
    if (scene.terrain.ocean) {
        gl::DebugGroup group("ocean");
        auto timing = profiler_.pass("ocean");
        targets_.copySeabed();
        glBindFramebuffer(GL_FRAMEBUFFER, targets_.surfaceFramebuffer());
        const GLuint inputs[] = {targets_.seabedDepth().id(), targets_.seabedRadiance().id()};
        glBindTextures(0, 2, inputs);
        atmosphere_.bind();
        terrain_.bindHeightField();  // the sea floor's height, for the far sea
        if (OceanPass::cameraDepthM(scene, camera) > 0.0) {
            glBindVertexArray(emptyVertexArray_.id());
            ocean_.drawUnderwater(scene, camera);
        }
        ocean_.drawSurface(scene, camera);
        glBindVertexArray(emptyVertexArray_.id());
    }
    {
        gl::DebugGroup group("tonemap");
        auto timing = profiler_.pass("tonemap");
        glBindFramebuffer(GL_FRAMEBUFFER, targets_.ldrFramebuffer());
        const GLuint input = targets_.hdr().id();
        glBindTextures(0, 1, &input);
        tonemap_.draw();
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (present) {
        gl::DebugGroup group("ui");
        auto timing = profiler_.pass("ui");
        present();
    }
    profiler_.endFrame();
}

std::vector<gl::HotProgram*> Renderer::programs() {
    return {&terrain_.program(),       &lighting4D_.program(),         &lightingElek_.program(),
            &ocean_.surfaceProgram(), &ocean_.underwaterProgram(), &tonemap_.program()};
}

bool Renderer::reloadShaders(bool force) {
    bool any = false;
    for (gl::HotProgram* p : programs()) any = p->reloadIfChanged(force) || any;
    return any;
}

std::vector<std::string> Renderer::shaderErrors() {
    std::vector<std::string> errors;
    for (gl::HotProgram* p : programs())
        if (!p->error().empty()) errors.push_back(p->error());
    return errors;
}

}  // namespace planet
