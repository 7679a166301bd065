// Fuzzes readWaveList (scene/preset_waves.h) on the ocean.wave node of a TOML document (the
// root table when it has none, for the wrong-type path). Text toml++ rejects is skipped; a list
// the reader rejects must be an InputError. An accepted list must hold finite values in their
// ranges and unit origins, and read back the same from waveListToToml.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "fuzz/fuzz_check.h"
#include "scene/preset_waves.h"
#include "scene/toml_error.h"

using namespace planet;

namespace {

void checkWaves(const std::vector<ocean::GerstnerWave>& waves) {
    for (const ocean::GerstnerWave& w : waves) {
        fuzz::requireFinite(w.origin, "origin");
        if (std::abs(glm::length(w.origin) - 1.0) > 1e-9) fuzz::fail("origin not a unit vector");
        for (const WaveField& f : waveFields()) {
            const double v = w.*f.member;
            fuzz::requireFinite(v, f.key);
            if (std::string(f.key) != "speed_mps" && !(v >= f.lo && v <= f.hi))  // speed: derived when absent
                fuzz::fail(std::string(f.key) + " out of its range: " + std::to_string(v));
        }
    }
    const std::string written = waveListToToml(waves);
    try {
        const toml::table again = toml::parse(written, std::string_view("written.toml"));
        const toml::node* list = again.at_path("ocean.wave").node();
        if (waves.empty() ? list != nullptr : (!list || !sameWaves(readWaveList(*list, "written.toml"), waves)))
            fuzz::fail("the written wave list reads back different");
    } catch (const std::exception& e) {
        fuzz::fail(std::string("the written wave list does not load: ") + e.what());
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    toml::table root;
    try {
        root = toml::parse(text, std::string_view("fuzz.toml"));
    } catch (const toml::parse_error&) {
        return 0;  // not TOML: the preset reader's concern (fuzz_preset), not the wave list's
    }
    const toml::node* list = root.at_path("ocean.wave").node();
    std::vector<ocean::GerstnerWave> waves;
    try {
        waves = readWaveList(list ? *list : root, "fuzz.toml");
    } catch (const InputError&) {
        return 0;  // rejected as documented
    }
    checkWaves(waves);
    return 0;
}
