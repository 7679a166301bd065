// What every command starts from: where the data lives, the preset, the view.
//
// The data root (holding shaders/ and assets/) is, in order: --root, the
// PLANET_ROOT environment variable, the source folder the binary was built from.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/camera_path.h"
#include "scene/camera.h"
#include "app/views.h"
#include "scene/scene.h"
#include "terrain/continents.h"
#include "terrain/height.h"

namespace planet {

struct DataPaths {
    std::filesystem::path root;
    std::filesystem::path shaders() const { return root / "shaders"; }
    std::filesystem::path assets() const { return root / "assets"; }
    std::filesystem::path views() const { return root / "assets" / "views"; }
};

// Throws InputError when the folder has no shaders/ and assets/.
DataPaths findDataPaths(const std::string& rootOption);

struct Session {
    Scene scene;        // what is rendered: the preset, tuned live, with the view's sun
    Scene presetScene;  // the preset as loaded; a view without sun keys restores its sun
    std::string presetName;
    std::filesystem::path presetPath;
    std::vector<View> views;
    View view;
    Camera camera;
    // The continents map's owner for the whole process: hand it to the Renderer
    // (Renderer(shaders, tables, session.continents)) so that the GPU's texture and the CPU's
    // ground are one map, loaded once. Copies of the session share it.
    std::shared_ptr<terrain::Continents> continents = std::make_shared<terrain::Continents>();
    // The terrain's heights on the CPU (the map of `continents`, which the terrain draws), for
    // the camera's ground; follows scene.terrain in applyView and keepAboveGround.
    terrain::HeightField ground{continents};
};

// A preset alone, found by name or path, its warnings logged: what the commands that need
// neither a view nor the ground (precompute, sky-probe) start from, so they bake no continents.
struct NamedPreset {
    Scene scene;
    std::string name;  // the file's stem
    std::filesystem::path path;
};
NamedPreset loadNamedPreset(const DataPaths& paths, const std::string& preset);

// Loads the preset (warnings go to the log) and the view bookmarks, picks the
// view, places the sun and the camera. Throws InputError naming file, line, field.
// A view file that does not load is an error only when it is the view asked for;
// any other is left out of Session::views with a warning in the log (loadViews).
// `noTemporal` (--no-temporal) switches the preset's render.temporal off.
Session loadSession(const DataPaths& paths, const std::string& preset, const std::string& viewName,
                    bool noTemporal = false);

// Puts the camera (and the sun, when the view places it) where a view says.
void applyView(const View& view, Session& session);

// Lifts session.camera radially to kCameraMinAltitudeM above the ground (terrain or
// sea) under it; the fly controller only knows the sea-level sphere. Brings
// session.ground up to date with session.scene.terrain first (a rebake when a
// parameter of the continents changed). Returns true when it moved the camera.
bool keepAboveGround(Session& session);

// A camera path over the session's ground (keyframe altitudes are above it), loaded by name
// under assets/paths or as a file; warnings logged; the session's sun back to the preset's
// (a path's sun, or the preset's: never a view's). Throws InputError.
CameraPath loadSessionPath(const DataPaths& paths, const std::string& nameOrPath, Session& session);

// Puts the session at a path's sample: the camera (kept above the ground and within the
// renderer's limits), the sun when the path has one, and the scene's clock
// (clockStart + the time along the path). What planet render --path and the explorer's
// playback do for each frame. Returns what was corrected ("" when nothing).
std::string applyPathSample(const CameraPath& path, double t, double clockStart, Session& session);

// "640x360" -> {640, 360}; throws InputError for anything else or sides outside [1, 16384].
glm::ivec2 parseSize(const std::string& text);

// Checks that each output file can be created (its folder exists or can be
// made, and is writable) before any work is done, so that a bad path fails
// fast and no other output is left half-done. Throws InputError naming the file.
void checkOutputsWritable(const std::vector<std::string>& outputs);

}  // namespace planet
