// The frame's render targets.
//
//   gbuffer   normal (RGBA16F, world axes), albedo (RGBA8, linear), material
//             (RGBA8: id/255, roughness), depth (DEPTH32F, reversed-Z) with a stencil beside it:
//             where the terrain's mesh is the nearest surface (TerrainPass::kPlainStencil and
//             kDetailedStencil: its material's programs run there), then, cleared by the ocean
//             pass, where the sea's is (OceanPass::kSeaStencil: its light runs there)
//   surface   surfaceRadiance (RGBA16F): the radiance leaving the surface point towards the
//             camera, no air in it; surfaceDistance (R32F): metres along the view ray to that
//             point, 0 where there is none. Written by the surface light and the ocean
//             (surfaceFramebuffer, with a stencil: 1 where the surface light found the sea
//             floor's dark depths or no ground, so that its lighting program skips them before it runs).
//   seabed    copies of the G-buffer depth and of the surface radiance taken before the
//             ocean, which reads them while drawing over them
//   hdr       RGBA16F linear radiance arriving at the camera (what `render --out x.exr` writes),
//             with the sky passes' T and S beside it (skyMedium: RGBA32UI, T, S and the samples
//             in the temporal history as half floats, render/sky_medium.glsl)
//   mesh surface  three RGBA32F: what a mesh's fragments leave where their surface is the
//             nearest, for a pass that shades those pixels once each (terrain/mesh_surface.glsl):
//             the terrain's fragments for its material pass (terrainMeshFramebuffer), then the
//             ocean's for its light (ocean/sea_surface.glsl; seaSurfaceFramebuffer, beside the
//             surface distance)
//   sea reflection  RGBA32F: the sea's reflected ray at each pixel and the weight the clouds'
//             change to its radiance takes there (ocean/sea_light.frag writes it beside the
//             surface radiance: oceanFramebuffer); its samples, RGBA16F at 1 / SEA_REFLECTION_SPACING of the
//             size: that change marched at one pixel of each block (ocean/sea_reflection.frag),
//             added back into the surface radiance by the same file's compose program
//             (surfaceRadianceFramebuffer, additive)
//   terrain shadow  RG32F, 1 / terrainShadowSpacing of the size on each side (rounded up):
//             the terrain's shadow at the corner pixel of each block, on the ground and on the
//             sea's surface in front of it (render/terrain_shadow.frag)
//   sparse    a quarter of the size on each side (rounded up): the reduced-rate march's
//             samples, one pixel of each 4x4 block, with its surface distance and the
//             history's error at each
//             (render/sky_sparse.frag)
//   refine    a buffer: the pixels the temporal reconstruction could not trust, listed
//             (render/sky_temporal.frag lists them, render/sky_refine.comp marches them again
//             at full rate, one invocation each; render/pixel_list.glsl): a 16-byte
//             header (the indirect dispatch's group counts, the count), then a uint per pixel
//   ldr       RGBA8 tone-mapped sRGB bytes (what the window shows and PNGs hold)
//   antialiased  RGBA16F: the temporal anti-aliasing's result, copied back into hdr
//   history   the previous frame's hdr, surface distance and sky T and S, kept for temporal work
//             (FrameUniforms: previousClipFromWorld, cameraFromPrevious, historyValid)
//
// Layout must match shaders/common/gbuffer.glsl. Resized only when the frame size
// changes (which drops the history); a 0x0 size (minimised window) holds no textures.
#pragma once

#include <array>
#include <vector>

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

struct FrameHistory {
    gl::Texture radiance{GL_TEXTURE_2D};         // RGBA16F, the previous frame's hdr
    gl::Texture surfaceDistance{GL_TEXTURE_2D};  // R32F, the previous frame's surface distance
    gl::Texture skyMedium{GL_TEXTURE_2D};        // RGBA32UI, its sky T, S and sample count
};

// The terrain shadow samples' spacing for a frame `frameHeight` pixels high: pixels per side of a
// block (render/sample_spacing.glsl's terrainShadowSpacing: 2, and 4 from 720 rows up).
int terrainShadowSampleSpacing(int frameHeight);

// The terrain shadow's samples (render/terrain_shadow.frag): one pixel of each
// terrainShadowSpacing-square block (render/sample_spacing.glsl), the block's corner.
struct TerrainShadowSamples {
    glm::ivec2 size{0, 0};
    int spacing = 1;  // terrainShadowSpacing(height): pixels per side of a block
    gl::Texture visibility{GL_TEXTURE_2D};  // RG32F: the march's clearance, rad, on the ground (r) and on the
                                            // sea's surface in front of it (g); TERRAIN_SHADOW_NO_SURFACE where none
    gl::Framebuffer framebuffer;
};

// The clouds' change to the sea's reflection at one pixel of each block (ocean/sea_reflection.frag).
struct SeaReflectionSamples {
    glm::ivec2 size{0, 0};
    gl::Texture change{GL_TEXTURE_2D};  // RGBA16F: dL_C, 1 where marched (0 0 0 0 where no sea)
    gl::Framebuffer framebuffer;
};

// The reduced-rate march's samples (a quarter of the frame's size on each side: one pixel of
// each block of kSparseBlock x kSparseBlock, render/sparse_pattern.glsl's SPARSE_BLOCK).
inline constexpr int kSparseBlock = 4;
struct SparseSky {
    glm::ivec2 size{0, 0};
    gl::Texture inscatter{GL_TEXTURE_2D};      // RGBA16F: S, reprojection distance km
    gl::Texture transmittance{GL_TEXTURE_2D};  // RGBA16F: T, the clouds' opacity
    gl::Texture distanceError{GL_TEXTURE_2D};  // RG32F: its surface distance, m; the history's relative error there
    gl::Texture stencil{GL_TEXTURE_2D};        // STENCIL_INDEX8: the blocks whose ray meets no cloud (Renderer::drawSkyMarch)
    gl::Framebuffer framebuffer;
};

class RenderTargets {
public:
    // (Re)allocates for a size; returns true when it did (the history is then empty).
    // Size must be positive.
    bool resize(glm::ivec2 size);
    glm::ivec2 size() const { return size_; }

    const GBuffer& gbuffer() const { return gbuffer_; }
    const gl::Texture& surfaceRadiance() const { return surfaceRadiance_; }
    const gl::Texture& surfaceDistance() const { return surfaceDistance_; }
    // The surface light's stencil (render/surface_marks.frag's marks; tests read it).
    const gl::Texture& surfaceStencil() const { return surfaceStencil_; }
    const gl::Texture& hdr() const { return hdr_; }
    const gl::Texture& ldr() const { return ldr_; }
    const gl::Texture& skyMedium() const { return skyMedium_; }
    const SparseSky& sparseSky() const { return sparseSky_; }
    const TerrainShadowSamples& terrainShadowSamples() const { return terrainShadowSamples_; }
    const gl::Texture& seaReflection() const { return seaReflection_; }
    // The sky the sea reflected where the terrain may be reflected instead, and the sea's
    // distance there (the ocean's; 0 elsewhere): the terrain reflection pass's input.
    const gl::Texture& seaSkyReflection() const { return seaSkyReflection_; }
    const SeaReflectionSamples& seaReflectionSamples() const { return seaReflectionSamples_; }
    const gl::Buffer& skyRefineList() const { return skyRefineList_; }
    // Empties the refine list: no pixel listed, an indirect dispatch of no groups.
    void clearSkyRefineList() const { clearPixelList(skyRefineList_); }
    // The pixels listed for refinement (x, y), read back (a test's or bench's look, it waits).
    std::vector<glm::ivec2> readSkyRefineList() const { return readPixelList(skyRefineList_); }
    // The sea's pixels whose terrain shadow is marched after the ocean pass, with their distances
    // and sun shares (shaders/render/terrain_shadow_list.glsl): as many as the frame has pixels.
    const gl::Buffer& terrainShadowList() const { return terrainShadowList_; }
    void clearTerrainShadowList() const;
    // How many pixels asked to be listed in the last frame (beyond the capacity too), and the capacity.
    glm::uvec2 terrainShadowListCount() const;
    // The sea's pixels that march their own reflection (ocean/sea_reflection.frag), as above.
    const gl::Buffer& seaReflectionList() const { return seaReflectionList_; }
    void clearSeaReflectionList() const { clearPixelList(seaReflectionList_); }
    std::vector<glm::ivec2> readSeaReflectionList() const { return readPixelList(seaReflectionList_); }
    // The sea's pixels that may reflect the terrain (ocean/sea_light.frag lists them), as above.
    const gl::Buffer& terrainReflectionList() const { return terrainReflectionList_; }
    void clearTerrainReflectionList() const { clearPixelList(terrainReflectionList_); }
    std::vector<glm::ivec2> readTerrainReflectionList() const { return readPixelList(terrainReflectionList_); }
    // The terrain shadow's samples marched after the sampling pass, on the ground, the sea or both
    // (render/terrain_shadow_sample_marches.comp; the entries' flags: render/pixel_list.glsl).
    const gl::Buffer& terrainShadowSampleMarches() const { return terrainShadowSampleMarches_; }
    void clearTerrainShadowSampleMarches() const { clearPixelList(terrainShadowSampleMarches_); }
    std::vector<glm::ivec2> readTerrainShadowSampleMarches() const { return readPixelList(terrainShadowSampleMarches_); }
    // Whether any ground above the sea is on screen (one uint, render/land_on_screen.glsl).
    const gl::Buffer& landOnScreen() const { return landOnScreen_; }
    void clearLandOnScreen() const;
    bool readLandOnScreen() const;  // a test's look (it waits)
    const FrameHistory& history() const { return history_; }
    // hdr and skyMedium (the sky passes').
    GLuint hdrFramebuffer() const { return hdrFramebuffer_.id(); }
    // The same with the G-buffer's depth and stencil (the sky's reconstruction split by a stencil bit).
    GLuint hdrStencilFramebuffer() const { return hdrStencilFramebuffer_.id(); }
    GLuint ldrFramebuffer() const { return ldrFramebuffer_.id(); }
    // surface radiance + distance with the G-buffer's depth attached.
    GLuint surfaceFramebuffer() const { return surfaceFramebuffer_.id(); }
    // The ocean's mesh's targets: the surface distance and the sea surface's G-buffer, with the
    // G-buffer's depth and its stencil (clearSeaStencil() sets it to 0).
    GLuint seaSurfaceFramebuffer() const { return seaSurfaceFramebuffer_.id(); }
    void clearSeaStencil() const;
    const std::array<gl::Texture, 3>& meshSurface() const { return meshSurface_; }
    // Binds them at UNIT_MESH_SURFACE_0.. for the pass that reads what a mesh left.
    void bindMeshSurface() const;
    // The terrain's mesh's targets: the mesh surface, with the G-buffer's depth and its stencil
    // (1 where the mesh drew with the plain material, 2 with the detail's; the G-buffer's
    // framebuffer has the same attached, for the material pass's test).
    GLuint terrainMeshFramebuffer() const { return terrainMeshFramebuffer_.id(); }
    // The sea's light's: the surface radiance, the sea reflection and sea sky reflection beside
    // it (clearSeaReflection() empties both), the G-buffer's depth and stencil (its test).
    GLuint oceanFramebuffer() const { return oceanFramebuffer_.id(); }
    void clearSeaReflection() const;
    // The surface radiance alone (passes that add to it).
    GLuint surfaceRadianceFramebuffer() const { return surfaceRadianceFramebuffer_.id(); }

    // Clears the surface targets to "no surface" (radiance 0, distance 0).
    void clearSurface() const;
    // Copies the G-buffer depth and the surface radiance into seabedDepth() and seabedRadiance().
    void copySeabed() const;
    const gl::Texture& seabedDepth() const { return seabedDepth_; }
    const gl::Texture& seabedRadiance() const { return seabedRadiance_; }
    // Copies this frame's hdr, surface distance and sky T and S into history().
    void keepHistory() const;
    // The temporal anti-aliasing's result (render/antialias.frag) and its framebuffer;
    // keepAntialiased() copies it into hdr(), which the tone mapping and the history read.
    GLuint antialiasFramebuffer() const { return antialiasFramebuffer_.id(); }
    void keepAntialiased() const;

private:
    // A list of pixels (render/pixel_list.glsl) for a frame of this size.
    gl::Buffer makePixelList(const char* label) const;
    static void clearPixelList(const gl::Buffer& list);
    std::vector<glm::ivec2> readPixelList(const gl::Buffer& list) const;

    glm::ivec2 size_{0, 0};
    GBuffer gbuffer_;
    gl::Texture surfaceRadiance_{GL_TEXTURE_2D};
    gl::Texture surfaceDistance_{GL_TEXTURE_2D};
    gl::Texture hdr_{GL_TEXTURE_2D};
    gl::Texture ldr_{GL_TEXTURE_2D};
    gl::Texture skyMedium_{GL_TEXTURE_2D};
    SparseSky sparseSky_;
    TerrainShadowSamples terrainShadowSamples_;
    gl::Texture seaReflection_{GL_TEXTURE_2D};
    gl::Texture seaSkyReflection_{GL_TEXTURE_2D};
    SeaReflectionSamples seaReflectionSamples_;
    std::array<gl::Texture, 3> meshSurface_{gl::Texture(GL_TEXTURE_2D), gl::Texture(GL_TEXTURE_2D),
                                            gl::Texture(GL_TEXTURE_2D)};
    gl::Framebuffer terrainMeshFramebuffer_;
    gl::Framebuffer seaSurfaceFramebuffer_;
    gl::Framebuffer oceanFramebuffer_;
    gl::Framebuffer surfaceRadianceFramebuffer_;
    gl::Buffer skyRefineList_;
    gl::Buffer seaReflectionList_;
    gl::Buffer terrainShadowList_;
    gl::Buffer terrainReflectionList_;
    gl::Buffer landOnScreen_;
    gl::Buffer terrainShadowSampleMarches_;
    gl::Texture surfaceStencil_{GL_TEXTURE_2D};
    gl::Framebuffer surfaceFramebuffer_;
    gl::Framebuffer hdrFramebuffer_;
    gl::Framebuffer hdrStencilFramebuffer_;
    gl::Framebuffer ldrFramebuffer_;
    gl::Texture seabedDepth_{GL_TEXTURE_2D};
    gl::Texture seabedRadiance_{GL_TEXTURE_2D};
    FrameHistory history_;
    gl::Texture antialiased_{GL_TEXTURE_2D};
    gl::Framebuffer antialiasFramebuffer_;
};

}  // namespace planet
