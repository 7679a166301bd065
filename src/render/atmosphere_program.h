// A program that includes shaders/atmosphere/interface.glsl, in the variant the frame renders
// with (AtmosphereVariant): ELEK_TABLE 0 (Bruneton's 4D table) or 1 (Elek's 3D table; preset
// atmosphere.elek_3d_table), for the sky passes LIGHT_SHAFTS_TERRAIN 0 or 1 (preset
// terrain.light_shafts with terrain.shadows), CLOUD_FAR_FIELD_ONLY 0 or 1 (every footprint
// the frame sees the clouds with is the far field's: src/clouds/cloud_block.h,
// seenInFarFieldOnly), CLOUDS_OFF 0 or 1 (no cloud layer this frame: the cloud block's
// `enabled` 0, shaders/clouds/cloud_density.glsl), and for the sky passes' pixels CAMERA_IN_AIR and
// NO_SUN_DISC 0 or 1 (render/sky_air.glsl: the space's and the disc's code left out where the CPU
// knows they give nothing; at `ground` the reconstruction's still program went from 24 to 12 ms
// on llvmpipe, docs/PERFORMANCE.md, twenty-sixth). Programs rather than run-time branches: software renderers execute both
// sides of even a uniform branch, and a GPU is spared the registers of the unused one (the
// light shafts' code, its loops at no turns, doubled the sky pass on llvmpipe:
// docs/PERFORMANCE.md, 2026-12-03). The default variant (4D table, no shafts, the clouds' volume
// read) is built at once, the others the first time they are asked for (a pause while they
// compile, once: the explorer climbing into the clouds' far field). A pass may name
// modes besides (the constructor's `modes`), built the same way.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "atmosphere/tables.h"
#include "atmosphere/uniforms.h"
#include "gl/program.h"

namespace planet {

// What the CPU knows of the whole frame that a program reading the atmosphere is built for.
struct AtmosphereVariant {
    bool elekTable = false;      // ELEK_TABLE
    bool lightShafts = false;    // LIGHT_SHAFTS_TERRAIN (the sky passes)
    bool cloudFarField = false;  // CLOUD_FAR_FIELD_ONLY (shaders/clouds/cloud_density.glsl)
    bool cloudsOff = false;      // CLOUDS_OFF (shaders/clouds/cloud_density.glsl)
    // What a sky pass's pixels see (render/sky_air.glsl; Renderer::drawSkyPasses): the camera a
    // kilometre or more under the air's top, so that no ray misses the air (CAMERA_IN_AIR), and
    // pixels off the sun's disc's rectangle on screen (NO_SUN_DISC).
    bool cameraInAir = false;
    bool noSunDisc = false;
};

class AtmosphereProgram {
public:
    // `sources` is the frame's; the atmosphere's table sizes and the variant's #defines are added here.
    // `modes`: #defines a pass may also be built with, one at a time, for what the CPU knows of the
    // whole frame (the camera under the sea, a still frame, the sea a flat mirror): get()'s `mode`
    // k > 0 adds `#define modes[k - 1] 1`, a program rather than a branch for the same reason.
    AtmosphereProgram(const gl::ShaderSources& sources, const atmosphere::TableSizes& sizes, gl::ProgramDesc desc,
                      std::vector<std::string> modes = {})
        : sources_(sources), sizes_(sizes), desc_(std::move(desc)), modes_(std::move(modes)),
          variants_(kVariants * (modes_.size() + 1)) {
        variants_[0].emplace(sourcesOf(0), desc_);
    }

    gl::HotProgram& get(const AtmosphereVariant& v, int mode = 0) {
        const int index = (v.elekTable ? 1 : 0) + (v.lightShafts ? 2 : 0) + (v.cloudFarField ? 4 : 0) + (v.cloudsOff ? 8 : 0) +
                          (v.cameraInAir ? 16 : 0) + (v.noSunDisc ? 32 : 0) + kVariants * mode;
        if (!variants_.at(static_cast<std::size_t>(index))) {
            gl::ProgramDesc d = desc_;
            if (mode > 0) d.name += " (" + modes_[static_cast<std::size_t>(mode - 1)] + ")";
            if (v.elekTable) d.name += " (Elek 3D table)";
            if (v.lightShafts) d.name += " (light shafts)";
            if (v.cloudFarField) d.name += " (clouds' far field)";
            if (v.cloudsOff) d.name += " (no clouds)";
            if (v.cameraInAir) d.name += " (camera in the air)";
            if (v.noSunDisc) d.name += " (no sun disc)";
            variants_[static_cast<std::size_t>(index)].emplace(sourcesOf(index), d);
        }
        return *variants_[static_cast<std::size_t>(index)];
    }
    // Other table sizes (the explorer's tables refined to their target): the programs take them
    // at their next rebuild (reloadIfChanged(true) on built()), the variants not built yet when
    // they are first asked for.
    void setTableSizes(const atmosphere::TableSizes& sizes) {
        sizes_ = sizes;
        for (std::size_t i = 0; i < variants_.size(); ++i)
            if (variants_[i]) variants_[i]->setSources(sourcesOf(static_cast<int>(i)));
    }
    // The programs built so far, for hot reload.
    std::vector<gl::HotProgram*> built() {
        std::vector<gl::HotProgram*> p;
        for (std::optional<gl::HotProgram>& v : variants_)
            if (v) p.push_back(&*v);
        return p;
    }

private:
    // bit 0: ELEK_TABLE, bit 1: LIGHT_SHAFTS_TERRAIN, bit 2: CLOUD_FAR_FIELD_ONLY, bit 3: CLOUDS_OFF,
    // bit 4: CAMERA_IN_AIR, bit 5: NO_SUN_DISC; then the mode
    static constexpr int kVariants = 64;

    gl::ShaderSources sourcesOf(int index) const {
        const int mode = index / kVariants;
        const auto flag = [index](int bit) { return (index & bit) ? "1\n" : "0\n"; };
        return {sources_.root, sources_.preamble + atmosphere::atmosphereShaderDefines(sizes_) + "#define ELEK_TABLE " +
                                   flag(1) + "#define LIGHT_SHAFTS_TERRAIN " + flag(2) + "#define CLOUD_FAR_FIELD_ONLY " +
                                   flag(4) + "#define CLOUDS_OFF " + flag(8) + "#define CAMERA_IN_AIR " + flag(16) +
                                   "#define NO_SUN_DISC " + flag(32) +
                                   (mode > 0 ? "#define " + modes_[static_cast<std::size_t>(mode - 1)] + " 1\n" : "")};
    }

    gl::ShaderSources sources_;
    atmosphere::TableSizes sizes_;
    gl::ProgramDesc desc_;
    std::vector<std::string> modes_;
    std::vector<std::optional<gl::HotProgram>> variants_;
};

}  // namespace planet
