#include "atmosphere/atmosphere.h"
#include "atmosphere/table_store.h"

#include <cstdio>
#include <cstring>

#include "atmosphere/parameters.h"
#include "atmosphere/table_cache.h"
#include "render/bindings.h"
#include "util/log.h"

namespace planet::atmosphere {

bool Atmosphere::Target::operator==(const Target& o) const {
    return orders == o.orders && std::memcmp(&uniforms, &o.uniforms, sizeof uniforms) == 0;
}

Atmosphere::Target Atmosphere::targetFor(const Scene& scene) {
    Target t{makeAtmosphereUniforms(makeAtmosphereParameters(scene)), scene.atmosphere.scattering_orders};
    t.uniforms.elekRayleighPhase = 0.0f;  // Elek's Rayleigh phase is applied at render time, not in the tables
    return t;
}

Atmosphere::Atmosphere(const std::filesystem::path& shaderRoot, const TableSizes& sizes)
    : shaderRoot_(shaderRoot), precompute_(shaderRoot, sizes) {
    glNamedBufferStorage(uniforms_.id(), sizeof(AtmosphereUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    uniforms_.label("AtmosphereUniforms");
}

void Atmosphere::update(const Scene& scene) {
    const Target wanted = targetFor(scene);
    const RenderFlags flags{scene.atmosphere.elek_3d_table, scene.atmosphere.elek_rayleigh_phase};
    if (!tables_) {  // first use: tables now
        tables_ = loadOrCompute(makeAtmosphereParameters(scene), wanted.orders);
        // Elek's 3D table from the 4D ones (the cache holds only those), one short pass.
        precompute_.computeElekTable(makeAtmosphereParameters(scene), *tables_);
        current_ = wanted;
        flags_ = flags;
        writeUniforms();
        return;
    }
    if (!(flags == flags_)) {  // render-time switches: same tables, new flags
        flags_ = flags;
        writeUniforms();
    }
    if (job_ && !(pending_ == wanted)) job_.reset();  // parameters moved on: restart with the newest
    if (!job_ && !(current_ == wanted)) {
        // One r layer per chunk: the longest stall a rebuild adds to a frame.
        job_ = precompute_.start(makeAtmosphereParameters(scene), wanted.orders, {}, 1, /*elekTable=*/true);
        pending_ = wanted;
    }
    if (job_ && job_->step()) finishJob();
}

GpuTables Atmosphere::loadOrCompute(const AtmosphereParameters& parameters, int orders) {
    // The one load-or-compute of the tables (table_store.h), with what the renderer logs.
    TableStoreOptions options;
    options.onCompute = [&](const TableStoreReport& r) {
        if (!r.rejected.empty()) logWarning("atmosphere cache " + r.dir.string() + " not used (" + r.rejected + "); rebuilding it");
        char mib[32];
        std::snprintf(mib, sizeof mib, "%.2f MiB", static_cast<double>(sizes().bytes()) / (1 << 20));
        logInfo(std::string("precomputing atmosphere tables (") + mib + ")...");
    };
    options.onStep = [](const PrecomputeStep& s) { logInfo("  " + s.name + ": " + std::to_string(s.seconds) + " s"); };
    TableStoreReport report;
    GpuTables tables = loadOrComputeTables(precompute_, parameters, orders, {}, shaderRoot_, options, &report);
    if (report.hit) logInfo("atmosphere tables from the cache " + report.dir.string());
    // A read-only folder costs the next start time, nothing else.
    if (!report.notSaved.empty()) logWarning("atmosphere tables not cached: " + report.notSaved);
    return tables;
}

void Atmosphere::finishJob() {
    tables_ = job_->takeResult();
    current_ = pending_;
    writeUniforms();
    job_.reset();
}

void Atmosphere::writeUniforms() {
    AtmosphereUniforms u = current_.uniforms;
    u.elekRayleighPhase = flags_.elekRayleighPhase ? 1.0f : 0.0f;
    glNamedBufferSubData(uniforms_.id(), 0, sizeof u, &u);
}

void Atmosphere::bind() const {
    const GLuint textures[] = {tables_->transmittance.id(), tables_->scattering.id(), tables_->singleMie.id(),
                               tables_->irradiance.id()};
    static_assert(binding::UNIT_SCATTERING == binding::UNIT_TRANSMITTANCE + 1 &&
                  binding::UNIT_SINGLE_MIE == binding::UNIT_TRANSMITTANCE + 2 &&
                  binding::UNIT_IRRADIANCE == binding::UNIT_TRANSMITTANCE + 3 &&
                  binding::UNIT_ELEK_SINGLE_MIE == binding::UNIT_ELEK_SCATTERING + 1);
    glBindTextures(binding::UNIT_TRANSMITTANCE, 4, textures);
    const GLuint elekTextures[] = {tables_->elekScattering.id(), tables_->elekSingleMie.id()};
    glBindTextures(binding::UNIT_ELEK_SCATTERING, 2, elekTextures);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::BLOCK_ATMOSPHERE, uniforms_.id());
}

}  // namespace planet::atmosphere
