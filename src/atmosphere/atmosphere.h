// The atmosphere at run time: the tables in use, the parameters they were
// made for (uniform block, binding 1), and a rebuild in progress.
//
// The first update() makes tables before returning: from the disk cache
// (table_cache.h) when a valid entry exists, else precomputed on the GPU with
// progress in the log and then cached. Rebuilds while tuning are not cached.
// Later, when the scene's atmosphere changes, update() runs one chunk of a
// rebuild per call -- the explorer calls it once a frame -- while the old
// tables and their parameters stay in use, and swaps when the rebuild is done.
// So tuning never freezes the window and never shows half-built tables.
//
// The tables include Elek's 3D table (elek_table.glsl), built as the last step
// of every precomputation. Which parametrization the frame uses is the preset's
// atmosphere.elek_3d_table, a render-time choice of program variant
// (render/atmosphere_program.h); it never rebuilds.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "atmosphere/precompute_gpu.h"
#include "atmosphere/uniforms.h"
#include "scene/scene.h"

namespace planet::atmosphere {

class Atmosphere {
public:
    Atmosphere(const std::filesystem::path& shaderRoot, const TableSizes& sizes);

    // Brings the tables towards the scene's atmosphere (see above).
    void update(const Scene& scene);
    // Binds the tables at their units (UNIT_TRANSMITTANCE ... UNIT_ELEK_SINGLE_MIE in
    // shaders/common/bindings.glsl) and the parameter block at BLOCK_ATMOSPHERE.
    void bind() const;
    // Whether there are tables yet (the first update() makes them).
    bool ready() const { return tables_.has_value(); }

    bool rebuilding() const { return job_.has_value(); }
    double rebuildProgress() const { return job_ ? job_->progress() : 1.0; }
    const TableSizes& sizes() const { return precompute_.sizes(); }
    const GpuTables& tables() const { return *tables_; }
    // Whether the uniform block asks for Elek's 3D table (the scene's atmosphere.elek_3d_table).
    bool usesElekTable() const { return flags_.elek3dTable; }

private:
    struct Target {
        AtmosphereUniforms uniforms;
        int orders = 0;
        bool operator==(const Target& o) const;
    };
    static Target targetFor(const Scene& scene);
    GpuTables loadOrCompute(const AtmosphereParameters& parameters, int orders);
    void finishJob();
    void writeUniforms();  // current_.uniforms with the render-time flags

    std::filesystem::path shaderRoot_;  // the model's sources are part of the cache key
    GpuPrecompute precompute_;
    std::optional<GpuTables> tables_;
    Target current_{};                 // what tables_ hold
    std::optional<GpuPrecomputeJob> job_;
    Target pending_{};                 // what job_ computes
    struct RenderFlags {  // switches applied when rendering; they do not change the tables
        bool elek3dTable = false;
        bool elekRayleighPhase = false;
        bool operator==(const RenderFlags&) const = default;
    };
    RenderFlags flags_;
    gl::Buffer uniforms_;
};

}  // namespace planet::atmosphere
