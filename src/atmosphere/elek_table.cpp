#include "atmosphere/elek_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace planet::atmosphere {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kTexelBytes = 4 * sizeof(float);  // RGBA32F

std::size_t texels(glm::ivec3 s) { return static_cast<std::size_t>(s.x) * s.y * s.z; }


void writeTexels(const gl::Texture& t, const Table3D& table) {
    std::vector<float> floats(table.texels.size() * 4);
    for (std::size_t i = 0; i < table.texels.size(); ++i)
        for (int c = 0; c < 4; ++c) floats[4 * i + c] = static_cast<float>(table.texels[i][c]);
    glTextureSubImage3D(t.id(), 0, 0, 0, 0, table.width, table.height, table.depth, GL_RGBA, GL_FLOAT, floats.data());
}

}  // namespace

ElekTables computeElekTables(const AtmosphereParameters& atmosphere, const AtmosphereTables& tables) {
    const TableSizes& sizes = tables.sizes;
    Model model(sizes);
    ElekTables elek{sizes, Table3D(sizes.elekSize()), Table3D(sizes.elekSize())};
    for (int z = 0; z < elek.scattering.depth; ++z)
        for (int y = 0; y < elek.scattering.height; ++y)
            for (int x = 0; x < elek.scattering.width; ++x) {
                glm::dvec3 mie;
                const glm::dvec3 scattering = model.ComputeElekTableTexture(
                    atmosphere, tables.scattering, tables.singleMie, glm::dvec3(x + 0.5, y + 0.5, z + 0.5), mie);
                elek.scattering.at(x, y, z) = glm::dvec4(scattering, 1.0);
                elek.singleMie.at(x, y, z) = glm::dvec4(mie, 1.0);
            }
    return elek;
}

ElekTables readBackElek(const GpuTables& tables) {
    ElekTables elek{tables.sizes, Table3D(tables.sizes.elekSize()), Table3D(tables.sizes.elekSize())};
    elek.scattering.texels = readTexels(tables.elekScattering, elek.scattering.texels.size());
    elek.singleMie.texels = readTexels(tables.elekSingleMie, elek.singleMie.texels.size());
    return elek;
}

void uploadElek(const ElekTables& elek, const GpuTables& tables) {
    if (!(elek.sizes == tables.sizes)) throw std::invalid_argument("uploadElek: table sizes differ");
    writeTexels(tables.elekScattering, elek.scattering);
    writeTexels(tables.elekSingleMie, elek.singleMie);
}

std::size_t scattering4DBytes(const TableSizes& s) { return 2 * kTexelBytes * texels(s.scatteringSize()); }
std::size_t elekBytes(const TableSizes& s) { return 2 * kTexelBytes * texels(s.elekSize()); }
std::size_t sharedTableBytes(const TableSizes& s) {
    return kTexelBytes * (static_cast<std::size_t>(s.transmittance_width) * s.transmittance_height +
                          static_cast<std::size_t>(s.irradiance_width) * s.irradiance_height);
}

ElekComparison compareElekWith4D(const AtmosphereParameters& atmosphere, const AtmosphereTables& tables,
                                 const ElekTables& elek) {
    if (!(elek.sizes == tables.sizes)) throw std::invalid_argument("compareElekWith4D: table sizes differ");
    Model model(tables.sizes);
    struct Sample {
        double altitudeKm, sunZenithDeg, viewZenithDeg, azimuthDeg;
        glm::dvec3 ref, elek;
    };
    std::vector<Sample> samples;
    const double deg = kPi / 180.0;
    for (double altitudeKm : {0.0, 1.0, 10.0, 50.0}) {
        const glm::dvec3 camera(0.0, 0.0, atmosphere.bottom_radius + altitudeKm);
        for (int sunZenith = 0; sunZenith <= 100; sunZenith += 10) {
            const glm::dvec3 sun(std::sin(sunZenith * deg), 0.0, std::cos(sunZenith * deg));
            for (int viewZenith = 0; viewZenith <= 180; viewZenith += 10) {
                for (int azimuth = 0; azimuth <= 180; azimuth += 15) {
                    const double t = viewZenith * deg, p = azimuth * deg;
                    const glm::dvec3 view(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
                    glm::dvec3 transmittance;
                    const glm::dvec3 ref = model.GetSkyRadiance(atmosphere, tables.transmittance, tables.scattering,
                                                                tables.singleMie, camera, view, sun, transmittance);
                    const glm::dvec3 e = model.GetSkyRadianceElek(atmosphere, tables.transmittance, elek.scattering,
                                                                  elek.singleMie, camera, view, sun, transmittance);
                    samples.push_back({altitudeKm, double(sunZenith), double(viewZenith), double(azimuth), ref, e});
                }
            }
        }
    }

    double largest = 0.0;
    for (const Sample& s : samples) largest = std::max({largest, s.ref.r, s.ref.g, s.ref.b});
    const double floor = std::max(1e-3 * largest, 1e-30);

    ElekComparison c;
    c.bytes4D = scattering4DBytes(tables.sizes);
    c.bytesElek = elekBytes(tables.sizes);
    c.bytesShared = sharedTableBytes(tables.sizes);
    c.samples = static_cast<int>(samples.size());
    double sum = 0.0, sum0 = 0.0, sum180 = 0.0;
    int n0 = 0, n180 = 0;
    for (const Sample& s : samples) {
        double error = 0.0;
        for (int i = 0; i < 3; ++i) error = std::max(error, std::abs(s.elek[i] - s.ref[i]) / std::max(s.ref[i], floor));
        sum += error;
        if (s.azimuthDeg == 0.0) sum0 += error, ++n0;
        if (s.azimuthDeg == 180.0) sum180 += error, ++n180;
        if (error > c.maxRelativeError) {
            c.maxRelativeError = error;
            c.worstAltitudeKm = s.altitudeKm;
            c.worstSunZenithDeg = s.sunZenithDeg;
            c.worstViewZenithDeg = s.viewZenithDeg;
            c.worstAzimuthDeg = s.azimuthDeg;
        }
    }
    c.meanRelativeError = sum / std::max(c.samples, 1);
    c.meanRelativeErrorAzimuth0 = sum0 / std::max(n0, 1);
    c.meanRelativeErrorAzimuth180 = sum180 / std::max(n180, 1);
    return c;
}

std::string describeElekComparison(const ElekComparison& c) {
    char text[640];
    std::snprintf(text, sizeof text,
                  "sky parametrizations (scattering + single Mie tables, RGBA32F):\n"
                  "  4D Bruneton (r, mu, mu_s, nu): %.2f MiB\n"
                  "  3D Elek (r, mu, mu_s):         %.2f MiB\n"
                  "  shared transmittance + irradiance: %.2f MiB\n"
                  "Elek vs 4D sky radiance over %d views: mean relative error %.2f%%, max %.1f%%\n"
                  "  (worst at %.0f km, sun zenith %.0f deg, view zenith %.0f deg, azimuth %.0f deg);\n"
                  "  mean in the sun's vertical plane %.2f%%, opposite it %.2f%%\n",
                  c.bytes4D / 1048576.0, c.bytesElek / 1048576.0, c.bytesShared / 1048576.0, c.samples,
                  100.0 * c.meanRelativeError, 100.0 * c.maxRelativeError, c.worstAltitudeKm, c.worstSunZenithDeg,
                  c.worstViewZenithDeg, c.worstAzimuthDeg, 100.0 * c.meanRelativeErrorAzimuth0,
                  100.0 * c.meanRelativeErrorAzimuth180);
    return text;
}

}  // namespace planet::atmosphere
