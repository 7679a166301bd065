// The atmosphere tables from the table cache, or precomputed and cached: the one place that
// decides, for the renderer's Atmosphere, `planet precompute` and `planet sky-probe`.
//
// The entry is <cache root>/<tableCacheKey(parameters, sizes, orders, model source)>/
// (table_cache.h). Unless forced, a valid entry is used as it is; otherwise (none there,
// refused with a reason, or forced) the tables are precomputed, checked for NaN / Inf and
// saved there. The caller learns what happened from a TableStoreReport, and says what it
// wants to print or log through the options' callbacks: before the precomputation starts
// (onCompute, with the reason) and after each of its steps (onStep). A cache that cannot be
// written does not fail the call: report.notSaved says why, and the caller decides.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "atmosphere/model.h"
#include "atmosphere/precompute_gpu.h"
#include "atmosphere/reference_tables.h"
#include "atmosphere/tables.h"
#include "util/cache_entry.h"

namespace planet::atmosphere {

// What loadOrComputeTables did: CacheOutcome's dir, hit, forced, rejected, seconds (of the
// precomputation) and notSaved, plus the entry's key.
struct TableStoreReport : CacheOutcome {
    std::string key;
};

struct TableStoreOptions {
    bool force = false;  // precompute even when a valid entry is there
    ProgressFn onStep;   // after each precomputation step
    // Once the cache has been consulted and the tables are going to be precomputed; the
    // report holds key, dir, forced and rejected so far.
    std::function<void(const TableStoreReport&)> onCompute;
};

// The tables for `parameters` at precompute.sizes() with `orders` scattering orders, on the
// GPU: uploaded from the entry under `cacheRoot` (empty: defaultTableCacheRoot()) when it is
// valid, else precomputed with `precompute` (the model's steps, no Elek table), read back and
// saved there. `shaderRoot` holds the model's shaders, whose text is part of the key.
// Needs the GL context `precompute` was made in.
GpuTables loadOrComputeTables(GpuPrecompute& precompute, const AtmosphereParameters& parameters, int orders,
                              const std::filesystem::path& cacheRoot, const std::filesystem::path& shaderRoot,
                              const TableStoreOptions& options = {}, TableStoreReport* report = nullptr);

// How tables are made in CPU memory when the cache has none: the CPU reference
// (computeReferenceTables), or a GPU precomputation read back.
using ComputeTablesFn = std::function<AtmosphereTables(const ProgressFn& onStep)>;

// The same in CPU memory, at `sizes`: from the entry when valid, else compute(onStep), saved.
AtmosphereTables loadOrComputeTables(const ComputeTablesFn& compute, const AtmosphereParameters& parameters,
                                     const TableSizes& sizes, int orders, const std::filesystem::path& cacheRoot,
                                     const std::filesystem::path& shaderRoot, const TableStoreOptions& options = {},
                                     TableStoreReport* report = nullptr);

}  // namespace planet::atmosphere
