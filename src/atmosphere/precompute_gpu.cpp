#include "atmosphere/precompute_gpu.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

#include "atmosphere/uniforms.h"
#include "gl/debug.h"
#include "gl/program.h"

namespace planet::atmosphere {

namespace {

constexpr int kLocalSize = 8;  // local_size_x = local_size_y in every precompute shader; local_size_z = 1

// Uniform locations shared by the precompute shaders.
constexpr GLint kLayerOffsetLocation = 0;
constexpr GLint kScatteringOrderLocation = 1;

// Texture units (sampler bindings) and image units, as declared in the shaders.
enum SamplerUnit : GLuint {
    kTransmittanceUnit = 0,
    kDeltaRayleighUnit = 1,
    kDeltaMieUnit = 2,
    kDeltaMultipleUnit = 3,
    kDeltaIrradianceUnit = 4,
    kDeltaDensityUnit = 5,
    kScatteringInputUnit = 1,  // Elek pass: the finished scattering table
    kSingleMieInputUnit = 2,   // Elek pass: the finished single Mie table
};

// Rough cost of one texel of each pass, in table lookups / density evaluations,
// only to weight progress(): the sample counts of functions.glsl times the lookups per sample.
constexpr double kTransmittanceCost = 3 * 501;
constexpr double kDirectIrradianceCost = 2;
constexpr double kSingleScatteringCost = 51 * 4;
constexpr double kIndirectIrradianceCost = 16 * 64 * 4;
constexpr double kMultipleScatteringCost = 51 * 4;
// 16 rings of 8 nu-slice lookups and 512 directions' arithmetic: measured at about
// twice the multiple scattering pass (full tables, llvmpipe, 2026-12-02).
constexpr double kScatteringDensityCost = 2 * kMultipleScatteringCost;
constexpr double kElekTableCost = 4;

gl::Texture makeTable2D(int width, int height, const char* label) {
    gl::Texture t(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, GL_RGBA32F, width, height);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glClearTexImage(t.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
    t.label(label);
    return t;
}

gl::Texture makeTable3D(glm::ivec3 size, const char* label) {
    gl::Texture t(GL_TEXTURE_3D);
    glTextureStorage3D(t.id(), 1, GL_RGBA32F, size.x, size.y, size.z);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glClearTexImage(t.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
    t.label(label);
    return t;
}

void clearTable(const gl::Texture& t) { glClearTexImage(t.id(), 0, GL_RGBA, GL_FLOAT, nullptr); }

void bindImage2D(GLuint unit, const gl::Texture& t, GLenum access) {
    glBindImageTexture(unit, t.id(), 0, GL_FALSE, 0, access, GL_RGBA32F);
}
void bindImage3D(GLuint unit, const gl::Texture& t, GLenum access) {
    glBindImageTexture(unit, t.id(), 0, GL_TRUE, 0, access, GL_RGBA32F);
}

GLuint groups(int size) { return static_cast<GLuint>((size + kLocalSize - 1) / kLocalSize); }

// Everything a later pass (or readback) may do with what a pass wrote.
void barrier() {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void dispatch2D(int width, int height) {
    glDispatchCompute(groups(width), groups(height), 1);
    barrier();
}

// Layers [first, first + count) of a 3D pass.
void dispatch3D(GLuint program, glm::ivec3 size, int first, int count) {
    glProgramUniform1i(program, kLayerOffsetLocation, first);
    glDispatchCompute(groups(size.x), groups(size.y), static_cast<GLuint>(count));
    barrier();
}

std::vector<float> toFloats(const std::vector<glm::dvec4>& texels) {
    std::vector<float> floats(texels.size() * 4);
    for (std::size_t i = 0; i < texels.size(); ++i)
        for (int c = 0; c < 4; ++c) floats[4 * i + c] = static_cast<float>(texels[i][c]);
    return floats;
}

// Layers [first, first + count) of Elek's 3D table from the finished 4D tables.
void dispatchElekTable(GLuint program, const GpuTables& tables, int first, int count) {
    glUseProgram(program);
    glBindTextureUnit(kScatteringInputUnit, tables.scattering.id());
    glBindTextureUnit(kSingleMieInputUnit, tables.singleMie.id());
    bindImage3D(0, tables.elekScattering, GL_WRITE_ONLY);
    bindImage3D(1, tables.elekSingleMie, GL_WRITE_ONLY);
    dispatch3D(program, tables.sizes.elekSize(), first, count);
}

}  // namespace

// ------------------------------------------------------------------ tables

GpuTables makeGpuTables(const TableSizes& sizes) {
    GpuTables t;
    t.sizes = sizes;
    t.transmittance = makeTable2D(sizes.transmittance_width, sizes.transmittance_height, "atmosphere transmittance");
    t.scattering = makeTable3D(sizes.scatteringSize(), "atmosphere scattering");
    t.singleMie = makeTable3D(sizes.scatteringSize(), "atmosphere single Mie");
    t.irradiance = makeTable2D(sizes.irradiance_width, sizes.irradiance_height, "atmosphere irradiance");
    t.elekScattering = makeTable3D(sizes.elekSize(), "atmosphere Elek 3D scattering");
    t.elekSingleMie = makeTable3D(sizes.elekSize(), "atmosphere Elek 3D single Mie");
    return t;
}

std::vector<glm::dvec4> readTexels(const gl::Texture& t, std::size_t count) {
    std::vector<float> floats(count * 4);
    glGetTextureImage(t.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(floats.size() * sizeof(float)),
                      floats.data());
    std::vector<glm::dvec4> out(count);
    for (std::size_t i = 0; i < count; ++i)
        out[i] = glm::dvec4(floats[4 * i], floats[4 * i + 1], floats[4 * i + 2], floats[4 * i + 3]);
    return out;
}

AtmosphereTables readBack(const GpuTables& gpu) {
    const TableSizes& s = gpu.sizes;
    AtmosphereTables t(s);
    t.transmittance.texels = readTexels(gpu.transmittance, t.transmittance.texels.size());
    t.scattering.texels = readTexels(gpu.scattering, t.scattering.texels.size());
    t.singleMie.texels = readTexels(gpu.singleMie, t.singleMie.texels.size());
    t.irradiance.texels = readTexels(gpu.irradiance, t.irradiance.texels.size());
    return t;
}

GpuTables upload(const AtmosphereTables& tables) {
    GpuTables gpu = makeGpuTables(tables.sizes);
    auto upload2D = [](const gl::Texture& t, const Table2D& table) {
        const std::vector<float> f = toFloats(table.texels);
        glTextureSubImage2D(t.id(), 0, 0, 0, table.width, table.height, GL_RGBA, GL_FLOAT, f.data());
    };
    auto upload3D = [](const gl::Texture& t, const Table3D& table) {
        const std::vector<float> f = toFloats(table.texels);
        glTextureSubImage3D(t.id(), 0, 0, 0, 0, table.width, table.height, table.depth, GL_RGBA, GL_FLOAT, f.data());
    };
    upload2D(gpu.transmittance, tables.transmittance);
    upload3D(gpu.scattering, tables.scattering);
    upload3D(gpu.singleMie, tables.singleMie);
    upload2D(gpu.irradiance, tables.irradiance);
    return gpu;
}

// -------------------------------------------------------------------- job

struct GpuPrecomputeJob::State {
    struct Chunk {
        int step;             // index into stepNames
        std::string pass;     // debug group name
        double cost;          // estimated work, for progress()
        std::function<void()> run;
    };

    GpuTables tables;
    gl::Buffer uniforms;
    ProgressFn progress;
    std::vector<std::string> stepNames;
    std::vector<Chunk> chunks;
    std::size_t next = 0;
    double totalCost = 0.0, doneCost = 0.0;
    double stepSeconds = 0.0;
    std::vector<PrecomputeStep> steps;
    bool taken = false;
};

GpuPrecomputeJob::GpuPrecomputeJob(std::unique_ptr<State> state) : state_(std::move(state)) {}
GpuPrecomputeJob::GpuPrecomputeJob(GpuPrecomputeJob&&) noexcept = default;
GpuPrecomputeJob& GpuPrecomputeJob::operator=(GpuPrecomputeJob&&) noexcept = default;
GpuPrecomputeJob::~GpuPrecomputeJob() = default;

bool GpuPrecomputeJob::finished() const { return !state_ || state_->next >= state_->chunks.size(); }

double GpuPrecomputeJob::progress() const {
    if (!state_ || state_->totalCost <= 0.0) return 1.0;
    return std::clamp(state_->doneCost / state_->totalCost, 0.0, 1.0);
}

std::string GpuPrecomputeJob::currentStep() const {
    return finished() ? std::string() : state_->stepNames[static_cast<std::size_t>(state_->chunks[state_->next].step)];
}

const std::vector<PrecomputeStep>& GpuPrecomputeJob::steps() const {
    static const std::vector<PrecomputeStep> none;
    return state_ ? state_->steps : none;
}

bool GpuPrecomputeJob::step() {
    if (finished()) return true;
    State& s = *state_;
    const State::Chunk& chunk = s.chunks[s.next];
    const auto start = std::chrono::steady_clock::now();
    {
        gl::DebugGroup group("atmosphere precompute: " + chunk.pass);
        glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereUniformBinding, s.uniforms.id());
        chunk.run();
        glFinish();
    }
    s.stepSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    s.doneCost += chunk.cost;
    ++s.next;
    if (s.next == s.chunks.size() || s.chunks[s.next].step != chunk.step) {
        s.steps.push_back({s.stepNames[static_cast<std::size_t>(chunk.step)], s.stepSeconds});
        s.stepSeconds = 0.0;
        if (s.progress) s.progress(s.steps.back());
    }
    return finished();
}

GpuTables GpuPrecomputeJob::takeResult() {
    if (!finished() || !state_ || state_->taken) throw std::logic_error("GpuPrecomputeJob::takeResult: no finished result");
    state_->taken = true;
    return std::move(state_->tables);
}

// ----------------------------------------------------------- precompute

namespace {

gl::Program buildPass(const std::filesystem::path& root, const TableSizes& sizes, const char* name,
                      const char* file) {
    return gl::buildProgram(gl::ShaderSources{root, gl::shaderPreamble() + atmosphereShaderDefines(sizes)},
                            gl::ProgramDesc{name, {file}});
}

}  // namespace

GpuPrecompute::GpuPrecompute(const std::filesystem::path& shaderRoot, const TableSizes& sizes)
    : sizes_((checkScatteringNuSize(sizes), sizes)),
      transmittance_(buildPass(shaderRoot, sizes, "atmosphere transmittance", "atmosphere/precompute/transmittance.comp")),
      directIrradiance_(buildPass(shaderRoot, sizes, "atmosphere direct irradiance",
                                  "atmosphere/precompute/direct_irradiance.comp")),
      singleScattering_(buildPass(shaderRoot, sizes, "atmosphere single scattering",
                                  "atmosphere/precompute/single_scattering.comp")),
      scatteringDensity_(buildPass(shaderRoot, sizes, "atmosphere scattering density",
                                   "atmosphere/precompute/scattering_density.comp")),
      indirectIrradiance_(buildPass(shaderRoot, sizes, "atmosphere indirect irradiance",
                                    "atmosphere/precompute/indirect_irradiance.comp")),
      multipleScattering_(buildPass(shaderRoot, sizes, "atmosphere multiple scattering",
                                    "atmosphere/precompute/multiple_scattering.comp")),
      elekTable_(buildPass(shaderRoot, sizes, "atmosphere Elek 3D table", "atmosphere/precompute/elek_table.comp")),
      deltaIrradiance_(makeTable2D(sizes.irradiance_width, sizes.irradiance_height, "atmosphere delta irradiance")),
      deltaRayleigh_(makeTable3D(sizes.scatteringSize(), "atmosphere delta Rayleigh")),
      deltaMie_(makeTable3D(sizes.scatteringSize(), "atmosphere delta Mie")),
      deltaMultiple_(makeTable3D(sizes.scatteringSize(), "atmosphere delta multiple")),
      deltaDensity_(makeTable3D(sizes.scatteringSize(), "atmosphere delta scattering density")) {}

GpuPrecomputeJob GpuPrecompute::start(const AtmosphereParameters& atmosphere, int scatteringOrders,
                                      const ProgressFn& progress, int layersPerChunk, bool elekTable) {
    if (layersPerChunk < 1) throw std::invalid_argument("GpuPrecompute::start: layersPerChunk must be >= 1");
    auto state = std::make_unique<GpuPrecomputeJob::State>();
    GpuPrecomputeJob::State& s = *state;
    s.progress = progress;
    s.tables = makeGpuTables(sizes_);
    const AtmosphereUniforms u = makeAtmosphereUniforms(atmosphere);
    glNamedBufferStorage(s.uniforms.id(), sizeof u, &u, 0);
    s.uniforms.label("atmosphere precompute parameters");
    // Deterministic start: delta multiple is bound (never read) at order 2.
    for (const gl::Texture* t : {&deltaIrradiance_, &deltaRayleigh_, &deltaMie_, &deltaMultiple_, &deltaDensity_})
        clearTable(*t);

    const TableSizes& sz = sizes_;
    const glm::ivec3 size3 = sz.scatteringSize();
    const double texels3 = double(size3.x) * size3.y;  // per layer
    GpuTables* out = &s.tables;  // stable: State lives on the heap

    auto addStep = [&](std::string name) {
        s.stepNames.push_back(std::move(name));
        return static_cast<int>(s.stepNames.size()) - 1;
    };
    auto add2D = [&](int step, std::string pass, double cost, std::function<void()> run) {
        s.chunks.push_back({step, std::move(pass), cost, std::move(run)});
    };
    // A 3D pass as chunks of layers; `bind` sets the program and its inputs and outputs.
    auto add3D = [&](int step, const std::string& pass, double costPerTexel, GLuint program,
                     std::function<void()> bind) {
        for (int first = 0; first < size3.z; first += layersPerChunk) {
            const int count = std::min(layersPerChunk, size3.z - first);
            s.chunks.push_back({step, pass, costPerTexel * texels3 * count, [=] {
                                    bind();
                                    dispatch3D(program, size3, first, count);
                                }});
        }
    };

    const int transmittanceStep = addStep("transmittance");
    add2D(transmittanceStep, "transmittance",
          kTransmittanceCost * sz.transmittance_width * sz.transmittance_height, [this, out] {
              glUseProgram(transmittance_.id());
              bindImage2D(0, out->transmittance, GL_WRITE_ONLY);
              dispatch2D(sizes_.transmittance_width, sizes_.transmittance_height);
          });

    const int directStep = addStep("direct irradiance");
    add2D(directStep, "direct irradiance", kDirectIrradianceCost * sz.irradiance_width * sz.irradiance_height,
          [this, out] {
              glUseProgram(directIrradiance_.id());
              glBindTextureUnit(kTransmittanceUnit, out->transmittance.id());
              bindImage2D(0, deltaIrradiance_, GL_WRITE_ONLY);
              dispatch2D(sizes_.irradiance_width, sizes_.irradiance_height);
          });

    const int singleStep = addStep("single scattering");
    add3D(singleStep, "single scattering", kSingleScatteringCost, singleScattering_.id(), [this, out] {
        glUseProgram(singleScattering_.id());
        glBindTextureUnit(kTransmittanceUnit, out->transmittance.id());
        bindImage3D(0, deltaRayleigh_, GL_WRITE_ONLY);
        bindImage3D(1, deltaMie_, GL_WRITE_ONLY);
        bindImage3D(2, out->scattering, GL_WRITE_ONLY);
        bindImage3D(3, out->singleMie, GL_WRITE_ONLY);
    });

    for (int order = 2; order <= scatteringOrders; ++order) {
        const std::string name = "order " + std::to_string(order);
        const int orderStep = addStep(name);
        add3D(orderStep, name + " scattering density", kScatteringDensityCost, scatteringDensity_.id(),
              [this, out, order] {
                  glUseProgram(scatteringDensity_.id());
                  glProgramUniform1i(scatteringDensity_.id(), kScatteringOrderLocation, order);
                  glBindTextureUnit(kTransmittanceUnit, out->transmittance.id());
                  glBindTextureUnit(kDeltaRayleighUnit, deltaRayleigh_.id());
                  glBindTextureUnit(kDeltaMieUnit, deltaMie_.id());
                  glBindTextureUnit(kDeltaMultipleUnit, deltaMultiple_.id());
                  glBindTextureUnit(kDeltaIrradianceUnit, deltaIrradiance_.id());
                  bindImage3D(0, deltaDensity_, GL_WRITE_ONLY);
              });
        add2D(orderStep, name + " indirect irradiance",
              kIndirectIrradianceCost * sz.irradiance_width * sz.irradiance_height, [this, out, order] {
                  glUseProgram(indirectIrradiance_.id());
                  glProgramUniform1i(indirectIrradiance_.id(), kScatteringOrderLocation, order - 1);
                  glBindTextureUnit(kDeltaRayleighUnit, deltaRayleigh_.id());
                  glBindTextureUnit(kDeltaMieUnit, deltaMie_.id());
                  glBindTextureUnit(kDeltaMultipleUnit, deltaMultiple_.id());
                  bindImage2D(0, deltaIrradiance_, GL_WRITE_ONLY);
                  bindImage2D(1, out->irradiance, GL_READ_WRITE);
                  dispatch2D(sizes_.irradiance_width, sizes_.irradiance_height);
              });
        add3D(orderStep, name + " multiple scattering", kMultipleScatteringCost, multipleScattering_.id(),
              [this, out] {
                  glUseProgram(multipleScattering_.id());
                  glBindTextureUnit(kTransmittanceUnit, out->transmittance.id());
                  glBindTextureUnit(kDeltaDensityUnit, deltaDensity_.id());
                  bindImage3D(0, deltaMultiple_, GL_WRITE_ONLY);
                  bindImage3D(1, out->scattering, GL_READ_WRITE);
              });
    }
    if (elekTable) {
        // Reads the finished 4D tables (scattering, single Mie), so it comes last.
        const int elekStep = addStep("Elek 3D table");
        const glm::ivec3 elekSize = sz.elekSize();
        const GLuint program = elekTable_.id();
        for (int first = 0; first < elekSize.z; first += layersPerChunk) {
            const int count = std::min(layersPerChunk, elekSize.z - first);
            s.chunks.push_back({elekStep, "Elek 3D table", kElekTableCost * elekSize.x * elekSize.y * count,
                                [program, out, first, count] { dispatchElekTable(program, *out, first, count); }});
        }
    }
    for (const GpuPrecomputeJob::State::Chunk& c : s.chunks) s.totalCost += c.cost;
    return GpuPrecomputeJob(std::move(state));
}

void GpuPrecompute::computeElekTable(const AtmosphereParameters& atmosphere, const GpuTables& tables) {
    if (!(tables.sizes == sizes_)) throw std::invalid_argument("GpuPrecompute::computeElekTable: table sizes differ");
    gl::Buffer uniforms;
    const AtmosphereUniforms u = makeAtmosphereUniforms(atmosphere);
    glNamedBufferStorage(uniforms.id(), sizeof u, &u, 0);
    gl::DebugGroup group("atmosphere precompute: Elek 3D table");
    glBindBufferBase(GL_UNIFORM_BUFFER, kAtmosphereUniformBinding, uniforms.id());
    dispatchElekTable(elekTable_.id(), tables, 0, sizes_.elek_r);
    glFinish();
}

GpuTables GpuPrecompute::compute(const AtmosphereParameters& atmosphere, int scatteringOrders,
                                 const ProgressFn& progress, bool elekTable) {
    // Whole 3D passes per chunk: nothing else needs the GPU in between.
    GpuPrecomputeJob job =
        start(atmosphere, scatteringOrders, progress, std::max(sizes_.scattering_r, sizes_.elek_r), elekTable);
    while (!job.step()) {
    }
    return job.takeResult();
}

}  // namespace planet::atmosphere
