#include "render/render_targets.h"

#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include "render/bindings.h"

namespace planet {

namespace {

// The sampled passes' spacings, from the very file the shaders include.
#include "shaders/render/sample_spacing.glsl"

constexpr GLsizeiptr kRefineListHeaderBytes = 16;  // render/pixel_list.glsl: groups x, y, z, count
// render/terrain_shadow_list.glsl: groups x, y, z, count, capacity, 3 unused; a uvec4 an entry.
constexpr GLsizeiptr kTerrainShadowListHeaderBytes = 32;
constexpr GLsizeiptr kTerrainShadowListEntryBytes = 16;
// Every pixel of the frame (16 bytes a pixel): at a low sun over water among mountains most of
// the sea may be listed (a fifth of the frame in the flooded valley's test), and with the
// samples off (OCEAN_TERRAIN_SHADOW_FROM_SAMPLES 0) all of it.
GLuint terrainShadowListCapacity(glm::ivec2 size) { return GLuint(std::max(1, size.x * size.y)); }

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

void copyImage(const gl::Texture& from, const gl::Texture& to, glm::ivec2 size) {
    glCopyImageSubData(from.id(), GL_TEXTURE_2D, 0, 0, 0, 0, to.id(), GL_TEXTURE_2D, 0, 0, 0, 0, size.x, size.y, 1);
}

gl::Framebuffer makeFramebuffer(std::initializer_list<const gl::Texture*> colours, const gl::Texture* depth,
                                const char* name, const gl::Texture* stencil = nullptr) {
    gl::Framebuffer fb;
    GLenum buffers[8];
    GLsizei count = 0;
    for (const gl::Texture* c : colours) {
        glNamedFramebufferTexture(fb.id(), GL_COLOR_ATTACHMENT0 + count, c->id(), 0);
        buffers[count] = GL_COLOR_ATTACHMENT0 + count;
        ++count;
    }
    // The G-buffer's depth has a stencil beside it (DEPTH32F_STENCIL8): attached whole.
    if (depth) glNamedFramebufferTexture(fb.id(), GL_DEPTH_STENCIL_ATTACHMENT, depth->id(), 0);
    if (stencil) glNamedFramebufferTexture(fb.id(), GL_STENCIL_ATTACHMENT, stencil->id(), 0);
    glNamedFramebufferDrawBuffers(fb.id(), count, buffers);
    fb.label(name);
    checkComplete(fb, name);
    return fb;
}

}  // namespace

int terrainShadowSampleSpacing(int frameHeight) { return terrainShadowSpacing(frameHeight); }

bool RenderTargets::resize(glm::ivec2 size) {
    if (size == size_) return false;
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
    // With a stencil: 1 where the ocean's mesh left the sea as the nearest surface (its light runs there).
    gbuffer_.depth = makeTexture(GL_DEPTH32F_STENCIL8, size, "gbuffer.depth + sea stencil");
    gbuffer_.framebuffer = makeFramebuffer({&gbuffer_.normal, &gbuffer_.albedo, &gbuffer_.material},
                                           &gbuffer_.depth, "gbuffer");
    for (int i = 0; i < 3; ++i)
        meshSurface_[i] = makeTexture(GL_RGBA32F, size, ("mesh surface " + std::to_string(i)).c_str());
    terrainMeshFramebuffer_ = makeFramebuffer({&meshSurface_[0], &meshSurface_[1], &meshSurface_[2]}, &gbuffer_.depth,
                                              "terrain mesh surface + depth, stencil");
    surfaceRadiance_ = makeTexture(GL_RGBA16F, size, "surface radiance");
    surfaceDistance_ = makeTexture(GL_R32F, size, "surface distance");
    surfaceStencil_ = makeTexture(GL_STENCIL_INDEX8, size, "surface stencil");
    surfaceFramebuffer_ = makeFramebuffer({&surfaceRadiance_, &surfaceDistance_}, nullptr, "surface radiance + stencil",
                                          &surfaceStencil_);
    // Full floats: the terrain reflection pass searches along the reflected ray from the sea's
    // distance, where half floats would move its vanishing point by up to a pixel.
    seaReflection_ = makeTexture(GL_RGBA32F, size, "sea reflection");
    seaSkyReflection_ = makeTexture(GL_RGBA32F, size, "sea sky reflection");
    seaSurfaceFramebuffer_ = makeFramebuffer({&surfaceDistance_, &meshSurface_[0], &meshSurface_[1], &meshSurface_[2]},
                                             &gbuffer_.depth, "surface distance + sea surface + depth, stencil");
    oceanFramebuffer_ = makeFramebuffer({&surfaceRadiance_, &seaReflection_, &seaSkyReflection_}, &gbuffer_.depth,
                                        "surface radiance + sea reflection + depth, stencil");
    surfaceRadianceFramebuffer_ = makeFramebuffer({&surfaceRadiance_}, nullptr, "surface radiance");
    seaReflectionSamples_.size = (size + SEA_REFLECTION_SPACING - 1) / SEA_REFLECTION_SPACING;
    seaReflectionSamples_.change = makeTexture(GL_RGBA16F, seaReflectionSamples_.size, "sea reflection samples");
    seaReflectionSamples_.framebuffer =
        makeFramebuffer({&seaReflectionSamples_.change}, nullptr, "sea reflection samples");
    hdr_ = makeTexture(GL_RGBA16F, size, "hdr");
    skyMedium_ = makeTexture(GL_RGBA32UI, size, "sky T, S");
    hdrFramebuffer_ = makeFramebuffer({&hdr_, &skyMedium_}, nullptr, "hdr + sky T, S");
    hdrStencilFramebuffer_ = makeFramebuffer({&hdr_, &skyMedium_}, &gbuffer_.depth, "hdr + sky T, S, stencil");
    terrainShadowSamples_.spacing = terrainShadowSpacing(size.y);
    terrainShadowSamples_.size = (size + terrainShadowSamples_.spacing - 1) / terrainShadowSamples_.spacing;
    terrainShadowSamples_.visibility = makeTexture(GL_RG32F, terrainShadowSamples_.size, "terrain shadow samples");
    terrainShadowSamples_.framebuffer =
        makeFramebuffer({&terrainShadowSamples_.visibility}, nullptr, "terrain shadow samples");
    sparseSky_.size = (size + kSparseBlock - 1) / kSparseBlock;
    sparseSky_.inscatter = makeTexture(GL_RGBA16F, sparseSky_.size, "sparse sky inscatter");
    sparseSky_.transmittance = makeTexture(GL_RGBA16F, sparseSky_.size, "sparse sky transmittance");
    sparseSky_.distanceError = makeTexture(GL_RG32F, sparseSky_.size, "sparse sky distance, history error");
    sparseSky_.stencil = makeTexture(GL_STENCIL_INDEX8, sparseSky_.size, "sparse sky stencil");
    sparseSky_.framebuffer = makeFramebuffer({&sparseSky_.inscatter, &sparseSky_.transmittance, &sparseSky_.distanceError},
                                             nullptr, "sparse sky T, S, distance, history error, stencil",
                                             &sparseSky_.stencil);
    skyRefineList_ = makePixelList("sky refine list");
    seaReflectionList_ = makePixelList("sea reflection list");
    terrainShadowList_ = gl::Buffer();
    glNamedBufferStorage(terrainShadowList_.id(),
                         kTerrainShadowListHeaderBytes + kTerrainShadowListEntryBytes * GLsizeiptr(terrainShadowListCapacity(size_)),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
    terrainShadowList_.label("sea terrain shadow list");
    clearTerrainShadowList();
    terrainReflectionList_ = makePixelList("terrain reflection list");
    terrainShadowSampleMarches_ = makePixelList("terrain shadow sample marches list");
    landOnScreen_ = gl::Buffer();
    glNamedBufferStorage(landOnScreen_.id(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
    landOnScreen_.label("land on screen");
    clearLandOnScreen();
    ldr_ = makeTexture(GL_RGBA8, size, "ldr");
    ldrFramebuffer_ = makeFramebuffer({&ldr_}, nullptr, "ldr");
    seabedDepth_ = makeTexture(GL_DEPTH32F_STENCIL8, size, "seabed depth");  // the G-buffer's format (a copy)
    // Read between texels by the sea's screen-space reflections (its depth is affine on screen).
    glTextureParameteri(seabedDepth_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(seabedDepth_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    seabedRadiance_ = makeTexture(GL_RGBA16F, size, "seabed radiance");
    history_.radiance = makeTexture(GL_RGBA16F, size, "history.radiance");
    // Read between texels by the anti-aliasing's reprojection.
    glTextureParameteri(history_.radiance.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(history_.radiance.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    antialiased_ = makeTexture(GL_RGBA16F, size, "antialiased");
    antialiasFramebuffer_ = makeFramebuffer({&antialiased_}, nullptr, "antialiased");
    history_.surfaceDistance = makeTexture(GL_R32F, size, "history.surface distance");
    history_.skyMedium = makeTexture(GL_RGBA32UI, size, "history.sky T, S");
    return true;
}

void RenderTargets::clearSurface() const {
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(surfaceFramebuffer_.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(surfaceFramebuffer_.id(), GL_COLOR, 1, zero);
    const GLint clear = 0;
    glClearNamedFramebufferiv(surfaceFramebuffer_.id(), GL_STENCIL, 0, &clear);
}

void RenderTargets::clearSeaReflection() const {
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(oceanFramebuffer_.id(), GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(oceanFramebuffer_.id(), GL_COLOR, 2, zero);
}

void RenderTargets::clearSeaStencil() const {
    const GLint clear = 0;
    glClearNamedFramebufferiv(seaSurfaceFramebuffer_.id(), GL_STENCIL, 0, &clear);
}

void RenderTargets::bindMeshSurface() const {
    for (std::size_t i = 0; i < meshSurface_.size(); ++i)
        glBindTextureUnit(binding::UNIT_MESH_SURFACE_0 + static_cast<GLuint>(i), meshSurface_[i].id());
}

void RenderTargets::copySeabed() const {
    copyImage(gbuffer_.depth, seabedDepth_, size_);
    copyImage(surfaceRadiance_, seabedRadiance_, size_);
}

void RenderTargets::keepAntialiased() const { copyImage(antialiased_, hdr_, size_); }

gl::Buffer RenderTargets::makePixelList(const char* label) const {
    gl::Buffer list;
    glNamedBufferStorage(list.id(), kRefineListHeaderBytes + GLsizeiptr(sizeof(GLuint)) * size_.x * size_.y, nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    list.label(label);
    clearPixelList(list);
    return list;
}

void RenderTargets::clearTerrainShadowList() const {
    const GLuint header[8] = {0, 1, 1, 0, terrainShadowListCapacity(size_), 0, 0, 0};
    glNamedBufferSubData(terrainShadowList_.id(), 0, sizeof header, header);
}

glm::uvec2 RenderTargets::terrainShadowListCount() const {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint header[8] = {};
    glGetNamedBufferSubData(terrainShadowList_.id(), 0, sizeof header, header);
    return {header[3], header[4]};
}

void RenderTargets::clearLandOnScreen() const {
    const GLuint none = 0;
    glNamedBufferSubData(landOnScreen_.id(), 0, sizeof none, &none);
}

bool RenderTargets::readLandOnScreen() const {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint value = 0;
    glGetNamedBufferSubData(landOnScreen_.id(), 0, sizeof value, &value);
    return value != 0;
}

void RenderTargets::clearPixelList(const gl::Buffer& list) {
    const GLuint header[4] = {0, 1, 1, 0};  // groups x, y, z; count (render/pixel_list.glsl)
    glNamedBufferSubData(list.id(), 0, sizeof header, header);
}

std::vector<glm::ivec2> RenderTargets::readPixelList(const gl::Buffer& list) const {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint header[4] = {0, 0, 0, 0};
    glGetNamedBufferSubData(list.id(), 0, sizeof header, header);
    std::vector<GLuint> packed(std::min<std::size_t>(header[3], std::size_t(size_.x) * std::size_t(size_.y)));
    if (!packed.empty())
        glGetNamedBufferSubData(list.id(), kRefineListHeaderBytes, GLsizeiptr(packed.size() * sizeof(GLuint)),
                                packed.data());
    std::vector<glm::ivec2> pixels;
    pixels.reserve(packed.size());
    for (GLuint p : packed) pixels.emplace_back(int(p & 0xffffu), int((p >> 16) & 0x3fffu));  // (flags above)
    return pixels;
}

void RenderTargets::keepHistory() const {
    copyImage(hdr_, history_.radiance, size_);
    copyImage(surfaceDistance_, history_.surfaceDistance, size_);
    copyImage(skyMedium_, history_.skyMedium, size_);
}

}  // namespace planet
