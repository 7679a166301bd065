// The parameter table: one row per tunable scene parameter.
//
// A row names the TOML section and key, its unit, valid range and help text,
// and how to reach the field inside a Scene. Presets are read and written by
// walking this table; the explorer draws one widget per row. Ranges are
// inclusive and apply to every component of a vector parameter.
#pragma once

#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "scene/scene.h"

namespace planet {

using ParamRef = std::variant<double*, int*, glm::dvec3*, bool*>;

struct ParamSpec {
    std::string section;  // TOML table, e.g. "planet"
    std::string key;      // key inside the table, e.g. "radius_km"
    std::string unit;     // "km", "deg", "" for dimensionless
    double min = 0.0;     // inclusive; ignored for bool
    double max = 0.0;
    std::string help;
    std::function<ParamRef(Scene&)> field;

    std::string path() const { return section + "." + key; }
};

// Every parameter of a Scene, grouped by section in a stable order.
const std::vector<ParamSpec>& sceneParams();

}  // namespace planet
