// View bookmarks: named camera placements stored as assets/views/NAME.toml.
//
// A view places the camera geographically and, optionally, the sun relative
// to that spot:
//
//     description = "Standing on a beach, looking along the coast"
//     latitude_deg = 36.5      # required, [-90, 90]
//     longitude_deg = -4.9     # required, [-180, 180]
//     altitude_m = 2.0         # required, above the planet sphere, [0.1, 1e9]
//     heading_deg = 90.0       # clockwise from north, [-360, 360], default 0
//     pitch_deg = 5.0          # above the local horizon, [-90, 90], default 0
//     fov_deg = 60.0           # vertical field of view, (1, 170), default 60
//     sun_elevation_deg = 30.0 # optional, with sun_azimuth_deg, [-90, 90]
//     sun_azimuth_deg = 100.0  # optional, clockwise from north, [-360, 360]
//
// The sun keys come as a pair or not at all; when present they override the
// preset's subsolar point (applyViewSun). Errors are InputError (file, line,
// key) and unknown keys are warnings, as for presets (scene/preset.h).
//
// Local frame at (lat, lon), world frame as in scene/scene.h:
//     east  = (-sin lon, cos lon, 0)
//     north = (-sin lat cos lon, -sin lat sin lon, cos lat)
//     up    = directionFromLatLon(lat, lon)
// and a direction at elevation el, azimuth az (clockwise from north) is
//     cos(el) (sin(az) east + cos(az) north) + sin(el) up.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "scene/toml_error.h"  // InputError, thrown by the loaders

namespace planet {

struct View {
    std::string name;         // file stem, e.g. "beach"
    std::string description;  // "" when absent
    double latitude_deg = 0.0;   // deg, [-90, 90]
    double longitude_deg = 0.0;  // deg, [-180, 180]
    double altitude_m = 2.0;     // m above the sphere, [0.1, 1e9]
    double heading_deg = 0.0;    // deg clockwise from north, [-360, 360]
    double pitch_deg = 0.0;      // deg above the local horizon, [-90, 90]
    double fov_deg = 60.0;       // vertical field of view, deg, (1, 170)
    std::optional<double> sun_elevation_deg;  // deg above the local horizon, [-90, 90]
    std::optional<double> sun_azimuth_deg;    // deg clockwise from north, [-360, 360]

    bool hasSun() const { return sun_elevation_deg.has_value() && sun_azimuth_deg.has_value(); }
};

// Parses view text; name becomes View::name, sourceName is used in messages.
// Unknown keys are appended to *warnings when it is not null. Throws InputError.
View parseView(std::string_view tomlText, const std::string& sourceName, const std::string& name,
               std::vector<std::string>* warnings = nullptr);
// Reads a view file; its name is the file stem. Throws InputError.
View loadView(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr);

// A view file of a folder that did not load: its name (the file stem) and why.
struct BrokenView {
    std::string name;
    InputError error;  // as loadView threw it: file:line: field: message
};

// Every *.toml in dir that loads, sorted by name. One bad file does not stop the others
// (a command that uses another view must not fail for it): it is left out, its error
// goes to *broken (sorted by name) when that is given, and a warning
//     "assets/views/x.toml:3: TOML syntax error: ... (view skipped)"
// to *warnings in its place among the others (the unknown keys of the views that load,
// file by file in name order). The result is
// empty when every file is broken. A missing folder, or one without any *.toml, is an
// InputError.
std::vector<View> loadViews(const std::filesystem::path& dir, std::vector<std::string>* warnings = nullptr,
                            std::vector<BrokenView>* broken = nullptr);
// The view with this name. When views has none, a broken file of that name (from
// loadViews) throws its own InputError (file:line: ...): the one view that was asked
// for is the one whose error stops the command. Otherwise an InputError listing the
// available names.
const View& findView(const std::vector<View>& views, const std::string& name,
                     const std::vector<BrokenView>& broken = {});

// World-frame unit vector for elevation/azimuth (deg) seen from (lat, lon) (deg).
glm::dvec3 directionFromHorizontal(double latDeg, double lonDeg, double elevationDeg, double azimuthDeg);

// World-frame unit vector towards the sun: from the view's sun keys when it
// has them, otherwise the scene's own subsolar direction.
glm::dvec3 subsolarDirection(const View& view, const Scene& scene);

// Moves scene.sun's subsolar point so that the sun stands where the view says;
// no-op when the view has no sun keys.
void applyViewSun(const View& view, Scene& scene);

}  // namespace planet
