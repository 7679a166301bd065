// Camera paths: keyframed flights stored as assets/paths/NAME.toml, sampled in
// double for `planet render --path`.
//
//     description = "Take off from the beach and climb to orbit"
//     fps = 30                      # frames per second of the natural sampling, (0, 1000], default 30
//
//     [[keyframe]]
//     time_s = 0.0                  # required, seconds along the path, strictly increasing, [0, 1e6]
//     latitude_deg = 43.0           # required, [-90, 90]
//     longitude_deg = -6.5025       # required, [-180, 180]
//     altitude_m = 2.0              # required, above the ground under the keyframe, [0.1, 1e9]
//     heading_deg = 250.0           # required, clockwise from north, [-360, 360]
//     pitch_deg = -5.0              # required, above the local horizon, [-90, 90]
//     fov_deg = 60.0                # optional, vertical field of view, (1, 170), default 60
//     sun_elevation_deg = 30.0      # optional pair, as in a view (app/views.h), [-90, 90]
//     sun_azimuth_deg = 220.0       # clockwise from north, [-360, 360]
//
// At least two keyframes. The sun keys come as a pair, and either every
// keyframe has them or none does (then the preset's sun stays). Errors are
// InputError (file:line: keyframe[i].field: message), unknown keys warnings,
// as for views and presets.
//
// Sampling (CameraPath::sample), all in double:
//  - position: the keyframes' directions from the planet centre and the logarithm
//    of their altitudes above the sphere are cubic Hermite splines in time (C1),
//    the direction renormalised. Log altitude, not metres: a climb from 2 m to
//    400 km spans five decades, and a spline in metres would both overshoot
//    below the ground in the low segments (their tangents are dominated by the
//    100-km steps above) and crawl near the ground then rush at the top; in
//    log altitude each factor of altitude takes comparable time, which is how
//    the climb looks (apparent speed goes as speed / altitude). Its tangents
//    are monotone (Fritsch-Butland), so between two keyframes the altitude
//    never leaves their range. Directions as unit vectors, not (lat, lon):
//    no trouble at the poles or across longitude 180.
//  - orientation: squad (spherical quadrangle interpolation) of the keyframe
//    cameras' quaternions, hemisphere-aligned: slerp-smooth within a segment,
//    without slerp's kinks in angular velocity at the keyframes.
//  - fov, sun elevation and azimuth (unwrapped to the shorter turn): linear.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/camera.h"
#include "scene/toml_error.h"  // InputError, thrown by the loaders

namespace planet {

struct PathKeyframe {
    double time_s = 0.0;         // s along the path
    double latitude_deg = 0.0;   // deg, [-90, 90]
    double longitude_deg = 0.0;  // deg, [-180, 180]
    double altitude_m = 2.0;     // m above the ground under the keyframe, [0.1, 1e9]
    double heading_deg = 0.0;    // deg clockwise from north
    double pitch_deg = 0.0;      // deg above the local horizon
    double fov_deg = 60.0;       // vertical field of view, deg
    std::optional<double> sun_elevation_deg;
    std::optional<double> sun_azimuth_deg;
    int line = 0;  // source line of the keyframe's table, for messages

    bool hasSun() const { return sun_elevation_deg.has_value() && sun_azimuth_deg.has_value(); }
};

struct CameraPathFile {
    std::string name;         // file stem, e.g. "takeoff"
    std::string description;  // "" when absent
    double fps = 30.0;        // frames per second of the natural sampling
    std::vector<PathKeyframe> keyframes;  // >= 2, times strictly increasing

    double startTime() const { return keyframes.front().time_s; }
    double endTime() const { return keyframes.back().time_s; }
    double duration() const { return endTime() - startTime(); }
    bool hasSun() const { return keyframes.front().hasSun(); }  // all or none (checked when parsed)
};

// Parses path text; name becomes CameraPathFile::name, sourceName is used in
// messages. Unknown keys are appended to *warnings when not null. Throws InputError.
CameraPathFile parseCameraPath(std::string_view tomlText, const std::string& sourceName, const std::string& name,
                               std::vector<std::string>* warnings = nullptr);
// Reads a path file; its name is the file stem. Throws InputError.
CameraPathFile loadCameraPath(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr);
// nameOrPath as a file when there is one, else pathsDir/NAME.toml; InputError
// listing the available names when neither exists.
std::filesystem::path resolveCameraPath(const std::string& nameOrPath, const std::filesystem::path& pathsDir);

// How many frames a render of the path makes and when: `frames` evenly in time
// over the whole path (both ends included; 1 frame: the start), or without it
// round(duration * fps) + 1 frames, 1 / fps apart give or take the rounding.
// A frame's file name from an --out pattern with one printf integer conversion
// (%d, %4d, %04d; %% is a literal %), e.g. "seq/f_%04d.png" -> "seq/f_0007.png".
// hasFramePattern: whether the text has exactly one such conversion and no other.
bool hasFramePattern(const std::string& pattern);
// Throws InputError naming the pattern unless hasFramePattern.
std::string frameFileName(const std::string& pattern, int frame);

int pathFrameCount(const CameraPathFile& path, std::optional<int> frames);
double pathFrameTime(const CameraPathFile& path, int frame, int frameCount);

// One sample of a path.
struct PathSample {
    Camera camera;                            // position, orientation, fovY (near as Camera's default)
    double latitude_deg = 0.0;                // the camera's place, for the sun's keys
    double longitude_deg = 0.0;
    std::optional<double> sun_elevation_deg;  // as seen from the camera's place; unset when the path has no sun
    std::optional<double> sun_azimuth_deg;
};

class CameraPath {
public:
    // Height of the ground above the sphere (m) under a unit direction; the
    // keyframes' altitudes are above it. Empty: the sphere itself.
    using GroundHeight = std::function<double(const glm::dvec3& direction)>;

    CameraPath(const CameraPathFile& file, double planetRadiusM, const GroundHeight& groundHeightM = {});

    // The camera at time t (s, on the path's clock), clamped to [startTime, endTime].
    PathSample sample(double t) const;
    const CameraPathFile& file() const { return file_; }

private:
    CameraPathFile file_;
    double radius_;
    std::vector<double> times_;
    std::vector<glm::dvec3> directions_, directionTangents_;  // unit vectors; d/dt
    std::vector<double> logAltitudes_, logAltitudeTangents_;  // ln(m above the sphere); d/dt
    std::vector<glm::dquat> orientations_, squadControls_;    // hemisphere-aligned
    std::vector<double> sunAzimuths_;                         // unwrapped
};

}  // namespace planet
