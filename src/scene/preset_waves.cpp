// [[ocean.wave]] lists: reading with file:line errors, writing round-trippably (preset_waves.h).
#include "scene/preset_waves.h"

#include <cmath>

#include "scene/scene.h"
#include "scene/toml_error.h"

namespace planet {

namespace {


// The scalar fields and the ranges a preset may give them (the explorer's panel uses the same;
// validateWaves then checks the set as a whole).
const std::vector<WaveField> kWaveFields = {
    {"amplitude_m", 0.0, 1000.0, "m", &ocean::GerstnerWave::amplitude_m},
    {"wavelength_m", 1e-3, 1e7, "m", &ocean::GerstnerWave::wavelength_m},
    {"steepness", 0.0, 1.0, "", &ocean::GerstnerWave::steepness},
    {"speed_mps", -1e4, 1e4, "m/s", &ocean::GerstnerWave::speed_mps},
    {"phase_rad", -1e6, 1e6, "rad", &ocean::GerstnerWave::phase_rad},
};

std::string tomlFloat(double value) {
    std::string text = formatNumber(value);
    if (text.find_first_of(".eni") == std::string::npos) text += ".0";
    return text;
}

ocean::GerstnerWave readWave(const toml::table& table, const std::string& file, const std::string& path) {
    ocean::GerstnerWave wave;
    const toml::node* origin = table.get("origin");
    const toml::node* lat = table.get("latitude_deg");
    const toml::node* lon = table.get("longitude_deg");
    if (origin && (lat || lon))
        throw InputError(file, sourceLine(*origin), path + ".origin", "give origin or latitude_deg/longitude_deg, not both");
    if (origin) {
        const glm::dvec3 o = readVec3(*origin, file, path + ".origin");
        const double length = glm::length(o);
        if (!(length > 1e-9) || !std::isfinite(length))
            throw InputError(file, sourceLine(*origin), path + ".origin", "must be a non-zero finite vector");
        // Normalised unless it already is (so a written preset reads back bit for bit).
        wave.origin = std::abs(length - 1.0) < 1e-12 ? o : o / length;
    } else if (lat && lon) {
        const double latitude = readNumber(*lat, file, path + ".latitude_deg");
        const double longitude = readNumber(*lon, file, path + ".longitude_deg");
        checkRange(latitude, -90.0, 90.0, "deg", locate(*lat, file, path + ".latitude_deg"));
        checkRange(longitude, -180.0, 180.0, "deg", locate(*lon, file, path + ".longitude_deg"));
        wave.origin = directionFromLatLon(latitude, longitude);
    } else {
        throw InputError(file, sourceLine(table), path, "a wave needs origin = [x, y, z] or latitude_deg and longitude_deg");
    }
    for (const WaveField& f : kWaveFields) {
        const toml::node* node = table.get(f.key);
        if (!node) continue;
        const std::string field = path + "." + f.key;
        const double value = readNumber(*node, file, field);
        checkRange(value, f.lo, f.hi, f.unit, locate(*node, file, field));
        wave.*f.member = value;
    }
    if (!table.get("wavelength_m")) throw InputError(file, sourceLine(table), path + ".wavelength_m", "missing");
    if (!table.get("amplitude_m")) throw InputError(file, sourceLine(table), path + ".amplitude_m", "missing");
    if (!table.get("speed_mps")) wave.speed_mps = ocean::deepWaterSpeed(wave.wavelength_m);
    for (auto&& [key, value] : table) {
        const std::string name(key.str());
        bool known = name == "origin" || name == "latitude_deg" || name == "longitude_deg";
        for (const WaveField& f : kWaveFields) known = known || name == f.key;
        if (!known) throw InputError(file, sourceLine(value), path + "." + name, "unknown wave field");
    }
    return wave;
}

}  // namespace

std::vector<ocean::GerstnerWave> readWaveList(const toml::node& node, const std::string& file) {
    const toml::array* array = node.as_array();
    if (!array) throw InputError(file, sourceLine(node), "ocean.wave", "expected [[ocean.wave]] tables, got " + typeName(node));
    std::vector<ocean::GerstnerWave> waves;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const std::string path = "ocean.wave[" + std::to_string(i) + "]";
        const toml::table* table = array->get(i)->as_table();
        if (!table) throw InputError(file, sourceLine(*array->get(i)), path, "expected a table");
        waves.push_back(readWave(*table, file, path));
    }
    return waves;
}

std::string waveListToToml(const std::vector<ocean::GerstnerWave>& waves) {
    std::string text;
    for (const ocean::GerstnerWave& w : waves) {
        text += "\n[[ocean.wave]]\n";
        text += "origin = [" + tomlFloat(w.origin.x) + ", " + tomlFloat(w.origin.y) + ", " + tomlFloat(w.origin.z) + "]\n";
        for (const WaveField& f : kWaveFields) text += std::string(f.key) + " = " + tomlFloat(w.*f.member) + "\n";
    }
    return text;
}

const std::vector<WaveField>& waveFields() { return kWaveFields; }

bool sameWaves(const std::vector<ocean::GerstnerWave>& a, const std::vector<ocean::GerstnerWave>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].origin != b[i].origin) return false;
        for (const WaveField& f : kWaveFields)
            if (a[i].*f.member != b[i].*f.member) return false;
    }
    return true;
}

}  // namespace planet
