// Dear ImGui panels of the explorer. Each function draws one window from the
// state it is given and reports what the user changed; none owns state.
#pragma once

#include <string>
#include <vector>

#include "app/camera_controller.h"
#include "app/views.h"
#include "render/profiler.h"
#include "scene/scene.h"

namespace planet {

// Frame time: FPS, frame GPU/CPU graph, and a per-pass min/median/max table.
void drawProfilerPanel(const Profiler& profiler, const std::string& renderer);

// One widget per row of the parameter table, grouped by section. Returns true
// when a value changed (already clamped to its valid range). While the
// atmosphere tables are being rebuilt, `rebuildProgress` in [0, 1) shows as a
// bar (the old tables stay in use until then); pass 1 when idle. `cloudBakeProgress`
// likewise for a background bake of the clouds' volume and weather map.
bool drawSceneParams(Scene& scene, double rebuildProgress, double cloudBakeProgress);

struct CameraPanelResult {
    int jumpToView = -1;   // index into views, or -1
    bool savePreset = false;
};
CameraPanelResult drawCameraPanel(const Camera& camera, CameraController& controller, double planetRadiusM,
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

// Shader compile errors from hot reload, in a red window; nothing when empty.
void drawShaderErrors(const std::vector<std::string>& errors);

}  // namespace planet
