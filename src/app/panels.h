// Dear ImGui panels of the explorer. Each function draws one window from the
// state it is given and reports what the user changed; none owns state.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/camera_controller.h"
#include "app/views.h"
#include "render/profiler.h"
#include "scene/scene.h"

namespace planet {

// Where each panel starts when there is no saved layout (the layout is saved in the user's
// config folder, explorer.cpp): the frame-time panel open at the top left, the others
// collapsed to their title bars at the edges (`width` x `height` once expanded), so that at
// 1280x720 they cover under 30 % of the view (tested).
struct PanelPlacement {
    std::string name;
    float x = 0, y = 0, width = 0, height = 0;
    bool collapsed = false;
};
std::vector<PanelPlacement> initialPanelLayout(float displayWidth, float displayHeight);
// The share of the display the placements cover, a collapsed panel by its title bar
// (`titleHeight` pixels), overlaps counted once.
double panelCoverage(const std::vector<PanelPlacement>& layout, float displayWidth, float displayHeight,
                     float titleHeight);

// The explorer's render scale (app/render_scale.h) as the Frame time panel shows it:
// `chosen` (nullopt: auto) is what the slider and its Auto button change; `effective` the
// scale in use and `frame` the frame's size, shown beside it.
struct RenderScaleUi {
    std::optional<double>& chosen;
    double effective = 1.0;
    glm::ivec2 frame{0};
};

// Frame time: FPS, frame GPU/CPU graph, and a per-pass min/median/max table; with `scale`,
// the render scale's slider too.
void drawProfilerPanel(Profiler& profiler, const std::string& renderer, RenderScaleUi* scale = nullptr);

// One widget per row of the parameter table, grouped by section. Returns true
// when a value changed (already clamped to its valid range). While the
// atmosphere tables are being rebuilt, `rebuildProgress` in [0, 1) shows as a
// bar labelled `rebuildLabel` (the old tables stay in use until then); pass 1 when idle.
// `cloudBakeProgress` likewise for a background bake of the clouds' volume and weather map.
bool drawSceneParams(Scene& scene, double rebuildProgress, double cloudBakeProgress,
                     const char* rebuildLabel = "rebuilding tables");

// Camera: altitude and place, fly/orbit and speed, the view bookmarks, the time of day at
// the camera (moves the sun: scene.sun's longitude), and saving the preset.
struct CameraPanelResult {
    int jumpToView = -1;   // index into views, or -1
    bool savePreset = false;
    bool sunMoved = false; // the time-of-day control changed scene.sun
};
CameraPanelResult drawCameraPanel(const Camera& camera, CameraController& controller, Scene& scene,
                                  const std::vector<View>& views, std::string& presetPath, const std::string& status);

// The ocean's clock, owned by the explorer: scene.time_s advances by rate * dt unless paused.
struct WaveClock {
    bool paused = false;
    double rate = 1.0;
};

// The wave set: the clock, statistics, regenerate from the [ocean] parameters, and every
// wave's fields (origin, amplitude, wavelength, steepness, speed, phase) to edit, add or
// remove. Returns true when the waves changed.
bool drawWavePanel(Scene& scene, WaveClock& clock);

// A line of status at the bottom right of the window (work going on in the background, e.g.
// the atmosphere tables being refined), with a progress bar when `progress` is in [0, 1];
// nothing when `text` is empty. Drawn with the panels hidden too: it says why the picture
// is about to change.
void drawStatusLine(const std::string& text, double progress = -1.0);

// Shader compile errors from hot reload, in a red window; nothing when empty.
void drawShaderErrors(const std::vector<std::string>& errors);

}  // namespace planet
