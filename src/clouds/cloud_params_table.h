// The [clouds] rows of the scene parameter table (see scene/scene_params.h), kept apart
// from the plain struct as the terrain's are.
#pragma once

#include <vector>

#include "clouds/cloud_params.h"
#include "scene/scene_params.h"

namespace planet {

// Appends one row per field of CloudParams (Scene::clouds), section "clouds".
void addCloudParams(std::vector<ParamSpec>& table);

}  // namespace planet
