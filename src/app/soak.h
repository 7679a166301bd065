// `planet bench --suite soak`: a long run that looks for leaks. The renderer flies a path
// through every view (a keyframe at each, 100 frames apart), one parameter edit every 100
// frames (exposure, cloud coverage, the atmosphere's Mie asymmetry and Rayleigh scattering,
// which remake the tables, the sea's wind, which remakes the waves, the terrain's height, the
// temporal march on and off, a resize, a forced reload of every shader), and every 100 frames
// samples the process's resident memory and the context's live GL objects (gl/live_objects.h)
// into a CSV. The summary says whether both were flat after the warm-up: the GL objects
// exactly, the memory as a slope over the second half of the run.
#pragma once

#include <glm/glm.hpp>

#include "app/commands.h"
#include "app/session.h"
#include "render/renderer.h"

namespace planet {

// Runs `frames` frames; writes options.csv when set. Returns 0 when both stayed flat, else 1
// (the report says which grew).
int benchSoak(Renderer& renderer, Session& session, glm::ivec2 size, int frames, const BenchOptions& options);

}  // namespace planet
