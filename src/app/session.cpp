#include "app/session.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>
#include <regex>

#include "scene/preset.h"
#include "terrain/height.h"
#include "scene/toml_error.h"
#include "util/log.h"

namespace planet {

namespace fs = std::filesystem;

DataPaths findDataPaths(const std::string& rootOption) {
    fs::path root = rootOption;
    if (root.empty()) {
        const char* env = std::getenv("PLANET_ROOT");
        root = env && *env ? fs::path(env) : fs::path(PLANET_SOURCE_DIR);
    }
    DataPaths paths{root};
    if (!fs::is_directory(paths.shaders()) || !fs::is_directory(paths.assets()))
        throw InputError("data folder '" + root.string() + "' has no shaders/ and assets/ (set --root or PLANET_ROOT)");
    return paths;
}

void applyView(const View& view, Session& session) {
    session.view = view;
    session.scene.sun = session.presetScene.sun;  // a previous view's sun must not linger
    applyViewSun(view, session.scene);
    // A view's altitude is above the ground under it: the terrain, or the sea.
    session.ground.update(session.scene.terrain);
    const double ground =
        terrain::surfaceHeightM(session.ground, directionFromLatLon(view.latitude_deg, view.longitude_deg));
    session.camera = cameraAtGeographic(view.latitude_deg, view.longitude_deg, ground + view.altitude_m,
                                        view.heading_deg, view.pitch_deg, view.fov_deg, session.scene.planetRadiusM());
    const std::string fix = sanitizeCamera(session.camera, session.scene.planetRadiusM());
    if (!fix.empty()) logWarning("view '" + view.name + "': " + fix);
}

NamedPreset loadNamedPreset(const DataPaths& paths, const std::string& preset) {
    NamedPreset named;
    named.path = resolvePreset(preset, paths.assets());
    PresetLoad load = loadPreset(named.path);
    for (const std::string& w : load.warnings) logWarning(w);
    named.scene = load.scene;
    named.name = named.path.stem().string();
    return named;
}

Session loadSession(const DataPaths& paths, const std::string& preset, const std::string& viewName,
                    bool noTemporal) {
    Session s;
    NamedPreset named = loadNamedPreset(paths, preset);
    if (noTemporal) named.scene.render.temporal = false;
    s.scene = named.scene;
    s.presetScene = named.scene;
    s.presetName = named.name;
    s.presetPath = named.path;
    // A broken view file stops the command only when it is the one asked for.
    std::vector<std::string> warnings;
    std::vector<BrokenView> broken;
    s.views = loadViews(paths.views(), &warnings, &broken);
    const View& view = findView(s.views, viewName, broken);
    for (const std::string& w : warnings) logWarning(w);
    applyView(view, s);
    return s;
}

void checkOutputsWritable(const std::vector<std::string>& outputs) {
    for (const std::string& out : outputs) {
        const fs::path path = fs::absolute(out);
        auto fail = [&](const std::string& why) { throw InputError("cannot write '" + out + "': " + why); };
        std::error_code ec;
        if (fs::is_directory(path, ec)) fail("it is a folder");
        const fs::path folder = path.parent_path();
        fs::create_directories(folder, ec);
        if (ec) fail("cannot create its folder '" + folder.string() + "': " + ec.message());
        // A file created and removed at once: what the file system says (a read-only mount, a
        // folder only root may write, /proc) rather than what the permission bits promise.
        const fs::path probe = folder / (".planet-write-test-" + std::to_string(::getpid()));
        const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
        if (fd < 0) fail(std::strerror(errno));
        ::close(fd);
        fs::remove(probe, ec);
    }
}

bool keepAboveGround(Session& session) {
    Camera& camera = session.camera;
    const double radius = session.scene.planetRadiusM();
    session.ground.update(session.scene.terrain);
    const double lowest = radius + terrain::surfaceHeightM(session.ground, camera.position) + kCameraMinAltitudeM;
    const double distance = glm::length(camera.position);
    // 1 um of slack: the lifted position, rescaled in double, may land a rounding error short.
    if (!(distance > 0.0) || distance >= lowest - 1e-6) return false;
    camera.position *= lowest / distance;
    return true;
}

glm::ivec2 parseSize(const std::string& text) {
    static const std::regex re(R"(^\s*(\d{1,5})\s*[xX]\s*(\d{1,5})\s*$)");
    std::smatch m;
    if (std::regex_match(text, m, re)) {
        const glm::ivec2 size(std::stoi(m[1]), std::stoi(m[2]));
        if (size.x >= 1 && size.y >= 1 && size.x <= 16384 && size.y <= 16384) return size;
    }
    throw InputError("--size '" + text + "': expected WIDTHxHEIGHT with each side in [1, 16384], e.g. 640x360");
}

CameraPath loadSessionPath(const DataPaths& paths, const std::string& nameOrPath, Session& session) {
    std::vector<std::string> warnings;
    const CameraPathFile file = loadCameraPath(resolveCameraPath(nameOrPath, paths.assets() / "paths"), &warnings);
    for (const std::string& w : warnings) logWarning(w);
    session.scene.sun = session.presetScene.sun;
    session.ground.update(session.scene.terrain);
    return CameraPath(file, session.scene.planetRadiusM(), [&session](const glm::dvec3& direction) {
        return terrain::surfaceHeightM(session.ground, direction);
    });
}

std::string applyPathSample(const CameraPath& path, double t, double clockStart, Session& session) {
    const PathSample sample = path.sample(t);
    session.camera = sample.camera;
    keepAboveGround(session);
    const std::string fix = sanitizeCamera(session.camera, session.scene.planetRadiusM());
    if (sample.sun_elevation_deg) {
        View place;
        place.latitude_deg = sample.latitude_deg;
        place.longitude_deg = sample.longitude_deg;
        place.sun_elevation_deg = sample.sun_elevation_deg;
        place.sun_azimuth_deg = sample.sun_azimuth_deg;
        applyViewSun(place, session.scene);
    }
    session.scene.time_s = clockStart + (t - path.file().startTime());
    return fix;
}

}  // namespace planet
