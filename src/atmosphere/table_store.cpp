// The atmosphere tables from the cache or precomputed (see table_store.h): one flow,
// util/cache_entry.h's loadOrMake, for tables kept on the GPU and tables kept in CPU memory.
#include "atmosphere/table_store.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "atmosphere/table_cache.h"

namespace planet::atmosphere {

namespace fs = std::filesystem;

namespace {

bool allFinite(const AtmosphereTables& t) {
    for (const std::vector<glm::dvec4>* texels :
         {&t.transmittance.texels, &t.scattering.texels, &t.singleMie.texels, &t.irradiance.texels})
        for (const glm::dvec4& v : *texels)
            for (int c = 0; c < 4; ++c)
                if (!std::isfinite(v[c])) return false;
    return true;
}

// Saves computed tables, unless they hold NaN or Inf (the loader would refuse them anyway).
void saveComputed(const AtmosphereTables& tables, const fs::path& dir, const std::string& key) {
    if (!allFinite(tables)) throw std::runtime_error("the precomputed tables contain NaN or Inf; not cached");
    saveTables(tables, dir, key);
}

// The one flow: `fromCache` turns loaded tables into the result, `compute(onStep)` makes
// the result, `cpuTables(result)` gives what is saved.
template <class FromCache, class Compute, class CpuTables>
auto loadOrCompute(const AtmosphereParameters& parameters, const TableSizes& sizes, int orders,
                   const fs::path& cacheRoot, const fs::path& shaderRoot, const TableStoreOptions& options,
                   TableStoreReport* out, const FromCache& fromCache, const Compute& compute,
                   const CpuTables& cpuTables) {
    TableStoreReport report;
    report.key = tableCacheKey(parameters, sizes, orders, atmosphereModelSource(shaderRoot));
    const fs::path dir = (cacheRoot.empty() ? defaultTableCacheRoot() : cacheRoot) / report.key;
    auto result = loadOrMake(
        dir, options.force,
        [&](std::string* reason) {
            std::optional<AtmosphereTables> cached = loadTables(dir, report.key, sizes, reason);
            return cached ? std::optional(fromCache(std::move(*cached))) : std::nullopt;
        },
        [&] { return compute(options.onStep); },
        [&](const auto& computed) { saveComputed(cpuTables(computed), dir, report.key); },
        [&](const CacheOutcome& o) {
            static_cast<CacheOutcome&>(report) = o;
            if (options.onCompute) options.onCompute(report);
        },
        &report);
    if (out) *out = report;
    return result;
}

}  // namespace

GpuTables loadOrComputeTables(GpuPrecompute& precompute, const AtmosphereParameters& parameters, int orders,
                              const fs::path& cacheRoot, const fs::path& shaderRoot, const TableStoreOptions& options,
                              TableStoreReport* report) {
    return loadOrCompute(
        parameters, precompute.sizes(), orders, cacheRoot, shaderRoot, options, report,
        [](AtmosphereTables&& cached) { return upload(cached); },
        [&](const ProgressFn& onStep) { return precompute.compute(parameters, orders, onStep); },
        [](const GpuTables& computed) { return readBack(computed); });
}

AtmosphereTables loadOrComputeTables(const ComputeTablesFn& compute, const AtmosphereParameters& parameters,
                                     const TableSizes& sizes, int orders, const fs::path& cacheRoot,
                                     const fs::path& shaderRoot, const TableStoreOptions& options,
                                     TableStoreReport* report) {
    return loadOrCompute(
        parameters, sizes, orders, cacheRoot, shaderRoot, options, report,
        [](AtmosphereTables&& cached) { return std::move(cached); }, compute,
        [](const AtmosphereTables& computed) -> const AtmosphereTables& { return computed; });
}

}  // namespace planet::atmosphere
