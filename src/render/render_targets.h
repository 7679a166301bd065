// The frame's render targets: G-buffer, HDR radiance and the display image.
//
//   gbuffer  normal (RGBA16F, world axes), albedo (RGBA8, linear), material
//            (RGBA8: id/255, roughness), depth (DEPTH32F, reversed-Z)
//   hdr      RGBA16F linear radiance (what `render --out x.exr` writes)
//   ldr      RGBA8 tone-mapped sRGB bytes (what the window shows and PNGs hold)
//   seabed   copies of the G-buffer depth and of hdr taken before the ocean pass, which
//            reads them while drawing into hdr + the G-buffer depth (surfaceFramebuffer)
//
// Layout must match shaders/common/gbuffer.glsl. Resized only when the frame
// size changes; a 0x0 size (minimised window) holds no textures.
#pragma once

#include <glm/glm.hpp>

#include "gl/handle.h"

namespace planet {

struct GBuffer {
    gl::Texture normal{GL_TEXTURE_2D};
    gl::Texture albedo{GL_TEXTURE_2D};
    gl::Texture material{GL_TEXTURE_2D};
    gl::Texture depth{GL_TEXTURE_2D};
    gl::Framebuffer framebuffer;
};

class RenderTargets {
public:
    // (Re)allocates for a size; no-op when unchanged. Size must be positive.
    void resize(glm::ivec2 size);
    glm::ivec2 size() const { return size_; }

    const GBuffer& gbuffer() const { return gbuffer_; }
    const gl::Texture& hdr() const { return hdr_; }
    const gl::Texture& ldr() const { return ldr_; }
    GLuint hdrFramebuffer() const { return hdrFramebuffer_.id(); }
    GLuint ldrFramebuffer() const { return ldrFramebuffer_.id(); }
    // hdr with the G-buffer's depth attached: for surfaces drawn forward after lighting.
    GLuint surfaceFramebuffer() const { return surfaceFramebuffer_.id(); }

    // Copies the G-buffer depth and hdr into seabedDepth() and seabedRadiance().
    void copySeabed() const;
    const gl::Texture& seabedDepth() const { return seabedDepth_; }
    const gl::Texture& seabedRadiance() const { return seabedRadiance_; }

private:
    glm::ivec2 size_{0, 0};
    GBuffer gbuffer_;
    gl::Texture hdr_{GL_TEXTURE_2D};
    gl::Texture ldr_{GL_TEXTURE_2D};
    gl::Framebuffer hdrFramebuffer_;
    gl::Framebuffer ldrFramebuffer_;
    gl::Framebuffer surfaceFramebuffer_;
    gl::Texture seabedDepth_{GL_TEXTURE_2D};
    gl::Texture seabedRadiance_{GL_TEXTURE_2D};
};

}  // namespace planet
