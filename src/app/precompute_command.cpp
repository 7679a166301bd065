// `planet precompute`: the preset's atmosphere tables, built headlessly on the
// GPU (or by the CPU reference with --reference) and written to the table
// cache (src/atmosphere/table_cache.h), with the time of every step, the total
// and the tables' memory. A valid cache entry is reused unless --force; a
// damaged one is reported and rebuilt.
//
// loadOrPrecomputeTables() prints what atmosphere/table_store.h's
// loadOrComputeTables() decides and does; `sky-probe` gets its tables the same way.
#include <cstdio>
#include <iostream>
#include <optional>

#include "app/commands.h"
#include "app/session.h"
#include "atmosphere/elek_table.h"
#include "atmosphere/parameters.h"
#include "atmosphere/precompute_gpu.h"
#include "atmosphere/reference_tables.h"
#include "atmosphere/table_store.h"
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
    auto where = [](const TableStoreReport& r) { return fs::absolute(r.dir).lexically_normal().string(); };

    TableStoreOptions options;
    options.force = force;
    options.onCompute = [&](const TableStoreReport& r) {
        if (r.forced)
            out << "--force: rebuilding the tables for key " << r.key << "\n";
        else if (!r.rejected.empty())
            out << "cache at " << where(r) << " is not usable, rebuilding: " << r.rejected << "\n";
        else
            out << "no cached tables for key " << r.key << ", computing\n";
        out << "precomputing " << orders << " scattering order(s) on "
            << (reference ? std::string("the CPU (double-precision reference)") : gl::rendererDescription()) << "\n";
        out.flush();
    };
    options.onStep = [&out](const PrecomputeStep& step) {
        out << "  " << step.name << std::string(step.name.size() < 20 ? 20 - step.name.size() : 1, ' ')
            << format("%9.3f s", step.seconds) << "\n";
        out.flush();
    };
    const ComputeTablesFn compute = [&](const ProgressFn& onStep) {
        if (reference) return computeReferenceTables(params, sizes, orders, onStep).tables;
        GpuPrecompute precompute(shaderRoot, sizes);
        return readBack(precompute.compute(params, orders, onStep));
    };

    TableStoreReport report;
    AtmosphereTables tables =
        loadOrComputeTables(compute, params, sizes, orders, cacheRoot, shaderRoot, options, &report);
    if (report.hit) {
        out << "cache hit: valid tables in " << where(report) << " (key " << report.key << ")\n";
        return tables;
    }
    out << "  total" << std::string(15, ' ') << format("%9.3f s", report.seconds) << "\n";
    out << "table memory: " << format("%.2f MiB", static_cast<double>(sizes.bytes()) / (1024.0 * 1024.0))
        << " as RGBA32F (" << describeSizes(sizes) << ")\n";
    if (!report.notSaved.empty()) throw std::runtime_error(report.notSaved);
    out << "wrote " << where(report) << "\n";
    return tables;
}

int runPrecompute(const PrecomputeOptions& options) {
    const CommonOptions& common = options.common;
    const DataPaths paths = findDataPaths(common.root);
    const NamedPreset preset = loadNamedPreset(paths, common.preset);  // no view, no ground: no continents

    gl::DebugMessages messages;  // outlives the context that reports into it
    std::optional<gl::HeadlessContext> context;
    if (!options.reference) {
        context.emplace(common.glDebug);
        gl::installDebugOutput(&messages, common.glDebug);
    }
    const TableSizes sizes = commandTableSizes(common.tables, context.has_value());
    std::cout << "planet precompute: preset " << preset.name << ", tables " << common.tables << " ("
              << describeSizes(sizes) << ")\n";
    const AtmosphereTables tables = loadOrPrecomputeTables(preset.scene, sizes, options.cache, paths.shaders(),
                                                           options.reference, options.force, std::cout);
    // Elek's 3D parametrization (no nu, phase deferred), built from these tables
    // on the CPU: its memory and its sky radiance error against the 4D lookups.
    const AtmosphereParameters params = makeAtmosphereParameters(preset.scene);
    std::cout << "Elek 3D table vs 4D:\n"
              << describeElekComparison(compareElekWith4D(params, tables, computeElekTables(params, tables)));
    std::cout.flush();
    if (messages.errors > 0) throw std::runtime_error("GL errors were reported during the precomputation");
    return 0;
}

}  // namespace planet
