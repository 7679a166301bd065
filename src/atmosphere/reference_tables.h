// The CPU reference precomputation: every table of the model in double
// precision, multi-threaded, by the same functions the GPU runs.
//
// Steps (Bruneton's order, Elek §4.1): transmittance; direct irradiance;
// single scattering; then for each order k = 2..N: scattering density of
// order k, indirect irradiance of order k-1 (added to the irradiance table),
// multiple scattering of order k (added to the scattering table, divided by
// the Rayleigh phase so the table stays phase-free).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "atmosphere/model.h"
#include "atmosphere/tables.h"

namespace planet::atmosphere {

struct PrecomputeStep {
    std::string name;   // "transmittance", "single scattering", "order 2", ...
    double seconds = 0;
};

struct ReferenceResult {
    AtmosphereTables tables;
    std::vector<PrecomputeStep> steps;
    // Mean over the scattering table of each order's radiance (order 1 first,
    // phase-free single Rayleigh), to check that orders converge.
    std::vector<double> orderMeans;
};

using ProgressFn = std::function<void(const PrecomputeStep&)>;

// The most nu slices ComputeScatteringDensity (functions.glsl, MAX_NU_SIZE) holds
// for one ring of directions; both precomputations throw std::invalid_argument
// for a larger TableSizes::scattering_nu (or one under 1).
constexpr int kMaxScatteringNuSize = 16;
void checkScatteringNuSize(const TableSizes& sizes);

ReferenceResult computeReferenceTables(const AtmosphereParameters& atmosphere, const TableSizes& sizes,
                                       int scatteringOrders, const ProgressFn& progress = {}, int threads = 0);

}  // namespace planet::atmosphere
