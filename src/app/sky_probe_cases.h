// The input of `planet sky-probe` (sky_probe_command.cpp): a CSV of rays,
//
//     altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg
//     0,45,89.5,90
//
// one header line, then four finite numbers a row, each in its range (altitude
// [0, 1e9] m, zeniths [0, 180] deg, azimuth [-360, 360] deg). Fields are trimmed
// of spaces, tabs and carriage returns; blank lines are skipped. The whole text
// is checked before anything uses it: the first bad row is an InputError naming
// source, line and column.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace planet {

inline constexpr const char* kProbeInputColumns[4] = {"altitude_m", "sun_zenith_deg", "view_zenith_deg",
                                                      "view_azimuth_deg"};

// The columns `planet sky-probe` adds after the input's.
inline constexpr const char* kProbeOutputColumns[6] = {"radiance_r",      "radiance_g",      "radiance_b",
                                                       "transmittance_r", "transmittance_g", "transmittance_b"};

struct ProbeRow {
    std::string text[4];   // the input fields as written, echoed to the output
    double altitudeM, sunZenithDeg, viewZenithDeg, viewAzimuthDeg;
};

// Parses CSV text; sourceName is used in messages. Throws InputError.
std::vector<ProbeRow> parseProbeCases(std::string_view csvText, const std::string& sourceName);

// Reads and parses a CSV file. Throws FileError when it cannot be read, InputError when malformed.
std::vector<ProbeRow> readProbeCases(const std::filesystem::path& file);

// A row of sky-probe's output: the input row, the radiance / solar irradiance (1/sr)
// and the transmittance per channel.
struct ProbeResultRow {
    ProbeRow ray;
    glm::dvec3 radiance, transmittance;
};

// Parses / reads sky-probe's output CSV (its header, 10 columns, finite values >= 0).
// Throws InputError naming the line, FileError when the file cannot be read.
std::vector<ProbeResultRow> parseProbeResults(std::string_view csvText, const std::string& sourceName);
std::vector<ProbeResultRow> readProbeResults(const std::filesystem::path& file);

}  // namespace planet
