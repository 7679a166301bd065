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

// The four tables as RGBA32F textures, GL_LINEAR, GL_CLAMP_TO_EDGE, labelled.
struct GpuTables {
    TableSizes sizes;
    gl::Texture transmittance{GL_TEXTURE_2D};
    gl::Texture scattering{GL_TEXTURE_3D};
    gl::Texture singleMie{GL_TEXTURE_3D};
    gl::Texture irradiance{GL_TEXTURE_2D};
};

// Allocates the four tables (contents zero).
GpuTables makeGpuTables(const TableSizes& sizes);
// glGetTextureImage into double tables (tests, the disk cache).
AtmosphereTables readBack(const GpuTables& tables);
// The reverse: textures from CPU tables (loading from a cache).
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
    // Builds the six programs (preamble: shaderPreamble() + atmosphereShaderDefines(sizes))
    // and allocates the delta tables. Throws gl::ShaderError.
    GpuPrecompute(const std::filesystem::path& shaderRoot, const TableSizes& sizes);
    GpuPrecompute(const GpuPrecompute&) = delete;
    GpuPrecompute& operator=(const GpuPrecompute&) = delete;

    const TableSizes& sizes() const { return sizes_; }

    // Starts an incremental precomputation; `layersPerChunk` r layers of the
    // 3D passes per step() (>= 1). `progress` is called after each named step.
    GpuPrecomputeJob start(const AtmosphereParameters& atmosphere, int scatteringOrders,
                           const ProgressFn& progress = {}, int layersPerChunk = 4);

    // The whole precomputation, blocking. Calls `progress` after each step
    // ("transmittance", "direct irradiance", "single scattering", "order 2", ...).
    GpuTables compute(const AtmosphereParameters& atmosphere, int scatteringOrders, const ProgressFn& progress = {});

private:
    TableSizes sizes_;
    gl::Program transmittance_, directIrradiance_, singleScattering_, scatteringDensity_, indirectIrradiance_,
        multipleScattering_;
    // Temporary tables, as in the reference.
    gl::Texture deltaIrradiance_{GL_TEXTURE_2D};
    gl::Texture deltaRayleigh_{GL_TEXTURE_3D};
    gl::Texture deltaMie_{GL_TEXTURE_3D};
    gl::Texture deltaMultiple_{GL_TEXTURE_3D};
    gl::Texture deltaDensity_{GL_TEXTURE_3D};
};

}  // namespace planet::atmosphere
