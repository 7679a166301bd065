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

std::vector<View> loadViews(const std::filesystem::path& dir, std::vector<std::string>* warnings,
                            std::vector<BrokenView>* broken) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(dir.string(), 0, "", "views folder not found");
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir, ec))
        if (entry.path().extension() == ".toml") files.push_back(entry.path());
    if (files.empty()) throw InputError(dir.string(), 0, "", "no view files (*.toml) in this folder");
    // By name: the views, their warnings and the broken ones in a stable order.
    std::sort(files.begin(), files.end(),
              [](const fs::path& a, const fs::path& b) { return a.stem().string() < b.stem().string(); });
    std::vector<View> views;
    std::vector<BrokenView> failed;
    for (const fs::path& file : files) {
        std::vector<std::string> fileWarnings;  // a skipped file's unknown keys are not worth a word
        try {
            views.push_back(loadView(file, &fileWarnings));
        } catch (const InputError& e) {
            failed.push_back({file.stem().string(), e});
            fileWarnings = {std::string(e.what()) + " (view skipped)"};
        }
        if (warnings) warnings->insert(warnings->end(), fileWarnings.begin(), fileWarnings.end());
    }
    if (broken) *broken = std::move(failed);
    return views;
}

const View& findView(const std::vector<View>& views, const std::string& name, const std::vector<BrokenView>& broken) {
    for (const View& view : views)
        if (view.name == name) return view;
    for (const BrokenView& b : broken)
        if (b.name == name) throw b.error;
    std::vector<std::string> names;
    for (const View& view : views) names.push_back(view.name);
    std::string message = "unknown view '" + name + "'; available views: " + joinNames(names);
    if (!broken.empty()) {
        std::vector<std::string> skipped;
        for (const BrokenView& b : broken) skipped.push_back(b.name);
        message += "; skipped as broken: " + joinNames(skipped);
    }
    throw InputError("", 0, "", message);
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
