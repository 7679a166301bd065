// Continents: a cube map of elevation and its gradient baked from fBm simplex noise, and
// its cache. The terrain's height function samples it (shaders/terrain/height.glsl).
//
// Michelic §6 bakes the continents into a 1024^2 longitude-latitude map; a cube map
// has no pole singularity and spends texels far more evenly (a texel's solid angle
// varies by a factor 3*sqrt(3) ~ 5.2 over a face, against an unbounded ratio near a
// lat-long pole), so that is what we bake. The GPU samples it as a samplerCube (GL_LINEAR,
// seamless cube map filtering on); the CPU reaches the same values through
// sampleContinents(), which mirrors that filtering, seams included.
//
// Layout. Six square faces of `size` x `size` texels in OpenGL's order and orientation
// (GL 4.5 spec, Table 8.19): face 0..5 = GL_TEXTURE_CUBE_MAP_POSITIVE_X, NEGATIVE_X,
// POSITIVE_Y, NEGATIVE_Y, POSITIVE_Z, NEGATIVE_Z; texel (x, y) of a face has s = (x +
// 0.5) / size, t = (y + 0.5) / size, and row y is the y-th row handed to glTexImage2D
// (texels[(face * size + y) * size + x]), so uploading face f from &texel(f, 0, 0)
// puts every texel where the GPU looks for it. A texel is four floats (GL_RGBA32F):
//   x      elevation e in [-1, 1], negative = ocean;
//   y z w  its gradient with respect to the direction as a point of R^3, tangential part
//          only (the radial part says nothing about the surface): de per radian along the
//          sphere. Baked from the noise's analytic gradient, so bilinear filtering
//          interpolates a smooth gradient, and normals from it show no texel facets, where
//          finite differences of the filtered elevation would be constant over each texel.
//
// Values. fbm(frequency * direction + seedOffset(seed, 0)) (noise/noise.h), shifted so
// that exactly seaFraction of the sphere's *solid angle* (each texel weighted by the
// solid angle it subtends, not by count) is below 0, then each side scaled so that the
// deepest texel is -1 and the highest +1 (the sign, and so the coastline, is unchanged
// by the scaling); the gradient gets the same side's scale. The achieved fraction differs
// from the requested one by at most one texel's solid angle (<= 1 / (pi size^2) of the
// sphere, the centre texel's).
//
// Cache: one folder <root>/<key>/ holding continents.exr (four FLOAT channels, "Y" the
// elevation and "dYdx", "dYdy", "dYdz" its gradient; width size, height 6 size: the faces
// stacked top to bottom in face order, row 0 = face 0 row 0) and key.txt (key, version,
// size, parameters, checksum of the EXR bytes). The key hashes the parameters, the size,
// kContinentsVersion and a fingerprint of the noise function itself, so a change of the
// noise code alone invalidates old entries. Written to a temporary folder and renamed
// into place; loadContinents() trusts nothing (see there).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "util/cache_entry.h"
#include "util/log.h"

namespace planet::noise {

// Bump when the bake (not the noise: that is fingerprinted) changes what it produces.
// 2: RGBA texels (elevation + gradient), the terrain's seed offsets.
constexpr int kContinentsVersion = 2;

// The defaults are TerrainParams' (terrain/terrain_params.h), so that `planet bake` with
// no options bakes the default planet's map.
struct ContinentParams {
    int seed = 1;              // any int; picks an offset of the noise domain
    double frequency = 1.5;    // noise cycles per planet radius, (0, 1000]
    int octaves = 6;           // fBm octaves, [1, 10]
    double seaFraction = 0.6;  // fraction of the surface (by solid angle) under water, [0, 1]
    bool operator==(const ContinentParams&) const = default;
};

// A cube map of `Texel`s on the CPU: CubeMap (the continents: elevation and its gradient,
// RGBA) and noise/weather_map.h's WeatherMap (coverage and type, two channels: half the memory
// of four at 1024 per face, 50 MB instead of 100).
template <class Texel>
struct CubeMapOf {
    int size = 0;                // face width = height, texels
    std::vector<Texel> texels;   // 6 * size * size, index (face * size + y) * size + x; see the header

    Texel& at(int face, int x, int y) { return texels[index(face, x, y)]; }
    const Texel& at(int face, int x, int y) const { return texels[index(face, x, y)]; }
    // The elevation of a texel (its x).
    float elevation(int face, int x, int y) const { return texels[index(face, x, y)].x; }
    std::size_t index(int face, int x, int y) const {
        return (static_cast<std::size_t>(face) * static_cast<std::size_t>(size) + static_cast<std::size_t>(y)) *
                   static_cast<std::size_t>(size) +
               static_cast<std::size_t>(x);
    }
};
using CubeMap = CubeMapOf<glm::vec4>;

// Unit vector through the centre of texel (x, y) of `face` (0..5 = +X, -X, +Y, -Y, +Z, -Z)
// on a cube map of `size`, in OpenGL's convention: face centres are the six axes.
glm::dvec3 cubeTexelDirection(int face, int x, int y, int size);

// The face a direction falls on (largest |component|, as GL selects it; GL leaves ties
// to the implementation, here X wins over Y over Z) and its (s, t) in [0, 1]^2.
int cubeFaceOf(glm::dvec3 direction, double& s, double& t);

// Solid angle subtended by texel (x, y) of any face of a cube map of `size`, sr
// (the six faces sum to 4 pi).
double cubeTexelSolidAngle(int x, int y, int size);

// What a samplerCube with GL_LINEAR filtering and GL_TEXTURE_CUBE_MAP_SEAMLESS on
// returns for `direction` (need not be unit length, must not be zero): bilinear on the
// face the direction selects, the taps that fall beyond the face's edge taken from the
// neighbouring face's texels along that edge (GL 4.5 §8.13.1), and a tap beyond a corner,
// where three faces meet and no texel exists, the mean of the other three taps (what the
// spec recommends; implementations may differ there, within half a texel of the 8 cube
// corners). So the result is continuous across face edges, and at a texel centre it is
// that texel exactly. Computed in double; GPUs filter in float with their own weight
// precision (often 8 fractional bits), which tests allow for.
glm::vec4 sampleContinents(const CubeMap& map, glm::dvec3 direction);
// The same filtering of a two-channel map (noise/weather_map.h's sampleWeather).
glm::vec2 sampleCubeMap(const CubeMapOf<glm::vec2>& map, glm::dvec3 direction);

// The texel (tapFace, x, y) that bilinear tap (i, j) of `face` reads with that filtering on a map
// of `size`: the face's own inside it; for a tap one texel beyond an edge, the neighbouring face's
// texel along that edge at the same place (GL 4.5 §8.13.1); false beyond a corner (no texel).
bool seamlessTap(int size, int face, int i, int j, int& tapFace, int& x, int& y);

// Fraction of the sphere's solid angle whose texels' elevation is below 0.
double seaFractionOf(const CubeMap& map);

// Called with the fraction done in [0, 1], from the calling thread only.
using BakeProgress = std::function<void(double fraction)>;

// Bakes the continents (see the file header), on all cores. faceSize in [1, 8192];
// throws std::invalid_argument for that or a parameter out of its range.
CubeMap bakeContinents(const ContinentParams& params, int faceSize, const BakeProgress& progress = {});

// Logs the bake's progress (logInfo, every 10 %) once it has run for a second; for bakes
// a user waits for.
BakeProgress logBakeProgress();
// logBakeProgress, and `progress` too when there is one.
BakeProgress alsoLogged(const BakeProgress& progress);

// The run-time flow of every baked cache (continents, cloud volume, weather map):
// util/cache_entry.h's loadOrMake with what a user is told: an unusable entry (logWarning,
// then rebaked), what is baked into where, the time when over a second, and a cache that
// could not be written (logWarning; the bake is used anyway).
template <class Load, class Bake, class Save>
auto loadOrBakeLogged(const std::string& what, const std::string& description, const std::filesystem::path& dir,
                      const Load& load, const Bake& bake, const Save& save) {
    CacheOutcome outcome;
    auto result = loadOrMake(
        dir, /*force=*/false, load, bake, save,
        [&](const CacheOutcome& o) {
            if (!o.rejected.empty()) logWarning(what + " cache " + quote(dir) + " is not usable, rebaking: " + o.rejected);
            logInfo("baking the " + what + " (" + description + ") into " + quote(dir));
        },
        &outcome);
    if (outcome.seconds > 1.0) logInfo("baked the " + what + " in " + std::to_string(outcome.seconds) + " s");
    if (!outcome.notSaved.empty()) logWarning(what + " not cached: " + outcome.notSaved);
    return result;
}

// 16 hex digits: FNV-1a of kContinentsVersion, a noise fingerprint, params and faceSize.
std::string continentsCacheKey(const ContinentParams& params, int faceSize);

// Cache root: cache/continents under the current directory; when $PLANET_CACHE is set
// (it replaces cache/atmosphere), its sibling folder "continents" instead.
std::filesystem::path defaultContinentsCacheRoot();

// Writes continents.exr and key.txt into `dir` atomically (temporary sibling folder,
// then rename; an existing entry is replaced). Throws FileError.
void saveContinents(const CubeMap& map, const ContinentParams& params, const std::filesystem::path& dir,
                    const std::string& key);

// The map stored in `dir` if key.txt names `expectedKey`, this version and `faceSize`,
// the EXR's checksum matches, OpenEXR reads it, its header key and size match, it has
// the four channels, and every elevation is in [-1, 1] and every gradient finite;
// otherwise nullopt with the reason in *reason.
std::optional<CubeMap> loadContinents(const std::filesystem::path& dir, const std::string& expectedKey, int faceSize,
                                      std::string* reason = nullptr);

// The map for these parameters at run time: from the cache under `root` when it holds a
// valid entry, else baked (with logBakeProgress) and saved there. An unusable entry is
// reported (logWarning) and rebaked; a cache that cannot be written is reported and the
// baked map used anyway. Throws std::invalid_argument for parameters out of range.
CubeMap loadOrBakeContinents(const ContinentParams& params, int faceSize, const std::filesystem::path& root);

}  // namespace planet::noise
