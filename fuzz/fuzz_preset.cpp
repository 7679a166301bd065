// Fuzzes parsePreset (scene/preset.h). Bad input must come out as an InputError; any other
// exception, a crash or a sanitizer report fails. A preset that loads must hold finite numbers,
// pass validateScene, and read back the same from presetToToml (the round trip preset.h promises).
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <variant>

#include "fuzz/fuzz_check.h"
#include "scene/preset.h"
#include "scene/preset_waves.h"
#include "scene/scene_params.h"

using namespace planet;

namespace {

void checkLoaded(PresetLoad& load) {
    for (const ParamSpec& spec : sceneParams())
        std::visit([&](auto* p) { fuzz::requireFinite(*p, spec.path()); }, spec.field(load.scene));
    for (const ocean::GerstnerWave& w : load.scene.waves) {
        fuzz::requireFinite(w.origin, "wave origin");
        for (double v : {w.amplitude_m, w.wavelength_m, w.steepness, w.speed_mps, w.phase_rad})
            fuzz::requireFinite(v, "wave field");
    }
    if (!validateScene(load.scene).empty()) fuzz::fail("a loaded preset fails validateScene");

    PresetLoad again;
    try {
        again = parsePreset(presetToToml(load.scene, load.name, load.description), "written.toml");
    } catch (const InputError& e) {
        fuzz::fail(std::string("the written preset does not load: ") + e.what());
    }
    if (again.name != load.name || again.description != load.description) fuzz::fail("name or description changed");
    const auto same = [](auto* a, auto* b) {
        if constexpr (std::is_same_v<decltype(a), decltype(b)>) return bool(*a == *b);
        return false;
    };
    for (const ParamSpec& spec : sceneParams())
        if (!std::visit(same, spec.field(again.scene), spec.field(load.scene)))
            fuzz::fail(spec.path() + " reads back different");
    if (!sameWaves(again.scene.waves, load.scene.waves)) fuzz::fail("the waves read back different");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    PresetLoad load;
    try {
        load = parsePreset(text, "fuzz.toml");
    } catch (const InputError&) {
        return 0;  // rejected as documented
    }
    checkLoaded(load);
    return 0;
}
