// The [terrain] rows of the scene parameter table (see scene/scene_params.h).
//
// Kept apart from terrain_params.h so that the plain struct stays free of the
// table machinery, as atmosphere/atmosphere_params_table.h does.
//
// Unlike addAtmosphereParams, the rows reach TerrainParams through an accessor
// the table builder passes in, so this file does not name the Scene member:
// it compiles whether or not Scene holds the terrain yet, and the one place
// that wires the struct into Scene is the builder's call.
#pragma once

#include <vector>

#include "scene/scene_params.h"
#include "terrain/terrain_params.h"

namespace planet {

// Appends one row per field of TerrainParams (Scene::terrain), section
// "terrain", in the struct's order.
void addTerrainParams(std::vector<ParamSpec>& table);

}  // namespace planet
