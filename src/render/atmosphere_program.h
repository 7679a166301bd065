// A program that includes shaders/atmosphere/interface.glsl, in the variant the scene renders
// with: ELEK_TABLE 0 (Bruneton's 4D table) or 1 (Elek's 3D table; preset
// atmosphere.elek_3d_table), and for the sky passes LIGHT_SHAFTS_TERRAIN 0 or 1 (preset
// terrain.light_shafts with terrain.shadows). Programs rather than run-time branches: software
// renderers execute both sides of even a uniform branch, and a GPU is spared the registers
// of the unused one (the light shafts' code, its loops at no turns, doubled the sky pass on
// llvmpipe: docs/PERFORMANCE.md, 2026-12-03). The default variant (4D table, no shafts) is
// built at once, the others the first time they are asked for. A pass may name modes besides
// (the constructor's `modes`), built the same way.
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

class AtmosphereProgram {
public:
    // `sources` is the frame's; the atmosphere's table sizes and the variant's #defines are added here.
    // `modes`: #defines a pass may also be built with, one at a time, for what the CPU knows of the
    // whole frame (the camera under the sea, a still frame, the sea a flat mirror): get()'s `mode`
    // k > 0 adds `#define modes[k - 1] 1`, a program rather than a branch for the same reason.
    AtmosphereProgram(const gl::ShaderSources& sources, const atmosphere::TableSizes& sizes, gl::ProgramDesc desc,
                      std::vector<std::string> modes = {})
        : sources_(sources), sizes_(sizes), desc_(std::move(desc)), modes_(std::move(modes)),
          variants_(kTableAndShaftVariants * (modes_.size() + 1)) {
        variants_[0].emplace(variant(0), desc_);
    }

    gl::HotProgram& get(bool elekTable, bool lightShafts = false, int mode = 0) {
        const int index = (elekTable ? 1 : 0) + (lightShafts ? 2 : 0) + kTableAndShaftVariants * mode;
        if (!variants_.at(static_cast<std::size_t>(index))) {
            gl::ProgramDesc d = desc_;
            if (mode > 0) d.name += " (" + modes_[static_cast<std::size_t>(mode - 1)] + ")";
            if (elekTable) d.name += " (Elek 3D table)";
            if (lightShafts) d.name += " (light shafts)";
            variants_[static_cast<std::size_t>(index)].emplace(variant(index), d);
        }
        return *variants_[static_cast<std::size_t>(index)];
    }
    // Other table sizes (the explorer's tables refined to their target): the programs take them
    // at their next rebuild (reloadIfChanged(true) on built()), the variants not built yet when
    // they are first asked for.
    void setTableSizes(const atmosphere::TableSizes& sizes) {
        sizes_ = sizes;
        for (std::size_t i = 0; i < variants_.size(); ++i)
            if (variants_[i]) variants_[i]->setSources(variant(static_cast<int>(i)));
    }
    // The programs built so far, for hot reload.
    std::vector<gl::HotProgram*> built() {
        std::vector<gl::HotProgram*> p;
        for (std::optional<gl::HotProgram>& v : variants_)
            if (v) p.push_back(&*v);
        return p;
    }

private:
    static constexpr int kTableAndShaftVariants = 4;  // bit 0: ELEK_TABLE, bit 1: LIGHT_SHAFTS_TERRAIN; then the mode

    gl::ShaderSources variant(int index) const {
        const int mode = index / kTableAndShaftVariants;
        return {sources_.root, sources_.preamble + atmosphere::atmosphereShaderDefines(sizes_) + "#define ELEK_TABLE " +
                                   ((index & 1) ? "1" : "0") + "\n#define LIGHT_SHAFTS_TERRAIN " +
                                   ((index & 2) ? "1" : "0") + "\n" +
                                   (mode > 0 ? "#define " + modes_[static_cast<std::size_t>(mode - 1)] + " 1\n" : "")};
    }

    gl::ShaderSources sources_;
    atmosphere::TableSizes sizes_;
    gl::ProgramDesc desc_;
    std::vector<std::string> modes_;
    std::vector<std::optional<gl::HotProgram>> variants_;
};

}  // namespace planet
