// Continents: a cube map of elevation baked from fBm simplex noise, and its cache.
//
// Michelic §6 bakes the continents into a 1024^2 longitude-latitude map; a cube map
// has no pole singularity and spends texels far more evenly (a texel's solid angle
// varies by a factor 3*sqrt(3) ~ 5.2 over a face, against an unbounded ratio near a
// lat-long pole), so that is what we bake. The GPU samples it as a samplerCube; the
// CPU reaches the same values through sampleContinents().
//
// Layout. Six square faces of `size` x `size` floats in OpenGL's order and orientation
// (GL 4.5 spec, Table 8.19): face 0..5 = GL_TEXTURE_CUBE_MAP_POSITIVE_X, NEGATIVE_X,
// POSITIVE_Y, NEGATIVE_Y, POSITIVE_Z, NEGATIVE_Z; texel (x, y) of a face has s = (x +
// 0.5) / size, t = (y + 0.5) / size, and row y is the y-th row handed to glTexImage2D
// (texels[(face * size + y) * size + x]), so uploading face f from &texel(f, 0, 0)
// puts every texel where the GPU looks for it.
//
// Values. Elevation in [-1, 1], negative = ocean: fbm(frequency * direction + offset(seed))
// shifted so that exactly seaFraction of the sphere's *solid angle* (each texel
// weighted by the solid angle it subtends, not by count) is below 0, then each side
// scaled so that the deepest texel is -1 and the highest +1 (the sign, and so the
// coastline, is unchanged by the scaling). The achieved fraction differs from the
// requested one by at most one texel's solid angle (<= 1 / (pi size^2) of the sphere,
// the centre texel's).
//
// Cache: one folder <root>/<key>/ holding continents.exr (one FLOAT channel "Y",
// width size, height 6 size: the faces stacked top to bottom in face order, row 0 =
// face 0 row 0) and key.txt (key, version, size, parameters, checksum of the EXR
// bytes). The key hashes the parameters, the size, kContinentsVersion and a
// fingerprint of the noise function itself, so a change of the noise code alone
// invalidates old entries. Written to a temporary folder and renamed into place;
// loadContinents() trusts nothing (see there).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace planet::noise {

// Bump when the bake (not the noise: that is fingerprinted) changes what it produces.
constexpr int kContinentsVersion = 1;

struct ContinentParams {
    int seed = 1;              // any int; picks an offset of the noise domain
    double frequency = 1.5;    // noise cycles per planet radius, (0, 1000]
    int octaves = 6;           // fBm octaves, [1, 10]
    double seaFraction = 0.6;  // fraction of the surface (by solid angle) under water, [0, 1]
};

struct CubeMap {
    int size = 0;               // face width = height, texels
    std::vector<float> texels;  // 6 * size * size, index (face * size + y) * size + x

    float& at(int face, int x, int y) { return texels[index(face, x, y)]; }
    float at(int face, int x, int y) const { return texels[index(face, x, y)]; }
    std::size_t index(int face, int x, int y) const {
        return (static_cast<std::size_t>(face) * static_cast<std::size_t>(size) + static_cast<std::size_t>(y)) *
                   static_cast<std::size_t>(size) +
               static_cast<std::size_t>(x);
    }
};

// Unit vector through the centre of texel (x, y) of `face` (0..5 = +X, -X, +Y, -Y, +Z, -Z)
// on a cube map of `size`, in OpenGL's convention: face centres are the six axes.
glm::dvec3 cubeTexelDirection(int face, int x, int y, int size);

// The face a direction falls on (largest |component|, as GL selects it; GL leaves ties
// to the implementation, here X wins over Y over Z) and its (s, t) in [0, 1]^2.
int cubeFaceOf(glm::dvec3 direction, double& s, double& t);

// Solid angle subtended by texel (x, y) of any face of a cube map of `size`, sr
// (the six faces sum to 4 pi).
double cubeTexelSolidAngle(int x, int y, int size);

// The value a samplerCube with GL_LINEAR filtering and GL_CLAMP_TO_EDGE returns for
// `direction` (need not be unit length, must not be zero) when seamless cube map
// filtering is OFF: bilinear within the selected face, texel coordinates clamped to
// the face. At a texel centre it returns that texel exactly. Seams: with
// GL_TEXTURE_CUBE_MAP_SEAMLESS on (the renderer's default) the GPU instead blends in the
// neighbouring face within half a texel of an edge; the two differ only there and by at
// most the difference between edge texels on the two faces, which are one texel apart
// on the sphere, so by the field's change over one texel (tests measure it).
float sampleContinents(const CubeMap& map, glm::dvec3 direction);

// Fraction of the sphere's solid angle whose texels are below 0.
double seaFractionOf(const CubeMap& map);

// Called with the fraction done in [0, 1], from the calling thread only.
using BakeProgress = std::function<void(double fraction)>;

// Bakes the continents (see the file header), on all cores. faceSize in [1, 8192];
// throws std::invalid_argument for that or a parameter out of its range.
CubeMap bakeContinents(const ContinentParams& params, int faceSize, const BakeProgress& progress = {});

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
// the EXR's checksum matches, OpenEXR reads it, its header key and size match and every
// texel is finite and in [-1, 1]; otherwise nullopt with the reason in *reason.
std::optional<CubeMap> loadContinents(const std::filesystem::path& dir, const std::string& expectedKey, int faceSize,
                                      std::string* reason = nullptr);

}  // namespace planet::noise
