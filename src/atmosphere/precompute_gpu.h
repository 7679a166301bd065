// The GPU precomputation of the atmosphere tables: Bruneton's passes as
// compute shaders (shaders/atmosphere/precompute/*.comp), in single precision.
//
// It follows computeReferenceTables() (reference_tables.cpp) step for step,
// with the same tables meaning the same things, so the two compare texel by
// texel (tests/test_atmosphere_gpu.cpp):
//
//   transmittance        -> transmittance
//   direct irradiance    -> delta irradiance (the irradiance table stays 0: sky light only)
//   single scattering    -> delta Rayleigh, delta Mie, scattering = (rayleigh, mie.r), single Mie
//   order k = 2..N       -> scattering density of order k (delta density),
//                           indirect irradiance of order k-1 (delta irradiance, += irradiance),
//                           multiple scattering of order k (delta multiple, += scattering / RayleighPhase)
//   Elek 3D table        -> elekScattering, elekSingleMie (optional last step, elek_table.glsl;
//                           CPU counterpart computeElekTables in elek_table.h)
//
// Work is cut into chunks (one 2D pass, or a few r layers of a 3D pass) so a
// window can run one chunk per frame (GpuPrecomputeJob::step) and stay
// responsive; compute() runs a job to the end. Every chunk binds everything it
// uses (programs, textures, images, the parameter UBO at binding 1), so other
// rendering may run between chunks. Each chunk ends with glFinish, which makes
// the step timings honest and bounds how much GPU work one frame queues.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "atmosphere/reference_tables.h"
#include "atmosphere/tables.h"
#include "gl/handle.h"
#include "gl/program.h"

namespace planet::atmosphere {

// The four tables as RGBA32F textures, GL_LINEAR, GL_CLAMP_TO_EDGE, labelled,
// plus Elek's two 3D tables (sizes.elekSize(), zero unless the precomputation
// was asked for them; see elek_table.h for their CPU side).
struct GpuTables {
    TableSizes sizes;
    gl::Texture transmittance{GL_TEXTURE_2D};
    gl::Texture scattering{GL_TEXTURE_3D};
    gl::Texture singleMie{GL_TEXTURE_3D};
    gl::Texture irradiance{GL_TEXTURE_2D};
    gl::Texture elekScattering{GL_TEXTURE_3D};
    gl::Texture elekSingleMie{GL_TEXTURE_3D};
};

// Allocates the six tables (contents zero).
GpuTables makeGpuTables(const TableSizes& sizes);
// glGetTextureImage of the four 4D-model tables into double tables (tests, the
// disk cache); readBackElek() in elek_table.h reads the Elek tables.
AtmosphereTables readBack(const GpuTables& tables);
// The texels of an RGBA32F texture (count of them), as doubles.
std::vector<glm::dvec4> readTexels(const gl::Texture& texture, std::size_t count);
// The reverse: textures from CPU tables (loading from a cache). The Elek
// tables stay zero; uploadElek() in elek_table.h fills them.
GpuTables upload(const AtmosphereTables& tables);

class GpuPrecompute;

// One precomputation in progress. Uses its GpuPrecompute's programs and delta
// tables, so that object must outlive the job, and runs one job at a time.
class GpuPrecomputeJob {
public:
    GpuPrecomputeJob(GpuPrecomputeJob&&) noexcept;
    GpuPrecomputeJob& operator=(GpuPrecomputeJob&&) noexcept;
    ~GpuPrecomputeJob();

    // Runs the next chunk (blocking until the GPU finished it). Returns true
    // when the whole precomputation is done (then further calls do nothing).
    bool step();
    bool finished() const;
    // Fraction of the estimated work done, in [0, 1].
    double progress() const;
    // Name of the step the next chunk belongs to ("" when finished).
    std::string currentStep() const;
    // Steps completed so far, with their GPU+CPU wall seconds.
    const std::vector<PrecomputeStep>& steps() const;
    // The finished tables; the job is empty afterwards. Requires finished().
    GpuTables takeResult();

private:
    friend class GpuPrecompute;
    struct State;
    explicit GpuPrecomputeJob(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

class GpuPrecompute {
public:
    // Builds the seven programs (preamble: shaderPreamble() + atmosphereShaderDefines(sizes))
    // and allocates the delta tables. Throws gl::ShaderError.
    GpuPrecompute(const std::filesystem::path& shaderRoot, const TableSizes& sizes);
    GpuPrecompute(const GpuPrecompute&) = delete;
    GpuPrecompute& operator=(const GpuPrecompute&) = delete;

    const TableSizes& sizes() const { return sizes_; }

    // Starts an incremental precomputation; `layersPerChunk` r layers of the
    // 3D passes per step() (>= 1). `progress` is called after each named step.
    // With `elekTable`, a last step "Elek 3D table" fills the Elek tables from
    // the finished 4D tables (off by default: the model's own steps only).
    GpuPrecomputeJob start(const AtmosphereParameters& atmosphere, int scatteringOrders,
                           const ProgressFn& progress = {}, int layersPerChunk = 4, bool elekTable = false);

    // The whole precomputation, blocking. Calls `progress` after each step
    // ("transmittance", "direct irradiance", "single scattering", "order 2", ...,
    // then "Elek 3D table" with `elekTable`).
    GpuTables compute(const AtmosphereParameters& atmosphere, int scatteringOrders, const ProgressFn& progress = {},
                      bool elekTable = false);

    // Only the "Elek 3D table" step, blocking, on tables whose 4D part is done
    // (e.g. just uploaded from the disk cache, which stores the 4D tables only).
    void computeElekTable(const AtmosphereParameters& atmosphere, const GpuTables& tables);

private:
    TableSizes sizes_;
    gl::Program transmittance_, directIrradiance_, singleScattering_, scatteringDensity_, indirectIrradiance_,
        multipleScattering_, elekTable_;
    // Temporary tables, as in the reference.
    gl::Texture deltaIrradiance_{GL_TEXTURE_2D};
    gl::Texture deltaRayleigh_{GL_TEXTURE_3D};
    gl::Texture deltaMie_{GL_TEXTURE_3D};
    gl::Texture deltaMultiple_{GL_TEXTURE_3D};
    gl::Texture deltaDensity_{GL_TEXTURE_3D};
};

}  // namespace planet::atmosphere
