// `planet precompute`: the preset's atmosphere tables, built headlessly on the
// GPU (or by the CPU reference with --reference) and written to the table
// cache (src/atmosphere/table_cache.h), with the time of every step, the total
// and the tables' memory. A valid cache entry is reused unless --force; a
// damaged one is reported and rebuilt.
//
// loadOrPrecomputeTables() is the shared core: `sky-probe` gets its GPU tables
// the same way.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

#include "app/commands.h"
#include "app/session.h"
#include "atmosphere/elek_table.h"
#include "atmosphere/parameters.h"
#include "atmosphere/precompute_gpu.h"
#include "atmosphere/reference_tables.h"
#include "atmosphere/table_cache.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "scene/toml_error.h"

namespace planet {

namespace fs = std::filesystem;
using namespace atmosphere;

namespace {

std::string format(const char* fmt, double a) {
    char text[64];
    std::snprintf(text, sizeof text, fmt, a);
    return text;
}

std::string describeSizes(const TableSizes& s) {
    const glm::ivec3 s3 = s.scatteringSize();
    return "transmittance " + std::to_string(s.transmittance_width) + "x" + std::to_string(s.transmittance_height) +
           ", scattering and single Mie " + std::to_string(s3.x) + "x" + std::to_string(s3.y) + "x" +
           std::to_string(s3.z) + " (nu " + std::to_string(s.scattering_nu) + " x mu_s " +
           std::to_string(s.scattering_mu_s) + ", mu " + std::to_string(s.scattering_mu) + ", r " +
           std::to_string(s.scattering_r) + "), irradiance " + std::to_string(s.irradiance_width) + "x" +
           std::to_string(s.irradiance_height);
}

bool allFinite(const AtmosphereTables& t) {
    for (const std::vector<glm::dvec4>* texels :
         {&t.transmittance.texels, &t.scattering.texels, &t.singleMie.texels, &t.irradiance.texels})
        for (const glm::dvec4& v : *texels)
            for (int c = 0; c < 4; ++c)
                if (!std::isfinite(v[c])) return false;
    return true;
}

}  // namespace

TableSizes commandTableSizes(const std::string& choice, bool haveContext) {
    if (haveContext || choice != "auto") return tableSizesFor(choice, haveContext ? gl::rendererDescription() : "");
    try {
        gl::HeadlessContext probe(false);
        return tableSizesFor(choice, gl::rendererDescription());
    } catch (const gl::ContextError&) {
        return tableSizesFor(choice, "");  // no GL at all: full tables
    }
}

AtmosphereTables loadOrPrecomputeTables(const Scene& scene, const TableSizes& sizes, const std::string& cacheRoot,
                                        const fs::path& shaderRoot, bool reference, bool force, std::ostream& out) {
    const AtmosphereParameters params = makeAtmosphereParameters(scene);
    const int orders = scene.atmosphere.scattering_orders;
    const std::string key = tableCacheKey(params, sizes, orders, atmosphereModelSource(shaderRoot));
    const fs::path dir = (cacheRoot.empty() ? defaultTableCacheRoot() : fs::path(cacheRoot)) / key;
    const std::string where = fs::absolute(dir).lexically_normal().string();

    if (!force) {
        std::string reason;
        if (std::optional<AtmosphereTables> cached = loadTables(dir, key, sizes, &reason)) {
            out << "cache hit: valid tables in " << where << " (key " << key << ")\n";
            return std::move(*cached);
        }
        if (fs::exists(dir))
            out << "cache at " << where << " is not usable, rebuilding: " << reason << "\n";
        else
            out << "no cached tables for key " << key << ", computing\n";
    } else {
        out << "--force: rebuilding the tables for key " << key << "\n";
    }

    out << "precomputing " << orders << " scattering order(s) on "
        << (reference ? std::string("the CPU (double-precision reference)") : gl::rendererDescription()) << "\n";
    out.flush();
    const ProgressFn progress = [&out](const PrecomputeStep& step) {
        out << "  " << step.name << std::string(step.name.size() < 20 ? 20 - step.name.size() : 1, ' ')
            << format("%9.3f s", step.seconds) << "\n";
        out.flush();
    };
    const auto start = std::chrono::steady_clock::now();
    AtmosphereTables tables;
    if (reference) {
        tables = computeReferenceTables(params, sizes, orders, progress).tables;
    } else {
        GpuPrecompute precompute(shaderRoot, sizes);
        tables = readBack(precompute.compute(params, orders, progress));
    }
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out << "  total" << std::string(15, ' ') << format("%9.3f s", total) << "\n";
    out << "table memory: " << format("%.2f MiB", static_cast<double>(sizes.bytes()) / (1024.0 * 1024.0))
        << " as RGBA32F (" << describeSizes(sizes) << ")\n";
    if (!allFinite(tables)) throw std::runtime_error("the precomputed tables contain NaN or Inf; not cached");

    saveTables(tables, dir, key);
    out << "wrote " << where << "\n";
    return tables;
}

int runPrecompute(const PrecomputeOptions& options) {
    const CommonOptions& common = options.common;
    const DataPaths paths = findDataPaths(common.root);
    const Session session = loadSession(paths, common.preset, common.view);

    gl::DebugMessages messages;  // outlives the context that reports into it
    std::optional<gl::HeadlessContext> context;
    if (!options.reference) {
        context.emplace(common.glDebug);
        gl::installDebugOutput(&messages, common.glDebug);
    }
    const TableSizes sizes = commandTableSizes(common.tables, context.has_value());
    std::cout << "planet precompute: preset " << session.presetName << ", tables " << common.tables << " ("
              << describeSizes(sizes) << ")\n";
    const AtmosphereTables tables = loadOrPrecomputeTables(session.scene, sizes, options.cache, paths.shaders(),
                                                           options.reference, options.force, std::cout);
    // Elek's 3D parametrization (no nu, phase deferred), built from these tables
    // on the CPU: its memory and its sky radiance error against the 4D lookups.
    const AtmosphereParameters params = makeAtmosphereParameters(session.scene);
    std::cout << "Elek 3D table vs 4D:\n"
              << describeElekComparison(compareElekWith4D(params, tables, computeElekTables(params, tables)));
    std::cout.flush();
    if (messages.errors > 0) throw std::runtime_error("GL errors were reported during the precomputation");
    return 0;
}

}  // namespace planet
