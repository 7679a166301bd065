// The parameter table: one row per tunable scene parameter.
//
// A row names the TOML section and key, its unit, valid range and help text,
// and how to reach the field inside a Scene. Presets are read and written by
// walking this table; the explorer draws one widget per row. Ranges are
// inclusive and apply to every component of a vector parameter.
//
// validateScene adds the rules a single row cannot express (cross-field
// rules); presets are checked against it on load and before saving.
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

// Every parameter of a Scene, grouped by section in a stable order
// (planet, atmosphere, terrain, ocean, clouds, sun, render).
const std::vector<ParamSpec>& sceneParams();

// One reason a scene is not valid, blamed on one parameter.
struct SceneProblem {
    std::string field;    // dotted path to blame, e.g. "atmosphere.top_radius_km" or "...[1]" for a component
    std::string message;  // what is wrong, with the values involved
};

// Everything that makes a scene unusable, in a stable order: first each
// parameter outside its table range (worded as checkRange words it), then
// the cross-field rules:
//   - atmosphere.top_radius_km > planet.radius_km (the atmosphere's bottom);
//   - atmosphere.mie_extinction_per_m >= atmosphere.mie_scattering_per_m per
//     component, since extinction = scattering + absorption;
//   - terrain.grid_exponent is 2 or 4;
//   - ocean.fade_end > ocean.fade_start (Michelic Eq. 11);
//   - every wave of Scene::waves passes ocean::validateWaves (blamed on "ocean.wave");
//   - clouds.top_altitude_km > clouds.bottom_altitude_km, and, with clouds on, the layer inside
//     the atmosphere.
// Empty when the scene is valid: then presetToToml(scene) loads back.
std::vector<SceneProblem> validateScene(const Scene& scene);

}  // namespace planet
