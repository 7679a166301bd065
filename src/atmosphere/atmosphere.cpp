#include "atmosphere/atmosphere.h"
#include "atmosphere/table_store.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>

#include "atmosphere/parameters.h"
#include "atmosphere/table_cache.h"
#include "render/bindings.h"
#include "util/log.h"

namespace planet::atmosphere {

namespace fs = std::filesystem;

namespace {

std::string mibText(const TableSizes& sizes) {
    char mib[32];
    std::snprintf(mib, sizeof mib, "%.2f MiB", static_cast<double>(sizes.bytes()) / (1 << 20));
    return mib;
}

std::string sizesText(const TableSizes& s, int orders) {
    return "transmittance " + std::to_string(s.transmittance_width) + "x" + std::to_string(s.transmittance_height) +
           ", scattering " + std::to_string(s.scattering_nu) + "x" + std::to_string(s.scattering_mu_s) + "x" +
           std::to_string(s.scattering_mu) + "x" + std::to_string(s.scattering_r) + ", " + std::to_string(orders) +
           " orders, " + mibText(s);
}

std::string secondsText(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", seconds);
    return text;
}

}  // namespace

// Half the reduced sizes on every axis (nu at its least, 2), 2 scattering orders: on llvmpipe
// 0.1 s against 0.8 s for the reduced tables at 2 orders and 1.8 s at 4 (each order's
// scattering density costs in proportion to the texels); one order would leave the sky's light
// on the ground out (the irradiance table starts at order 2). Against the reduced tables at 4
// orders, stills differ by 2.5-7 % in mean luminance (orbit, ground, sunset at 320x180; the
// limb from orbit most, p99 32 %): shown for the seconds the refinement takes.
StarterTables defaultStarterTables() { return {TableSizes{32, 8, 4, 16, 4, 2, 8, 2, 4, 16, 4}, 2}; }

TablePlan startPlan(const Scene& scene, const TableSizes& target, const StarterTables& starter,
                    const fs::path& shaderRoot, const fs::path& cacheRoot) {
    const AtmosphereParameters parameters = makeAtmosphereParameters(scene);
    const int orders = scene.atmosphere.scattering_orders;
    const std::string model = atmosphereModelSource(shaderRoot);
    const fs::path root = cacheRoot.empty() ? defaultTableCacheRoot() : cacheRoot;
    auto cached = [&](const StarterTables& t) {
        return fs::exists(root / tableCacheKey(parameters, t.sizes, t.orders, model) / "key.txt");
    };
    const StarterTables mine{starter.sizes, std::min(starter.orders, orders)};
    if (cached({target, orders}) || (mine.sizes == target && mine.orders == orders)) return {target, std::nullopt, cacheRoot};
    // Loading a cached entry costs less than computing any starter: the better one first.
    for (const StarterTables& c : {StarterTables{TableSizes::reduced(), orders}, mine})
        if (c.sizes.bytes() <= target.bytes() && !(c.sizes == target && c.orders == orders) && cached(c))
            return {target, c, cacheRoot};
    return {target, mine, cacheRoot};
}

bool Atmosphere::Target::operator==(const Target& o) const {
    return orders == o.orders && sizes == o.sizes && std::memcmp(&uniforms, &o.uniforms, sizeof uniforms) == 0;
}

Atmosphere::Target Atmosphere::targetFor(const Scene& scene) const {
    Target t{makeAtmosphereUniforms(makeAtmosphereParameters(scene)), scene.atmosphere.scattering_orders, plan_.target};
    t.uniforms.elekRayleighPhase = 0.0f;  // Elek's Rayleigh phase is applied at render time, not in the tables
    return t;
}

Atmosphere::Atmosphere(const fs::path& shaderRoot, const TablePlan& plan) : shaderRoot_(shaderRoot), plan_(plan) {
    glNamedBufferStorage(uniforms_.id(), sizeof(AtmosphereUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    uniforms_.label("AtmosphereUniforms");
}

Atmosphere::~Atmosphere() {
    if (cacheWriter_.joinable()) cacheWriter_.join();
}

void Atmosphere::update(const Scene& scene) {
    const Target wanted = targetFor(scene);
    const RenderFlags flags{scene.atmosphere.elek_3d_table, scene.atmosphere.elek_rayleigh_phase};
    if (!tables_) {  // first use: tables now
        makeFirstTables(scene, wanted);
        flags_ = flags;
        writeUniforms();
        return;  // a refinement starts with the next call: its programs' compile is not the first frame's
    }
    if (!(flags == flags_)) {  // render-time switches: same tables, new flags
        flags_ = flags;
        writeUniforms();
    }
    if (job_ && !(pending_ == wanted)) job_.reset();  // parameters moved on: restart with the newest
    if (!job_ && !(current_ == wanted)) startJob(scene, wanted);
    if (job_ && stepJob()) finishJob();
}

// One chunk, and more while they take under a quarter of the time since the last call (the
// frame's period): a frame of 16 ms gets one chunk, as before, but a software renderer's frame
// of seconds gets a second's worth, so a refinement of ~70 chunks does not take 70 of them.
bool Atmosphere::stepJob() {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    const double period = lastUpdate_ ? std::chrono::duration<double>(start - *lastUpdate_).count() : 0.0;
    lastUpdate_ = start;
    const double before = job_->progress();
    bool done = job_->step();
    while (!done && std::chrono::duration<double>(Clock::now() - start).count() < kChunkShareOfFrame * period)
        done = job_->step();
    // A step of a full-size refinement lasts minutes on a software renderer: a line every tenth.
    if (refining_ && !done && std::floor(10.0 * job_->progress()) > std::floor(10.0 * before))
        logInfo("  refining: " + std::to_string(static_cast<int>(100.0 * job_->progress())) + " % (" +
                job_->currentStep() + ")");
    return done;
}

void Atmosphere::makeFirstTables(const Scene& scene, const Target& wanted) {
    const AtmosphereParameters parameters = makeAtmosphereParameters(scene);
    current_ = wanted;
    if (plan_.starter) {
        current_.sizes = plan_.starter->sizes;
        current_.orders = std::min(plan_.starter->orders, wanted.orders);
    }
    refining_ = !(current_ == wanted);
    // The starter's precomputation (its programs, its delta tables) is needed once: not kept.
    std::unique_ptr<GpuPrecompute> starter;
    if (current_.sizes == plan_.target)
        precompute_ = std::make_unique<GpuPrecompute>(shaderRoot_, plan_.target);
    else
        starter = std::make_unique<GpuPrecompute>(shaderRoot_, current_.sizes);
    GpuPrecompute& precompute = starter ? *starter : *precompute_;
    tables_ = loadOrCompute(precompute, parameters, current_.orders);
    // Elek's 3D table from the 4D ones (the cache holds only those), one short pass.
    precompute.computeElekTable(parameters, *tables_);
    if (refining_) logInfo("atmosphere: starting with tables of " + sizesText(current_.sizes, current_.orders));
}

GpuTables Atmosphere::loadOrCompute(GpuPrecompute& precompute, const AtmosphereParameters& parameters, int orders) {
    // The one load-or-compute of the tables (table_store.h), with what the renderer logs.
    TableStoreOptions options;
    options.onCompute = [&](const TableStoreReport& r) {
        if (!r.rejected.empty()) logWarning("atmosphere cache " + r.dir.string() + " not used (" + r.rejected + "); rebuilding it");
        logInfo("precomputing atmosphere tables (" + mibText(precompute.sizes()) + ")...");
    };
    options.onStep = [](const PrecomputeStep& s) { logInfo("  " + s.name + ": " + std::to_string(s.seconds) + " s"); };
    TableStoreReport report;
    GpuTables tables = loadOrComputeTables(precompute, parameters, orders, plan_.cacheRoot, shaderRoot_, options, &report);
    if (report.hit) logInfo("atmosphere tables from the cache " + report.dir.string());
    // A read-only folder costs the next start time, nothing else.
    if (!report.notSaved.empty()) logWarning("atmosphere tables not cached: " + report.notSaved);
    return tables;
}

void Atmosphere::startJob(const Scene& scene, const Target& wanted) {
    if (!precompute_) precompute_ = std::make_unique<GpuPrecompute>(shaderRoot_, plan_.target);
    pendingParameters_ = makeAtmosphereParameters(scene);
    pending_ = wanted;
    lastUpdate_.reset();  // the frame's period is measured from this job's first chunk on
    ProgressFn progress;  // a refinement reports its steps; tuning's rebuilds show in the Scene panel only
    if (refining_) {
        logInfo("atmosphere: refining the tables to " + sizesText(wanted.sizes, wanted.orders) + " in the background");
        progress = [this](const PrecomputeStep& s) {
            logInfo("  refining: " + s.name + " " + secondsText(s.seconds) + " (" +
                    std::to_string(static_cast<int>(100.0 * (job_ ? job_->progress() : 1.0))) + " %)");
        };
    }
    // One r layer per chunk: the longest stall a rebuild adds to a frame.
    job_ = precompute_->start(pendingParameters_, wanted.orders, progress, 1, /*elekTable=*/true);
}

void Atmosphere::finishJob() {
    tables_ = job_->takeResult();
    current_ = pending_;
    writeUniforms();
    job_.reset();
    if (refining_) {
        refining_ = false;
        logInfo("atmosphere: refined tables in use (" + sizesText(current_.sizes, current_.orders) + ")");
        cacheRefined(pendingParameters_);
    }
}

// The refined tables go to the cache, so that the next start loads them at once. The
// read-back is quick; the EXR writing (seconds at full size) runs on a worker thread.
void Atmosphere::cacheRefined(const AtmosphereParameters& parameters) {
    AtmosphereTables tables = readBack(*tables_);
    if (cacheWriter_.joinable()) cacheWriter_.join();
    cacheWriter_ = std::thread([tables = std::move(tables), parameters, orders = current_.orders,
                                root = plan_.cacheRoot, shaderRoot = shaderRoot_]() mutable {
        try {
            TableStoreOptions options;
            options.force = true;  // save what was computed (the same flow as every cached table)
            TableStoreReport report;
            const TableSizes sizes = tables.sizes;
            loadOrComputeTables([&](const ProgressFn&) { return std::move(tables); }, parameters, sizes, orders, root,
                                shaderRoot, options, &report);
            if (report.notSaved.empty())
                logInfo("atmosphere: refined tables cached in " + report.dir.string());
            else
                logWarning("atmosphere: refined tables not cached: " + report.notSaved);
        } catch (const std::exception& e) {
            logWarning(std::string("atmosphere: refined tables not cached: ") + e.what());
        }
    });
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
