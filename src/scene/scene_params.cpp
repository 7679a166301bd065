// Scene parameter table and the geometry helpers of scene.h (see scene_params.h).
#include "scene/scene_params.h"

#include <cmath>

namespace planet {

glm::dvec3 directionFromLatLon(double latitudeDeg, double longitudeDeg) {
    const double lat = glm::radians(latitudeDeg);
    const double lon = glm::radians(longitudeDeg);
    return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

glm::dvec3 Scene::sunDirection() const { return directionFromLatLon(sun.latitude_deg, sun.longitude_deg); }

namespace {

std::vector<ParamSpec> buildTable() {
    std::vector<ParamSpec> t;
    auto add = [&](const char* section, const char* key, const char* unit, double lo, double hi, const char* help,
                   std::function<ParamRef(Scene&)> field) {
        t.push_back(ParamSpec{section, key, unit, lo, hi, help, std::move(field)});
    };
    add("planet", "radius_km", "km", 1.0, 1e5, "Radius of the solid planet (sea level).",
        [](Scene& s) { return ParamRef{&s.planet.radius_km}; });
    add("planet", "albedo", "", 0.0, 1.0, "Ground reflectance of the placeholder sphere, linear RGB.",
        [](Scene& s) { return ParamRef{&s.planet.albedo}; });
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
    return t;
}

}  // namespace

const std::vector<ParamSpec>& sceneParams() {
    static const std::vector<ParamSpec> table = buildTable();  // immutable after first use
    return table;
}

}  // namespace planet
