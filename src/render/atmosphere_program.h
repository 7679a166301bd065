// A program that includes shaders/atmosphere/interface.glsl, in the variant for the table
// the scene renders with: ELEK_TABLE 0 (Bruneton's 4D table) or 1 (Elek's 3D table;
// preset atmosphere.elek_3d_table). Two programs rather than a run-time branch: software
// renderers execute both sides of even a uniform branch, and a GPU is spared the registers
// of the unused one. The Elek variant is built the first time it is asked for.
#pragma once

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
    // `sources` is the frame's; the atmosphere's table sizes and ELEK_TABLE are added here.
    AtmosphereProgram(const gl::ShaderSources& sources, const atmosphere::TableSizes& sizes, gl::ProgramDesc desc)
        : sources_(sources), sizes_(sizes), desc_(std::move(desc)), bruneton4D_(variant(false), desc_) {}

    gl::HotProgram& get(bool elekTable) {
        if (!elekTable) return bruneton4D_;
        if (!elek3D_) {
            gl::ProgramDesc d = desc_;
            d.name += " (Elek 3D table)";
            elek3D_.emplace(variant(true), d);
        }
        return *elek3D_;
    }
    // Other table sizes (the explorer's tables refined to their target): the programs take them
    // at their next rebuild (reloadIfChanged(true) on built()), the variant not built yet when
    // it is first asked for.
    void setTableSizes(const atmosphere::TableSizes& sizes) {
        sizes_ = sizes;
        bruneton4D_.setSources(variant(false));
        if (elek3D_) elek3D_->setSources(variant(true));
    }
    // The programs built so far, for hot reload.
    std::vector<gl::HotProgram*> built() {
        std::vector<gl::HotProgram*> p{&bruneton4D_};
        if (elek3D_) p.push_back(&*elek3D_);
        return p;
    }

private:
    gl::ShaderSources variant(bool elek) const {
        return {sources_.root, sources_.preamble + atmosphere::atmosphereShaderDefines(sizes_) +
                                   "#define ELEK_TABLE " + (elek ? "1" : "0") + "\n"};
    }

    gl::ShaderSources sources_;
    atmosphere::TableSizes sizes_;
    gl::ProgramDesc desc_;
    gl::HotProgram bruneton4D_;
    std::optional<gl::HotProgram> elek3D_;
};

}  // namespace planet
