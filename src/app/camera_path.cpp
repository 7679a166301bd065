// Camera paths: reading assets/paths/*.toml and sampling them in double.
// See camera_path.h for the file format and the interpolation.
#include "app/camera_path.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "util/file_util.h"
#include "app/place_keys.h"
#include "scene/scene.h"

namespace planet {

namespace {

namespace fs = std::filesystem;

using namespace place_keys;

constexpr NumberKey kTime{"time_s", 0.0, 1e6, "s"};
constexpr NumberKey kFps{"fps", 0.0, 1000.0, "frames/s"};  // (0, 1000]

const std::vector<std::string> kTopKeys = {"description", "fps", "keyframe"};

std::vector<std::string> keyframeKeys() {
    std::vector<std::string> keys;
    for (const NumberKey& k : {kTime, kLatitude, kLongitude, kAltitude, kHeading, kPitch, kFov, kSunElevation, kSunAzimuth})
        keys.emplace_back(k.key);
    return keys;
}

PathKeyframe readKeyframe(const toml::table& table, const std::string& file, int index,
                          std::vector<std::string>* warnings) {
    const std::string prefix = "keyframe[" + std::to_string(index) + "].";
    const int line = sourceLine(table);
    warnUnknownKeys(table, keyframeKeys(), file, prefix, warnings);
    PathKeyframe k;
    k.line = line;
    k.time_s = readRequiredKey(table, kTime, file, prefix, line);
    k.latitude_deg = readRequiredKey(table, kLatitude, file, prefix, line);
    k.longitude_deg = readRequiredKey(table, kLongitude, file, prefix, line);
    k.altitude_m = readRequiredKey(table, kAltitude, file, prefix, line);
    k.heading_deg = readRequiredKey(table, kHeading, file, prefix, line);
    k.pitch_deg = readRequiredKey(table, kPitch, file, prefix, line);
    k.fov_deg = readNumberKey(table, kFov, file, prefix).value_or(k.fov_deg);
    readSunKeys(table, file, prefix, k.sun_elevation_deg, k.sun_azimuth_deg);
    return k;
}

// --- Interpolation helpers -------------------------------------------------

// Cubic Hermite basis on s in [0, 1] over a segment of length h (tangents are d/dt).
template <typename T>
T hermite(const T& p0, const T& p1, const T& m0, const T& m1, double s, double h) {
    const double s2 = s * s, s3 = s2 * s;
    return (2.0 * s3 - 3.0 * s2 + 1.0) * p0 + (s3 - 2.0 * s2 + s) * h * m0 + (-2.0 * s3 + 3.0 * s2) * p1 +
           (s3 - s2) * h * m1;
}

// Tangents (d/dt) of a C1 cubic Hermite spline through p at non-uniform times t:
// the three-point (parabola) derivative inside, the secant at the ends.
template <typename T>
std::vector<T> threePointTangents(const std::vector<double>& t, const std::vector<T>& p) {
    const std::size_t n = p.size();
    std::vector<T> m(n);
    m[0] = (p[1] - p[0]) / (t[1] - t[0]);
    m[n - 1] = (p[n - 1] - p[n - 2]) / (t[n - 1] - t[n - 2]);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
        const T d0 = (p[i] - p[i - 1]) / h0, d1 = (p[i + 1] - p[i]) / h1;
        m[i] = (d0 * h1 + d1 * h0) / (h0 + h1);
    }
    return m;
}

// Monotone tangents (Fritsch-Butland, weighted harmonic mean of the secants,
// zero at a local extremum): the spline never overshoots its data.
std::vector<double> monotoneTangents(const std::vector<double>& t, const std::vector<double>& p) {
    const std::size_t n = p.size();
    std::vector<double> m(n, 0.0);
    m[0] = (p[1] - p[0]) / (t[1] - t[0]);
    m[n - 1] = (p[n - 1] - p[n - 2]) / (t[n - 1] - t[n - 2]);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
        const double d0 = (p[i] - p[i - 1]) / h0, d1 = (p[i + 1] - p[i]) / h1;
        if (d0 * d1 <= 0.0) continue;
        m[i] = 3.0 * (h0 + h1) / ((2.0 * h1 + h0) / d0 + (h1 + 2.0 * h0) / d1);
    }
    return m;
}

// Quaternion log / exp of unit quaternions, as pure-vector quaternions.
glm::dquat quatLog(const glm::dquat& q) {
    const glm::dvec3 v(q.x, q.y, q.z);
    const double s = glm::length(v);
    if (s < 1e-15) return glm::dquat(0.0, v.x, v.y, v.z);
    const glm::dvec3 u = v * (std::atan2(s, q.w) / s);
    return glm::dquat(0.0, u.x, u.y, u.z);
}

glm::dquat quatExp(const glm::dquat& q) {
    const glm::dvec3 v(q.x, q.y, q.z);
    const double a = glm::length(v);
    const double k = a < 1e-15 ? 1.0 : std::sin(a) / a;
    return glm::dquat(std::cos(a), v.x * k, v.y * k, v.z * k);
}

// Slerp without the shortest-arc flip (squad needs the arc it is given).
glm::dquat slerpRaw(const glm::dquat& a, const glm::dquat& b, double s) {
    const double c = std::clamp(glm::dot(a, b), -1.0, 1.0);
    if (c > 1.0 - 1e-12) return glm::normalize(a * (1.0 - s) + b * s);
    const double angle = std::acos(c);
    const double sa = std::sin(angle);
    return glm::normalize(a * (std::sin((1.0 - s) * angle) / sa) + b * (std::sin(s * angle) / sa));
}

double lerp(double a, double b, double s) { return a + (b - a) * s; }

}  // namespace

CameraPathFile parseCameraPath(std::string_view tomlText, const std::string& sourceName, const std::string& name,
                               std::vector<std::string>* warnings) {
    const toml::table root = parseToml(tomlText, sourceName);
    warnUnknownKeys(root, kTopKeys, sourceName, "", warnings);
    CameraPathFile path;
    path.name = name;
    if (const toml::node* n = root.get("description")) path.description = readString(*n, sourceName, "description");
    if (const toml::node* n = root.get("fps")) {
        path.fps = readNumber(*n, sourceName, "fps");
        if (!(path.fps > 0.0 && path.fps <= kFps.hi))
            throw InputError(sourceName, sourceLine(*n), "fps",
                             "value " + formatNumber(path.fps) + " is out of range (0, 1000] frames/s");
    }
    const toml::node* list = root.get("keyframe");
    if (!list) throw InputError(sourceName, 0, "keyframe", "no keyframes (give at least 2 [[keyframe]] tables)");
    const toml::array* array = list->as_array();
    if (!array)
        throw InputError(sourceName, sourceLine(*list), "keyframe",
                         "expected an array of tables ([[keyframe]]), got " + typeName(*list));
    for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node& node = *array->get(i);
        const toml::table* table = node.as_table();
        const std::string field = "keyframe[" + std::to_string(i) + "]";
        if (!table) throw InputError(sourceName, sourceLine(node), field, "expected a table, got " + typeName(node));
        path.keyframes.push_back(readKeyframe(*table, sourceName, static_cast<int>(i), warnings));
        if (i > 0 && !(path.keyframes[i].time_s > path.keyframes[i - 1].time_s)) {
            const toml::node* t = table->get("time_s");
            throw InputError(sourceName, t ? sourceLine(*t) : path.keyframes[i].line, field + ".time_s",
                             "time " + formatNumber(path.keyframes[i].time_s) +
                                 " s is not after the previous keyframe's " +
                                 formatNumber(path.keyframes[i - 1].time_s) + " s (times must strictly increase)");
        }
        if (path.keyframes[i].hasSun() != path.keyframes[0].hasSun())
            throw InputError(sourceName, path.keyframes[i].line, field,
                             std::string("keyframe[0] ") + (path.keyframes[0].hasSun() ? "has" : "has no") +
                                 " sun keys and this one " + (path.keyframes[i].hasSun() ? "has" : "has not") +
                                 " (every keyframe places the sun, or none does)");
    }
    if (path.keyframes.size() < 2)
        throw InputError(sourceName, path.keyframes.empty() ? sourceLine(*list) : path.keyframes[0].line, "keyframe",
                         "a path needs at least 2 keyframes, this one has " + std::to_string(path.keyframes.size()));
    return path;
}

CameraPathFile loadCameraPath(const std::filesystem::path& path, std::vector<std::string>* warnings) {
    return parseCameraPath(readInputFile(path), path.string(), path.stem().string(), warnings);
}

fs::path resolveCameraPath(const std::string& nameOrPath, const fs::path& pathsDir) {
    std::error_code ec;
    const fs::path direct(nameOrPath);
    if (!nameOrPath.empty() && fs::exists(direct, ec)) {
        // Given as a path: say why it cannot be read rather than that no such name exists.
        if (const std::string why = whyNotReadableFile(direct); !why.empty())
            throw InputError("", 0, "", "camera path '" + nameOrPath + "': " + why);
        return direct;
    }
    const fs::path named = pathsDir / (nameOrPath + ".toml");
    if (fs::is_regular_file(named, ec)) return named;
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(pathsDir, ec))
        if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    throw InputError("", 0, "",
                     "unknown camera path '" + nameOrPath + "': no such file, and no " + named.string() +
                         "; available paths: " + joinNames(names));
}

namespace {

// Expands pattern for frame; returns false unless it has exactly one integer conversion and no other.
bool expandPattern(const std::string& pattern, int frame, std::string& out) {
    out.clear();
    int conversions = 0;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            out += '%';
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        const bool zero = j < pattern.size() && pattern[j] == '0';
        if (zero) ++j;
        int width = 0;
        while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && width < 100)
            width = width * 10 + (pattern[j++] - '0');
        if (j >= pattern.size() || pattern[j] != 'd' || width > 32) return false;
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, zero ? "%0*d" : "%*d", width, frame);
        out += buffer;
        ++conversions;
        i = j;
    }
    return conversions == 1;
}

}  // namespace

bool hasFramePattern(const std::string& pattern) {
    std::string out;
    return expandPattern(pattern, 0, out);
}

std::string frameFileName(const std::string& pattern, int frame) {
    std::string out;
    if (!expandPattern(pattern, frame, out))
        throw InputError("--out '" + pattern +
                         "': a sequence needs one frame number in the name, as a printf integer (e.g. f_%04d.png), "
                         "and no other % conversion (%% for a literal %)");
    return out;
}

int pathFrameCount(const CameraPathFile& path, std::optional<int> frames) {
    if (frames) {
        if (*frames < 1 || *frames > 1000000) throw InputError("--frames must be in [1, 1000000]");
        return *frames;
    }
    const double n = std::round(path.duration() * path.fps) + 1.0;
    if (!(n <= 1000000.0))
        throw InputError(path.name + ": " + formatNumber(n) + " frames at " + formatNumber(path.fps) +
                         " fps is too many (at most 1000000; give --frames)");
    return static_cast<int>(n);
}

double pathFrameTime(const CameraPathFile& path, int frame, int frameCount) {
    if (frameCount <= 1) return path.startTime();
    if (frame >= frameCount - 1) return path.endTime();  // exactly the last keyframe
    return path.startTime() + path.duration() * static_cast<double>(frame) / static_cast<double>(frameCount - 1);
}

CameraPath::CameraPath(const CameraPathFile& file, double planetRadiusM, const GroundHeight& groundHeightM)
    : file_(file), radius_(planetRadiusM) {
    const std::size_t n = file_.keyframes.size();
    if (n < 2) throw InputError(file_.name + ": a path needs at least 2 keyframes");
    for (std::size_t i = 0; i < n; ++i) {
        const PathKeyframe& k = file_.keyframes[i];
        const glm::dvec3 direction = directionFromLatLon(k.latitude_deg, k.longitude_deg);
        const double ground = groundHeightM ? groundHeightM(direction) : 0.0;
        // Above the sphere: kept positive so that its logarithm exists (ground under the sea level).
        const double altitude = std::max(ground + k.altitude_m, kCameraMinAltitudeM);
        const Camera camera = cameraAtGeographic(k.latitude_deg, k.longitude_deg, altitude, k.heading_deg,
                                                 k.pitch_deg, k.fov_deg, radius_);
        times_.push_back(k.time_s);
        directions_.push_back(direction);
        logAltitudes_.push_back(std::log(altitude));
        glm::dquat q = glm::normalize(camera.orientation);
        if (i > 0 && glm::dot(q, orientations_.back()) < 0.0) q = -q;  // the shorter arc from the previous
        orientations_.push_back(q);
        double azimuth = k.sun_azimuth_deg.value_or(0.0);
        if (i > 0) azimuth -= 360.0 * std::round((azimuth - sunAzimuths_.back()) / 360.0);  // the shorter turn
        sunAzimuths_.push_back(azimuth);
    }
    directionTangents_ = threePointTangents(times_, directions_);
    logAltitudeTangents_ = monotoneTangents(times_, logAltitudes_);
    // Squad's inner control points: s_i = q_i exp(-(log(q_i^-1 q_{i+1}) + log(q_i^-1 q_{i-1})) / 4),
    // the ends their own keyframes.
    squadControls_ = orientations_;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const glm::dquat inv = glm::conjugate(orientations_[i]);
        const glm::dquat a = quatLog(inv * orientations_[i + 1]);
        const glm::dquat b = quatLog(inv * orientations_[i - 1]);
        squadControls_[i] = glm::normalize(orientations_[i] * quatExp((a + b) * -0.25));
    }
}

PathSample CameraPath::sample(double t) const {
    const std::size_t n = times_.size();
    t = std::clamp(t, times_.front(), times_.back());
    // Segment i: times_[i] <= t <= times_[i + 1].
    std::size_t i = static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin());
    i = std::min(i == 0 ? 0 : i - 1, n - 2);
    const double h = times_[i + 1] - times_[i];
    const double s = std::clamp((t - times_[i]) / h, 0.0, 1.0);
    const PathKeyframe& k0 = file_.keyframes[i];
    const PathKeyframe& k1 = file_.keyframes[i + 1];

    PathSample out;
    const glm::dvec3 direction = glm::normalize(
        hermite(directions_[i], directions_[i + 1], directionTangents_[i], directionTangents_[i + 1], s, h));
    const double logAltitude =
        hermite(logAltitudes_[i], logAltitudes_[i + 1], logAltitudeTangents_[i], logAltitudeTangents_[i + 1], s, h);
    out.camera.position = direction * (radius_ + std::exp(logAltitude));
    const glm::dquat q = slerpRaw(slerpRaw(orientations_[i], orientations_[i + 1], s),
                                  slerpRaw(squadControls_[i], squadControls_[i + 1], s), 2.0 * s * (1.0 - s));
    out.camera.orientation = glm::normalize(q);
    out.camera.fovY_rad = glm::radians(lerp(k0.fov_deg, k1.fov_deg, s));
    out.latitude_deg = glm::degrees(std::atan2(direction.z, std::hypot(direction.x, direction.y)));
    out.longitude_deg = glm::degrees(std::atan2(direction.y, direction.x));
    if (file_.hasSun()) {
        out.sun_elevation_deg = lerp(*k0.sun_elevation_deg, *k1.sun_elevation_deg, s);
        out.sun_azimuth_deg = lerp(sunAzimuths_[i], sunAzimuths_[i + 1], s);
    }
    return out;
}

}  // namespace planet
