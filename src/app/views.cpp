// View bookmarks: reading assets/views/*.toml and placing the sun from a view.
// See views.h for the file format and the local-frame conventions.
#include "app/views.h"

#include <algorithm>
#include <cmath>

#include "scene/toml_error.h"

namespace planet {

namespace {

namespace fs = std::filesystem;

// One numeric key of a view file. open: the range excludes its ends.
struct ViewKey {
    const char* key;
    double lo, hi;
    const char* unit;
    bool open = false;
};

constexpr ViewKey kLatitude{"latitude_deg", -90.0, 90.0, "deg"};
constexpr ViewKey kLongitude{"longitude_deg", -180.0, 180.0, "deg"};
constexpr ViewKey kAltitude{"altitude_m", 0.1, 1e9, "m"};
constexpr ViewKey kHeading{"heading_deg", -360.0, 360.0, "deg"};
constexpr ViewKey kPitch{"pitch_deg", -90.0, 90.0, "deg"};
constexpr ViewKey kFov{"fov_deg", 1.0, 170.0, "deg", true};
constexpr ViewKey kSunElevation{"sun_elevation_deg", -90.0, 90.0, "deg"};
constexpr ViewKey kSunAzimuth{"sun_azimuth_deg", -360.0, 360.0, "deg"};

std::vector<std::string> knownKeys() {
    std::vector<std::string> keys = {"description"};
    for (const ViewKey& k : {kLatitude, kLongitude, kAltitude, kHeading, kPitch, kFov, kSunElevation, kSunAzimuth})
        keys.emplace_back(k.key);
    return keys;
}

void checkOpenRange(double value, const ViewKey& k, const InputLocation& where) {
    if (value > k.lo && value < k.hi) return;
    throw InputError(where.file, where.line, where.field,
                     "value " + formatNumber(value) + " is out of range (" + formatNumber(k.lo) + ", " +
                         formatNumber(k.hi) + ") " + k.unit);
}

// The key's value, type- and range-checked; nullopt when absent.
std::optional<double> readKey(const toml::table& root, const ViewKey& k, const std::string& file) {
    const toml::node* node = root.get(k.key);
    if (!node) return std::nullopt;
    const double value = readNumber(*node, file, k.key);
    const InputLocation where = locate(*node, file, k.key);
    if (k.open) checkOpenRange(value, k, where);
    else checkRange(value, k.lo, k.hi, k.unit, where);
    return value;
}

double readRequired(const toml::table& root, const ViewKey& k, const std::string& file) {
    const std::optional<double> value = readKey(root, k, file);
    if (!value) throw InputError(file, 0, k.key, "required key is missing");
    return *value;
}

void warnUnknownKeys(const toml::table& root, const std::string& file, std::vector<std::string>* warnings) {
    if (!warnings) return;
    const std::vector<std::string> known = knownKeys();
    for (auto&& [key, value] : root) {
        const std::string name(key.str());
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        const int keyLine = static_cast<int>(key.source().begin.line);
        warnings->push_back(unknownKeyWarning(file, keyLine > 0 ? keyLine : sourceLine(value), name, known));
    }
}

void readSun(const toml::table& root, const std::string& file, View& view) {
    view.sun_elevation_deg = readKey(root, kSunElevation, file);
    view.sun_azimuth_deg = readKey(root, kSunAzimuth, file);
    if (view.sun_elevation_deg.has_value() == view.sun_azimuth_deg.has_value()) return;
    const ViewKey& present = view.sun_elevation_deg ? kSunElevation : kSunAzimuth;
    const ViewKey& missing = view.sun_elevation_deg ? kSunAzimuth : kSunElevation;
    throw InputError(file, sourceLine(*root.get(present.key)), present.key,
                     std::string("needs '") + missing.key + "' as well (the sun keys come as a pair or not at all)");
}

}  // namespace

View parseView(std::string_view tomlText, const std::string& sourceName, const std::string& name,
               std::vector<std::string>* warnings) {
    const toml::table root = parseToml(tomlText, sourceName);
    warnUnknownKeys(root, sourceName, warnings);
    View view;
    view.name = name;
    if (const toml::node* n = root.get("description")) view.description = readString(*n, sourceName, "description");
    view.latitude_deg = readRequired(root, kLatitude, sourceName);
    view.longitude_deg = readRequired(root, kLongitude, sourceName);
    view.altitude_m = readRequired(root, kAltitude, sourceName);
    view.heading_deg = readKey(root, kHeading, sourceName).value_or(view.heading_deg);
    view.pitch_deg = readKey(root, kPitch, sourceName).value_or(view.pitch_deg);
    view.fov_deg = readKey(root, kFov, sourceName).value_or(view.fov_deg);
    readSun(root, sourceName, view);
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
