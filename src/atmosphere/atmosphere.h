// The atmosphere at run time: the tables in use, the parameters they were
// made for (uniform block, binding 1), and a rebuild in progress.
//
// The first update() makes tables before returning: from the disk cache
// (table_cache.h) when a valid entry exists, else precomputed on the GPU with
// progress in the log and then cached. Later, when the scene's atmosphere
// changes, update() runs a rebuild a chunk at a time -- the explorer calls it
// once a frame; one chunk a call, more while they take under a quarter of the
// frame's period (a software renderer's frames take seconds) -- while the old
// tables and their parameters stay in use, and swaps when the rebuild is done.
// So tuning never freezes the window and never shows half-built tables.
// Rebuilds while tuning are not cached.
//
// A window that must not wait (the explorer) plans its start (TablePlan): when
// the cache does not hold the target tables, the first update() makes cheaper
// starter tables at once (fewer texels, fewer scattering orders: what fits the
// first frame), and the following updates refine them to the target sizes with
// the same chunked rebuild, progress in the log, and cache the result, so that
// the next start loads the target at once. sizes() follows the tables in use:
// the programs that read them are built with those sizes as #defines, and the
// renderer rebuilds them when they change (Renderer::matchAtmosphereTables).
// The commands (render, sky-probe, bench) plan the target alone: tables at
// their sizes before the first frame, as before.
//
// The tables include Elek's 3D table (elek_table.glsl), built as the last step
// of every precomputation. Which parametrization the frame uses is the preset's
// atmosphere.elek_3d_table, a render-time choice of program variant
// (render/atmosphere_program.h); it never rebuilds.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>

#include "atmosphere/precompute_gpu.h"
#include "atmosphere/uniforms.h"
#include "scene/scene.h"

namespace planet::atmosphere {

// Tables to show before the target ones are there: smaller, and at most `orders` scattering
// orders (the scene's when it asks for fewer).
struct StarterTables {
    TableSizes sizes;
    int orders = 0;
};

// How the tables come: at `target` sizes before the first frame, or, with a starter, the
// starter first and the target in the background.
struct TablePlan {
    TableSizes target;
    std::optional<StarterTables> starter;  // none: the target before the first frame
    std::filesystem::path cacheRoot;       // empty: defaultTableCacheRoot()

    // A plan of the target alone (what the commands ask for), implicit so that a TableSizes
    // reads as one.
    TablePlan(const TableSizes& targetSizes) : target(targetSizes) {}  // NOLINT(google-explicit-constructor)
    TablePlan(const TableSizes& targetSizes, std::optional<StarterTables> starterTables,
              std::filesystem::path cache = {})
        : target(targetSizes), starter(std::move(starterTables)), cacheRoot(std::move(cache)) {}
    // The sizes the first tables have.
    const TableSizes& firstSizes() const { return starter ? starter->sizes : target; }
};

// The starter the explorer computes when nothing better is cached: half the reduced sizes,
// 2 scattering orders (the measured cost on llvmpipe: docs/PERFORMANCE.md, issue 14).
StarterTables defaultStarterTables();

// The explorer's plan for `scene`: the target alone when the cache holds an entry for it (the
// next start after a refinement: no starter, no second compile of the programs); else, as
// the starter, the cheapest entry the cache holds for the scene's atmosphere among the
// reduced sizes at the scene's orders and `starter` itself, or `starter` to be computed.
// Only looks for the entries' key files: the load checks them (a damaged target entry is
// then rebuilt before the first frame).
TablePlan startPlan(const Scene& scene, const TableSizes& target, const StarterTables& starter,
                    const std::filesystem::path& shaderRoot, const std::filesystem::path& cacheRoot = {});

class Atmosphere {
public:
    Atmosphere(const std::filesystem::path& shaderRoot, const TablePlan& plan);

    // Brings the tables towards the scene's atmosphere (see above).
    void update(const Scene& scene);
    // Binds the tables at their units (UNIT_TRANSMITTANCE ... UNIT_ELEK_SINGLE_MIE in
    // shaders/common/bindings.glsl) and the parameter block at BLOCK_ATMOSPHERE.
    void bind() const;
    // Whether there are tables yet (the first update() makes them).
    bool ready() const { return tables_.has_value(); }

    bool rebuilding() const { return job_.has_value(); }
    double rebuildProgress() const { return job_ ? job_->progress() : 1.0; }
    // Whether the tables in use are the starter's, not yet refined to the target.
    bool refining() const { return refining_; }
    // The sizes of the tables in use (before the first update(): those the plan makes first).
    const TableSizes& sizes() const { return tables_ ? tables_->sizes : plan_.firstSizes(); }
    const TableSizes& targetSizes() const { return plan_.target; }
    const GpuTables& tables() const { return *tables_; }
    // The parameter block bound with the tables in use (the model's radii and sun, as the programs read them).
    const AtmosphereUniforms& uniforms() const { return current_.uniforms; }
    // Whether the uniform block asks for Elek's 3D table (the scene's atmosphere.elek_3d_table).
    bool usesElekTable() const { return flags_.elek3dTable; }

    // Waits for the refined tables being written to the cache (a worker thread).
    ~Atmosphere();
    Atmosphere(const Atmosphere&) = delete;
    Atmosphere& operator=(const Atmosphere&) = delete;

private:
    struct Target {
        AtmosphereUniforms uniforms;
        int orders = 0;
        TableSizes sizes;
        bool operator==(const Target& o) const;
    };
    Target targetFor(const Scene& scene) const;
    void makeFirstTables(const Scene& scene, const Target& wanted);
    GpuTables loadOrCompute(GpuPrecompute& precompute, const AtmosphereParameters& parameters, int orders);
    void startJob(const Scene& scene, const Target& wanted);
    bool stepJob();  // returns whether the job is done
    void finishJob();
    void cacheRefined(const AtmosphereParameters& parameters);
    void writeUniforms();  // current_.uniforms with the render-time flags

    std::filesystem::path shaderRoot_;  // the model's sources are part of the cache key
    TablePlan plan_;
    // At the target sizes; made on first use (a starter from the cache needs none before the
    // refinement starts, and its compile then falls in the second frame, not the first).
    std::unique_ptr<GpuPrecompute> precompute_;
    std::optional<GpuTables> tables_;
    Target current_{};                 // what tables_ hold
    std::optional<GpuPrecomputeJob> job_;
    Target pending_{};                 // what job_ computes
    AtmosphereParameters pendingParameters_{};  // the same, as the model takes them (the cache's key)
    bool refining_ = false;            // tables_ are the starter's
    // A rebuild's chunks take at most this share of the time between update() calls (one
    // chunk at least).
    static constexpr double kChunkShareOfFrame = 0.25;
    std::optional<std::chrono::steady_clock::time_point> lastUpdate_;  // of the last chunks run
    std::thread cacheWriter_;          // writes the refined tables to the cache
    struct RenderFlags {  // switches applied when rendering; they do not change the tables
        bool elek3dTable = false;
        bool elekRayleighPhase = false;
        bool operator==(const RenderFlags&) const = default;
    };
    RenderFlags flags_;
    gl::Buffer uniforms_;
};

}  // namespace planet::atmosphere
