// Scene parameter table, scene validation and the geometry helpers of scene.h
// (see scene_params.h). The atmosphere rows live beside their struct, in
// atmosphere/atmosphere_params.cpp.
#include "scene/scene_params.h"

#include <cmath>
#include <variant>

#include "atmosphere/atmosphere_params_table.h"
#include "atmosphere/parameters.h"
#include "clouds/cloud_params_table.h"
#include "ocean/ocean_params_table.h"
#include "terrain/terrain_params_table.h"
#include "scene/toml_error.h"

namespace planet {

glm::dvec3 directionFromLatLon(double latitudeDeg, double longitudeDeg) {
    const double lat = glm::radians(latitudeDeg);
    const double lon = glm::radians(longitudeDeg);
    return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

glm::dvec3 Scene::sunDirection() const { return directionFromLatLon(sun.latitude_deg, sun.longitude_deg); }

namespace {
double wrap(double x, double period) { return x - period * std::floor(x / period); }
double placeLongitudeDeg(glm::dvec3 place) { return glm::degrees(std::atan2(place.y, place.x)); }
}  // namespace

double localSolarHour(const SunParams& sun, glm::dvec3 place) {
    return wrap(12.0 + (placeLongitudeDeg(place) - sun.longitude_deg) / 15.0, 24.0);
}

void setLocalSolarHour(SunParams& sun, glm::dvec3 place, double hour) {
    sun.longitude_deg = wrap(placeLongitudeDeg(place) - (hour - 12.0) * 15.0 + 180.0, 360.0) - 180.0;
}

namespace {

std::vector<ParamSpec> buildTable() {
    std::vector<ParamSpec> t;
    auto add = [&](const char* section, const char* key, const char* unit, double lo, double hi, const char* help,
                   std::function<ParamRef(Scene&)> field) {
        t.push_back(ParamSpec{section, key, unit, lo, hi, help, std::move(field)});
    };
    add("planet", "radius_km", "km", 1.0, 1e5, "Radius of the solid planet (sea level).",
        [](Scene& s) { return ParamRef{&s.planet.radius_km}; });
    add("planet", "albedo", "", 0.0, 1.0, "Albedo of the lowlands (grass on Earth, dust on Mars), linear RGB; sand, rock and snow have their own.",
        [](Scene& s) { return ParamRef{&s.planet.albedo}; });
    addAtmosphereParams(t);
    addTerrainParams(t);
    addOceanParams(t);
    addCloudParams(t);
    add("sun", "latitude_deg", "deg", -90.0, 90.0, "Latitude of the subsolar point.",
        [](Scene& s) { return ParamRef{&s.sun.latitude_deg}; });
    add("sun", "longitude_deg", "deg", -180.0, 180.0, "Longitude of the subsolar point.",
        [](Scene& s) { return ParamRef{&s.sun.longitude_deg}; });
    add("sun", "irradiance", "W/m^2/nm", 0.0, 100.0, "Solar irradiance at the top of the atmosphere (R, G, B).",
        [](Scene& s) { return ParamRef{&s.sun.irradiance}; });
    add("sun", "angular_radius_rad", "rad", 1e-4, 0.1, "Apparent angular radius of the sun disc.",
        [](Scene& s) { return ParamRef{&s.sun.angular_radius_rad}; });
    add("render", "exposure", "", 1e-3, 1e3, "Exposure applied before tone mapping.",
        [](Scene& s) { return ParamRef{&s.render.exposure}; });
    add("render", "temporal", "", 0.0, 1.0,
        "March clouds and air in one pixel of each 4x4 block a frame and reproject the rest from the previous "
        "frames (about 1/10 of the cost); off: every pixel every frame, for reference frames.",
        [](Scene& s) { return ParamRef{&s.render.temporal}; });
    add("render", "temporal_refine_error", "", 0.0, 1.0,
        "With the temporal march, in a moving frame: march again at full rate the pixels around a sample whose "
        "history was off by more than this share (three times it where only the clock ran; also those with nothing "
        "to reproject, on an edge, or with a history read across one); lower: closer to the full rate, and dearer. "
        "1: only those.",
        [](Scene& s) { return ParamRef{&s.render.temporal_refine_error}; });
    return t;
}

}  // namespace

const std::vector<ParamSpec>& sceneParams() {
    static const std::vector<ParamSpec> table = buildTable();  // immutable after first use
    return table;
}

namespace {

// Same wording as checkRange (toml_error.h), so a save and a load report alike.
std::string outOfRange(double value, const ParamSpec& spec) {
    std::string message = "value " + formatNumber(value) + " is out of range [" + formatNumber(spec.min) + ", " +
                          formatNumber(spec.max) + "]";
    return spec.unit.empty() ? message : message + " " + spec.unit;
}

void checkRanges(const Scene& scene, std::vector<SceneProblem>& problems) {
    Scene copy = scene;  // the table's accessors take a mutable Scene
    auto check = [&](double value, const ParamSpec& spec, const std::string& field) {
        if (!(value >= spec.min && value <= spec.max)) problems.push_back({field, outOfRange(value, spec)});
    };
    for (const ParamSpec& spec : sceneParams()) {
        const ParamRef ref = spec.field(copy);
        if (const auto* d = std::get_if<double*>(&ref)) check(**d, spec, spec.path());
        if (const auto* i = std::get_if<int*>(&ref)) check(**i, spec, spec.path());
        if (const auto* v = std::get_if<glm::dvec3*>(&ref))
            for (int c = 0; c < 3; ++c) check((**v)[c], spec, spec.path() + "[" + std::to_string(c) + "]");
    }
}

}  // namespace

std::vector<SceneProblem> validateScene(const Scene& scene) {
    std::vector<SceneProblem> problems;
    checkRanges(scene, problems);
    const AtmosphereParams& a = scene.atmosphere;
    if (!(a.top_radius_km > scene.planet.radius_km)) {
        problems.push_back({"atmosphere.top_radius_km",
                            "top of the atmosphere " + formatNumber(a.top_radius_km) +
                                " km must be above planet.radius_km " + formatNumber(scene.planet.radius_km) +
                                " km (the bottom of the atmosphere)"});
    }
    static const char* channel[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        if (a.mie_extinction_per_m[c] >= a.mie_scattering_per_m[c]) continue;
        problems.push_back({"atmosphere.mie_extinction_per_m",
                            std::string("component ") + std::to_string(c) + " (" + channel[c] + ") " +
                                formatNumber(a.mie_extinction_per_m[c]) +
                                " 1/m is below atmosphere.mie_scattering_per_m " +
                                formatNumber(a.mie_scattering_per_m[c]) +
                                " 1/m; extinction is scattering + absorption, so at least scattering"});
        break;  // one problem per rule: the first component that breaks it
    }
    // Where the atmosphere tables hold (atmosphere/parameters.h): only for a scene whose
    // ranges and the rules above pass, since the limits evaluate the model.
    if (problems.empty())
        for (const atmosphere::AtmosphereLimitProblem& p : atmosphere::checkAtmosphereLimits(scene))
            problems.push_back({p.field, p.message});
    if (scene.terrain.grid_exponent != 2 && scene.terrain.grid_exponent != 4)
        problems.push_back({"terrain.grid_exponent", "must be 2 or 4 (Michelic Eq. 2), not " +
                                                         std::to_string(scene.terrain.grid_exponent)});
    if (const std::string ocean = ocean::validateOceanParams(scene.ocean); !ocean.empty())
        problems.push_back({"ocean.fade_end", ocean});
    if (const std::string waves = ocean::validateWaves(scene.waves); !waves.empty())
        problems.push_back({"ocean.wave", waves});
    const CloudParams& c = scene.clouds;
    if (!(c.top_altitude_km > c.bottom_altitude_km))
        problems.push_back({"clouds.top_altitude_km", "top of the cloud layer " + formatNumber(c.top_altitude_km) +
                                                          " km must be above clouds.bottom_altitude_km " +
                                                          formatNumber(c.bottom_altitude_km) + " km"});
    else if (c.enabled && a.top_radius_km > scene.planet.radius_km &&  // a broken atmosphere is its own problem
             !(scene.planet.radius_km + c.top_altitude_km < a.top_radius_km))
        problems.push_back({"clouds.top_altitude_km", "top of the cloud layer " + formatNumber(c.top_altitude_km) +
                                                          " km must lie inside the atmosphere (atmosphere.top_radius_km - "
                                                          "planet.radius_km = " +
                                                          formatNumber(a.top_radius_km - scene.planet.radius_km) +
                                                          " km)"});
    return problems;
}

}  // namespace planet
