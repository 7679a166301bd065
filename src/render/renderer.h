// The frame: a short list of named passes, each in its own debug group and
// profiler scope, with data flowing one way (STYLE habit 6).
//
//   pass        reads                         writes
//   atmosphere tables  scene.atmosphere       the tables, only while they are rebuilt (a chunk a frame)
//   terrain     frame uniforms, terrain, grid G-buffer (normal, albedo, material, depth)
//   atmosphere  G-buffer, atmosphere tables   HDR radiance: surface light, aerial perspective, sky, sun
//                                             (render/lighting.frag, a post-process over the G-buffer)
//   ocean       seabed copies, waves, tables  HDR radiance and depth where the sea is (src/ocean), when
//                                             terrain.ocean is on; the water body first when the camera is under it
//   tonemap     HDR radiance, exposure        LDR (display-ready sRGB)
//
//   ui          LDR                           the window (explorer only: blit + panels)
//
// `planet render` reads HDR or LDR back instead of presenting. A later issue adds the
// clouds between ocean and tonemap.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "atmosphere/atmosphere.h"
#include "scene/camera.h"
#include "gl/handle.h"
#include "gl/program.h"
#include "ocean/ocean_pass.h"
#include "render/fullscreen_pass.h"
#include "render/profiler.h"
#include "render/render_targets.h"
#include "scene/scene.h"
#include "terrain/terrain_pass.h"

namespace planet {

class Renderer {
public:
    // Throws gl::ShaderError. The first render() makes the atmosphere tables.
    Renderer(const std::filesystem::path& shaderRoot, const atmosphere::TableSizes& atmosphereTables);

    // Renders one frame into targets(). `present`, when given, runs last as the
    // "ui" pass (the explorer blits LDR to its window and draws panels there),
    // so the profiler's frame covers everything. A size with a zero side
    // (minimised window) renders nothing and keeps the previous targets.
    void render(const Scene& scene, const Camera& camera, glm::ivec2 size,
                const std::function<void()>& present = {});

    const RenderTargets& targets() const { return targets_; }
    const atmosphere::Atmosphere& atmosphere() const { return atmosphere_; }
    Profiler& profiler() { return profiler_; }

    // Hot reload: rebuilds programs whose files changed. Broken edits keep the
    // last good program; shaderErrors() then lists the messages (empty when all is well).
    bool reloadShaders(bool force = false);
    std::vector<std::string> shaderErrors();

private:
    std::vector<gl::HotProgram*> programs();

    gl::ShaderSources sources_;
    atmosphere::Atmosphere atmosphere_;
    TerrainPass terrain_;
    FullscreenPass lighting4D_;    // the atmosphere pass with Bruneton's 4D table
    FullscreenPass lightingElek_;  // ... with Elek's 3D table (ELEK_TABLE 1)
    OceanPass ocean_;
    FullscreenPass tonemap_;
    gl::Buffer frameUniforms_;
    gl::VertexArray emptyVertexArray_;
    RenderTargets targets_;
    Profiler profiler_;
};

}  // namespace planet
