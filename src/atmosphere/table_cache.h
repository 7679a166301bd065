// The atmosphere tables on disk: a cache keyed by everything they depend on.
//
// Layout of one cache entry, a folder <root>/<key>/:
//
//   transmittance.exr   2D, width x height
//   scattering.exr      3D laid out as a 2D image of width x (height * depth): slice z is rows [z*h, (z+1)*h)
//   single_mie.exr      same
//   irradiance.exr      2D
//   key.txt             the key, model version, sizes, and a checksum of each EXR file's bytes
//
// Every EXR is FLOAT RGBA (the GPU textures are RGBA32F, so nothing is lost),
// row 0 = texel row 0, with the key and sizes in header attributes
// (planetTableKey, planetTableSizes). The key (tableCacheKey) is a 64-bit
// FNV-1a hash over every model parameter, every table size, the number of
// scattering orders and kModelVersion, so a change of any of them picks
// another folder. An entry is written into a temporary folder and renamed into
// place, so readers never see half of one.
//
// loadTables() trusts nothing: a missing file, a checksum or header mismatch, a
// file OpenEXR cannot read, a wrong size, another key or a NaN / Inf texel each
// make it return nullopt with the reason, and the caller recomputes.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "atmosphere/model.h"
#include "atmosphere/tables.h"

namespace planet::atmosphere {

// Bump whenever the model's code (shaders/atmosphere/*.glsl, the precompute
// passes) changes what the tables hold: older cache entries then stop matching.
constexpr int kModelVersion = 2;  // 2: exponential quadrature along rays, the air's top cut where it ends

// 16 lower-case hex digits of a 64-bit FNV-1a hash of the parameters (each
// double field by field), the sizes, the orders and kModelVersion.
// `modelSource` (atmosphereModelSource()) is hashed too, so editing the model's
// shaders makes old entries stop matching even when kModelVersion was not bumped.
std::string tableCacheKey(const AtmosphereParameters& atmosphere, const TableSizes& sizes, int scatteringOrders,
                          const std::string& modelSource = {});

// The text of the files the tables are computed from: atmosphere/definitions.glsl,
// atmosphere/functions.glsl and atmosphere/precompute/*.comp under the shaders root.
std::string atmosphereModelSource(const std::filesystem::path& shaderRoot);

// Where cache entries live: $PLANET_CACHE if set and not empty, else
// cache/atmosphere under the current directory.
std::filesystem::path defaultTableCacheRoot();

// Writes the four tables and key.txt into `dir` (created; an existing entry
// there is replaced) atomically: everything goes to a temporary sibling
// folder first, which is then renamed to `dir`. Throws FileError.
void saveTables(const AtmosphereTables& tables, const std::filesystem::path& dir, const std::string& key);

// The tables stored in `dir` if they are complete, intact, of `sizes` and
// keyed `expectedKey`; otherwise nullopt, with the reason in *reason when given.
std::optional<AtmosphereTables> loadTables(const std::filesystem::path& dir, const std::string& expectedKey,
                                           const TableSizes& sizes, std::string* reason = nullptr);

}  // namespace planet::atmosphere
