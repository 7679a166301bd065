#include "render/render_targets.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace planet {

namespace {

gl::Texture makeTexture(GLenum format, glm::ivec2 size, const char* label) {
    gl::Texture t(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, format, size.x, size.y);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    t.label(label);
    return t;
}

void checkComplete(const gl::Framebuffer& fb, const char* name) {
    const GLenum status = glCheckNamedFramebufferStatus(fb.id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string("framebuffer '") + name + "' incomplete (status " +
                                 std::to_string(status) + ")");
}

}  // namespace

void RenderTargets::resize(glm::ivec2 size) {
    if (size == size_) return;
    if (size.x <= 0 || size.y <= 0) throw std::invalid_argument("render target size must be positive");
    GLint maxSize = 0, maxViewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
    const int limit = std::min({maxSize, maxViewport[0], maxViewport[1]});
    if (size.x > limit || size.y > limit)
        throw std::invalid_argument("frame size " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                                    " exceeds this GPU's limit of " + std::to_string(limit) + " pixels per side");
    size_ = size;

    gbuffer_.normal = makeTexture(GL_RGBA16F, size, "gbuffer.normal");
    gbuffer_.albedo = makeTexture(GL_RGBA8, size, "gbuffer.albedo");
    gbuffer_.material = makeTexture(GL_RGBA8, size, "gbuffer.material");
    gbuffer_.depth = makeTexture(GL_DEPTH_COMPONENT32F, size, "gbuffer.depth");
    gbuffer_.framebuffer = gl::Framebuffer();
    const GLuint fb = gbuffer_.framebuffer.id();
    glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT0, gbuffer_.normal.id(), 0);
    glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT1, gbuffer_.albedo.id(), 0);
    glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT2, gbuffer_.material.id(), 0);
    glNamedFramebufferTexture(fb, GL_DEPTH_ATTACHMENT, gbuffer_.depth.id(), 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(fb, 3, buffers);
    gbuffer_.framebuffer.label("gbuffer");
    checkComplete(gbuffer_.framebuffer, "gbuffer");

    hdr_ = makeTexture(GL_RGBA16F, size, "hdr");
    hdrFramebuffer_ = gl::Framebuffer();
    glNamedFramebufferTexture(hdrFramebuffer_.id(), GL_COLOR_ATTACHMENT0, hdr_.id(), 0);
    hdrFramebuffer_.label("hdr");
    checkComplete(hdrFramebuffer_, "hdr");

    ldr_ = makeTexture(GL_RGBA8, size, "ldr");
    ldrFramebuffer_ = gl::Framebuffer();
    glNamedFramebufferTexture(ldrFramebuffer_.id(), GL_COLOR_ATTACHMENT0, ldr_.id(), 0);
    ldrFramebuffer_.label("ldr");
    checkComplete(ldrFramebuffer_, "ldr");

    surfaceFramebuffer_ = gl::Framebuffer();
    glNamedFramebufferTexture(surfaceFramebuffer_.id(), GL_COLOR_ATTACHMENT0, hdr_.id(), 0);
    glNamedFramebufferTexture(surfaceFramebuffer_.id(), GL_DEPTH_ATTACHMENT, gbuffer_.depth.id(), 0);
    surfaceFramebuffer_.label("hdr + depth");
    checkComplete(surfaceFramebuffer_, "hdr + depth");
    seabedDepth_ = makeTexture(GL_DEPTH_COMPONENT32F, size, "seabed depth");
    seabedRadiance_ = makeTexture(GL_RGBA16F, size, "seabed radiance");
}

void RenderTargets::copySeabed() const {
    glCopyImageSubData(gbuffer_.depth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, seabedDepth_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       size_.x, size_.y, 1);
    glCopyImageSubData(hdr_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, seabedRadiance_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, size_.x,
                       size_.y, 1);
}

}  // namespace planet
