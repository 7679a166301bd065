// The [atmosphere] rows of the scene parameter table (see scene/scene_params.h).
//
// Kept apart from atmosphere_params.h so that the plain struct stays free of
// the table machinery: scene.h includes the struct, and scene_params.h (which
// includes scene.h) is included only here and by the table's builder.
#pragma once

#include <vector>

#include "scene/scene_params.h"

namespace planet {

// Appends one row per field of AtmosphereParams, section "atmosphere", in the
// struct's order. Called by the table builder between the planet and sun rows.
void addAtmosphereParams(std::vector<ParamSpec>& table);

}  // namespace planet
