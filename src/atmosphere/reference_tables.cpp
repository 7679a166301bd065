#include "atmosphere/reference_tables.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace planet::atmosphere {

namespace {

// Runs fn(i) for i in [0, count) on `threads` threads (rows are independent).
template <class Fn>
void parallelFor(int count, int threads, const Fn& fn) {
    std::atomic<int> next{0};
    auto worker = [&] {
        for (int i = next++; i < count; i = next++) fn(i);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
}

// Calls fn(x, y, z, fragCoord) for every texel of a 3D table, one z-y row per task.
template <class Fn>
void forEachTexel(const Table3D& t, int threads, const Fn& fn) {
    parallelFor(t.depth * t.height, threads, [&](int row) {
        const int z = row / t.height, y = row % t.height;
        for (int x = 0; x < t.width; ++x) fn(x, y, z, glm::dvec3(x + 0.5, y + 0.5, z + 0.5));
    });
}

template <class Fn>
void forEachTexel(const Table2D& t, int threads, const Fn& fn) {
    parallelFor(t.height, threads, [&](int y) {
        for (int x = 0; x < t.width; ++x) fn(x, y, glm::dvec2(x + 0.5, y + 0.5));
    });
}

double meanRgb(const Table3D& t) {
    double sum = 0.0;
    for (const glm::dvec4& v : t.texels) sum += (v.r + v.g + v.b) / 3.0;
    return t.texels.empty() ? 0.0 : sum / static_cast<double>(t.texels.size());
}

constexpr double kPi = 3.14159265358979323846;

class StepTimer {
public:
    StepTimer(std::vector<PrecomputeStep>& steps, const ProgressFn& progress) : steps_(steps), progress_(progress) {}
    template <class Fn>
    void run(const std::string& name, const Fn& fn) {
        const auto start = std::chrono::steady_clock::now();
        fn();
        steps_.push_back({name, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
        if (progress_) progress_(steps_.back());
    }

private:
    std::vector<PrecomputeStep>& steps_;
    const ProgressFn& progress_;
};

}  // namespace

void checkScatteringNuSize(const TableSizes& sizes) {
    if (sizes.scattering_nu < 1 || sizes.scattering_nu > kMaxScatteringNuSize)
        throw std::invalid_argument("atmosphere tables: scattering_nu must be in [1, " +
                                    std::to_string(kMaxScatteringNuSize) + "], got " +
                                    std::to_string(sizes.scattering_nu));
}

ReferenceResult computeReferenceTables(const AtmosphereParameters& atmosphere, const TableSizes& sizes,
                                       int scatteringOrders, const ProgressFn& progress, int threads) {
    checkScatteringNuSize(sizes);
    if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    Model model(sizes, /*precompute=*/true);
    ReferenceResult result;
    result.tables = AtmosphereTables(sizes);
    AtmosphereTables& out = result.tables;

    Table2D deltaIrradiance(sizes.irradiance_width, sizes.irradiance_height);
    Table3D deltaRayleigh(sizes.scatteringSize());
    Table3D deltaMie(sizes.scatteringSize());
    Table3D deltaMultiple(sizes.scatteringSize());
    Table3D deltaDensity(sizes.scatteringSize());
    StepTimer timer(result.steps, progress);

    timer.run("transmittance", [&] {
        forEachTexel(out.transmittance, threads, [&](int x, int y, glm::dvec2 f) {
            out.transmittance.at(x, y) = glm::dvec4(model.ComputeTransmittanceToTopAtmosphereBoundaryTexture(atmosphere, f), 1.0);
        });
    });
    timer.run("direct irradiance", [&] {
        forEachTexel(deltaIrradiance, threads, [&](int x, int y, glm::dvec2 f) {
            deltaIrradiance.at(x, y) =
                glm::dvec4(model.ComputeDirectIrradianceTexture(atmosphere, out.transmittance, f), 1.0);
        });
    });
    timer.run("single scattering", [&] {
        forEachTexel(deltaRayleigh, threads, [&](int x, int y, int z, glm::dvec3 f) {
            glm::dvec3 rayleigh, mie;
            model.ComputeSingleScatteringTexture(atmosphere, out.transmittance, f, rayleigh, mie);
            deltaRayleigh.at(x, y, z) = glm::dvec4(rayleigh, 1.0);
            deltaMie.at(x, y, z) = glm::dvec4(mie, 1.0);
            out.scattering.at(x, y, z) = glm::dvec4(rayleigh, mie.r);
            out.singleMie.at(x, y, z) = glm::dvec4(mie, 1.0);
        });
    });
    // Single scattering's mean radiance over all directions: phase functions average to 1 / (4 pi).
    result.orderMeans.push_back((meanRgb(deltaRayleigh) + meanRgb(deltaMie)) / (4.0 * kPi));

    for (int order = 2; order <= scatteringOrders; ++order) {
        timer.run("order " + std::to_string(order), [&] {
            forEachTexel(deltaDensity, threads, [&](int x, int y, int z, glm::dvec3 f) {
                deltaDensity.at(x, y, z) = glm::dvec4(
                    model.ComputeScatteringDensityTexture(atmosphere, out.transmittance, deltaRayleigh, deltaMie,
                                                          deltaMultiple, deltaIrradiance, f, order),
                    1.0);
            });
            forEachTexel(deltaIrradiance, threads, [&](int x, int y, glm::dvec2 f) {
                const glm::dvec3 e = model.ComputeIndirectIrradianceTexture(atmosphere, deltaRayleigh, deltaMie,
                                                                            deltaMultiple, f, order - 1);
                deltaIrradiance.at(x, y) = glm::dvec4(e, 1.0);
                out.irradiance.at(x, y) += glm::dvec4(e, 0.0);
            });
            Table3D next(sizes.scatteringSize());
            forEachTexel(next, threads, [&](int x, int y, int z, glm::dvec3 f) {
                double nu = 0.0;
                const glm::dvec3 radiance =
                    model.ComputeMultipleScatteringTexture(atmosphere, out.transmittance, deltaDensity, f, nu);
                next.at(x, y, z) = glm::dvec4(radiance, 1.0);
                out.scattering.at(x, y, z) += glm::dvec4(radiance / model.RayleighPhaseFunction(nu), 0.0);
            });
            deltaMultiple = std::move(next);
        });
        result.orderMeans.push_back(meanRgb(deltaMultiple));
    }
    return result;
}

}  // namespace planet::atmosphere
