// Elek's 3D scattering table (Elek 2009, §4.1.1-4.1.2): a second, smaller
// parametrization of the same precomputed sky, chosen at render time with the
// preset's atmosphere.elek_3d_table.
//
// The table drops Bruneton's fourth axis (the sun-view azimuth, through nu)
// and keeps (altitude, view zenith, sun zenith) with Elek's remapping; the
// phase functions are applied per fragment with the real nu. Its texels are
// the 4D tables looked up at azimuth 0, so it costs one short pass after the
// 4D precomputation (GpuPrecompute's "Elek 3D table" step on the GPU,
// computeElekTables() here on the CPU). The shared math is in
// shaders/atmosphere/elek_table.glsl, compiled into Model (model.h).
//
//   memory (full sizes, RGBA32F): 4D scattering + single Mie 32 MiB, Elek 4 MiB;
//   transmittance (256 KiB) and irradiance (16 KiB) are shared by both.
//   error: compareElekWith4D() measures it over a grid of views (README, Presets).
#pragma once

#include <cstddef>
#include <string>

#include "atmosphere/model.h"
#include "atmosphere/precompute_gpu.h"
#include "atmosphere/tables.h"

namespace planet::atmosphere {

// Elek's two tables, both sizes.elekSize() = (mu_s, mu, r), phase-free:
// scattering rgb = Rayleigh + multiple orders, singleMie rgb = single Mie (a = 1).
struct ElekTables {
    TableSizes sizes;
    Table3D scattering;
    Table3D singleMie;
};

// CPU build (double, by Model) from finished 4D tables.
ElekTables computeElekTables(const AtmosphereParameters& atmosphere, const AtmosphereTables& tables);

// GPU textures <-> CPU tables (GpuTables::elekScattering, elekSingleMie).
ElekTables readBackElek(const GpuTables& tables);
void uploadElek(const ElekTables& elek, const GpuTables& tables);

// Bytes as RGBA32F textures: the 4D scattering + single Mie tables, Elek's two
// tables, and the transmittance + irradiance tables both parametrizations use.
std::size_t scattering4DBytes(const TableSizes& sizes);
std::size_t elekBytes(const TableSizes& sizes);
std::size_t sharedTableBytes(const TableSizes& sizes);

// Sky radiance (GetSkyRadiance vs GetSkyRadianceElek, CPU, sun disc excluded)
// over a grid: camera altitudes 0, 1, 10, 50 km; sun zenith 0..100 deg by 10;
// view zenith 0..180 deg by 10; view azimuth relative to the sun 0..180 deg by 15.
// Error of a sample: the largest over R, G, B of |elek - 4D| / max(4D, floor),
// floor = 1e-3 x the largest 4D radiance of the grid (night and ground-hitting
// rays count in absolute terms).
struct ElekComparison {
    std::size_t bytes4D = 0;      // 4D scattering + single Mie
    std::size_t bytesElek = 0;    // Elek scattering + single Mie
    std::size_t bytesShared = 0;  // transmittance + irradiance, needed by both
    int samples = 0;
    double meanRelativeError = 0.0;
    double maxRelativeError = 0.0;
    double meanRelativeErrorAzimuth0 = 0.0;    // views in the sun's vertical half-plane (omega = 0)
    double meanRelativeErrorAzimuth180 = 0.0;  // views in the opposite half-plane
    // Where the largest error is.
    double worstAltitudeKm = 0.0, worstSunZenithDeg = 0.0, worstViewZenithDeg = 0.0, worstAzimuthDeg = 0.0;
};

ElekComparison compareElekWith4D(const AtmosphereParameters& atmosphere, const AtmosphereTables& tables,
                                 const ElekTables& elek);

// A few lines for a command's output (memory and error).
std::string describeElekComparison(const ElekComparison& c);

}  // namespace planet::atmosphere
