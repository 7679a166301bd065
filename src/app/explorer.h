// The explorer: a GLFW window showing the frame, with camera controls, live
// parameter panels, the per-pass profiler and shader hot reload.
//
// Controls (as in other 3D tools):
//   Fly    W/S forward/back, A/D left/right, E/Q up/down, right mouse drag to
//          look, scroll to change speed (speed also scales with altitude),
//          Shift x5, Ctrl /5
//   Orbit  left mouse drag turns the planet, scroll zooms
//   Tab    switch fly/orbit     1-9  jump to view bookmarks
//   F1     hide/show panels     F5   reload shaders     F12  screenshot
//   Esc    quit
#pragma once

#include "app/commands.h"

namespace planet {

// True when a window can be opened (an X11 or Wayland display is named).
bool displayAvailable();

}  // namespace planet
