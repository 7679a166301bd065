// View bookmarks: reading assets/views/*.toml and placing the sun from a view.
// See views.h for the file format and the local-frame conventions.
#include "app/views.h"

#include <algorithm>
#include <cmath>

#include "app/place_keys.h"
#include "scene/toml_error.h"

namespace planet {

namespace {

namespace fs = std::filesystem;

using namespace place_keys;

std::vector<std::string> knownKeys() {
    std::vector<std::string> keys = {"description"};
    for (const NumberKey& k : {kLatitude, kLongitude, kAltitude, kHeading, kPitch, kFov, kSunElevation, kSunAzimuth})
        keys.emplace_back(k.key);
    return keys;
}

}  // namespace

View parseView(std::string_view tomlText, const std::string& sourceName, const std::string& name,
               std::vector<std::string>* warnings) {
    const toml::table root = parseToml(tomlText, sourceName);
    warnUnknownKeys(root, knownKeys(), sourceName, "", warnings);
    View view;
    view.name = name;
    if (const toml::node* n = root.get("description")) view.description = readString(*n, sourceName, "description");
    view.latitude_deg = readRequiredKey(root, kLatitude, sourceName);
    view.longitude_deg = readRequiredKey(root, kLongitude, sourceName);
    view.altitude_m = readRequiredKey(root, kAltitude, sourceName);
    view.heading_deg = readNumberKey(root, kHeading, sourceName).value_or(view.heading_deg);
    view.pitch_deg = readNumberKey(root, kPitch, sourceName).value_or(view.pitch_deg);
    view.fov_deg = readNumberKey(root, kFov, sourceName).value_or(view.fov_deg);
    readSunKeys(root, sourceName, "", view.sun_elevation_deg, view.sun_azimuth_deg);
    return view;
}

View loadView(const std::filesystem::path& path, std::vector<std::string>* warnings) {
    return parseView(readInputFile(path), path.string(), path.stem().string(), warnings);
}

std::vector<View> loadViews(const std::filesystem::path& dir, std::vector<std::string>* warnings) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(dir.string(), 0, "", "views folder not found");
    std::vector<View> views;
    for (const auto& entry : fs::directory_iterator(dir, ec))
        if (entry.path().extension() == ".toml") views.push_back(loadView(entry.path(), warnings));
    if (views.empty()) throw InputError(dir.string(), 0, "", "no view files (*.toml) in this folder");
    std::sort(views.begin(), views.end(), [](const View& a, const View& b) { return a.name < b.name; });
    return views;
}

const View& findView(const std::vector<View>& views, const std::string& name) {
    for (const View& view : views)
        if (view.name == name) return view;
    std::vector<std::string> names;
    for (const View& view : views) names.push_back(view.name);
    throw InputError("", 0, "", "unknown view '" + name + "'; available views: " + joinNames(names));
}

glm::dvec3 directionFromHorizontal(double latDeg, double lonDeg, double elevationDeg, double azimuthDeg) {
    const double lat = glm::radians(latDeg), lon = glm::radians(lonDeg);
    const double el = glm::radians(elevationDeg), az = glm::radians(azimuthDeg);
    const glm::dvec3 east(-std::sin(lon), std::cos(lon), 0.0);
    const glm::dvec3 north(-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat));
    const glm::dvec3 up = directionFromLatLon(latDeg, lonDeg);
    return std::cos(el) * (std::sin(az) * east + std::cos(az) * north) + std::sin(el) * up;
}

glm::dvec3 subsolarDirection(const View& view, const Scene& scene) {
    if (!view.hasSun()) return scene.sunDirection();
    return directionFromHorizontal(view.latitude_deg, view.longitude_deg, *view.sun_elevation_deg,
                                   *view.sun_azimuth_deg);
}

void applyViewSun(const View& view, Scene& scene) {
    if (!view.hasSun()) return;
    const glm::dvec3 d = subsolarDirection(view, scene);
    // atan2 rather than asin: well conditioned near the poles too.
    // Clamped: degrees(pi) may round to a hair above 180, outside the parameter's range.
    scene.sun.latitude_deg = std::clamp(glm::degrees(std::atan2(d.z, std::hypot(d.x, d.y))), -90.0, 90.0);
    scene.sun.longitude_deg = std::clamp(glm::degrees(std::atan2(d.y, d.x)), -180.0, 180.0);
}

}  // namespace planet
