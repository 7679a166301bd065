// The [ocean] rows of the scene parameter table (see scene/scene_params.h), kept
// apart from ocean_params.h as terrain/terrain_params_table.h is. The individual
// waves are not rows: they are the preset's [[ocean.wave]] list (scene/preset.cpp).
#pragma once

#include <vector>

#include "scene/scene_params.h"

namespace planet {

// Appends one row per field of OceanParams (Scene::ocean), section "ocean".
void addOceanParams(std::vector<ParamSpec>& table);

// True for the rows the generated wave set depends on (a change regenerates Scene::waves).
bool isWaveGeneratorParam(const ParamSpec& spec);

}  // namespace planet
