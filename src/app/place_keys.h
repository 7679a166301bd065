// The numeric keys of the small TOML files that place a camera (view bookmarks,
// app/views.h; camera path keyframes, app/camera_path.h): each key with its range and unit,
// read, range-checked and located once, and the keys a place has, so that a view and a
// keyframe accept the same values with the same messages.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/toml_error.h"

namespace planet {

// One numeric key. open: the range excludes its ends.
struct NumberKey {
    const char* key;
    double lo, hi;
    const char* unit;
    bool open = false;
};

// The keys of a place, as views and keyframes spell them.
namespace place_keys {
constexpr NumberKey kLatitude{"latitude_deg", -90.0, 90.0, "deg"};
constexpr NumberKey kLongitude{"longitude_deg", -180.0, 180.0, "deg"};
constexpr NumberKey kAltitude{"altitude_m", 0.1, 1e9, "m"};
constexpr NumberKey kHeading{"heading_deg", -360.0, 360.0, "deg"};
constexpr NumberKey kPitch{"pitch_deg", -90.0, 90.0, "deg"};
constexpr NumberKey kFov{"fov_deg", 1.0, 170.0, "deg", true};
constexpr NumberKey kSunElevation{"sun_elevation_deg", -90.0, 90.0, "deg"};
constexpr NumberKey kSunAzimuth{"sun_azimuth_deg", -360.0, 360.0, "deg"};
}  // namespace place_keys

// The key's value in `table`, type- and range-checked (InputError at its line naming
// prefix + key); nullopt when absent. prefix: "keyframe[2]." and the like, or "".
std::optional<double> readNumberKey(const toml::table& table, const NumberKey& k, const std::string& file,
                                    const std::string& prefix = "");
// The same for a key that must be there: missing, an InputError at `tableLine`.
double readRequiredKey(const toml::table& table, const NumberKey& k, const std::string& file,
                       const std::string& prefix = "", int tableLine = 0);
// A warning (unknownKeyWarning, with a suggestion) for each key of `table` not in `known`.
void warnUnknownKeys(const toml::table& table, const std::vector<std::string>& known, const std::string& file,
                     const std::string& prefix, std::vector<std::string>* warnings);
// The sun's elevation and azimuth: both or neither (one alone is an InputError).
void readSunKeys(const toml::table& table, const std::string& file, const std::string& prefix,
                 std::optional<double>& elevation, std::optional<double>& azimuth);

}  // namespace planet
