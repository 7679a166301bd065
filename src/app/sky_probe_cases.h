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

namespace planet {

inline constexpr const char* kProbeInputColumns[4] = {"altitude_m", "sun_zenith_deg", "view_zenith_deg",
                                                      "view_azimuth_deg"};

struct ProbeRow {
    std::string text[4];   // the input fields as written, echoed to the output
    double altitudeM, sunZenithDeg, viewZenithDeg, viewAzimuthDeg;
};

// Parses CSV text; sourceName is used in messages. Throws InputError.
std::vector<ProbeRow> parseProbeCases(std::string_view csvText, const std::string& sourceName);

// Reads and parses a CSV file. Throws FileError when it cannot be read, InputError when malformed.
std::vector<ProbeRow> readProbeCases(const std::filesystem::path& file);

}  // namespace planet
