// Fuzzes parseView (app/views.h). Bad input must come out as an InputError; any other
// exception, a crash or a sanitizer report fails. A view that loads must hold finite numbers
// in its documented ranges and place a finite sun.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "app/views.h"
#include "fuzz/fuzz_check.h"

using namespace planet;

namespace {

void requireIn(double v, double lo, double hi, const char* what) {
    fuzz::requireFinite(v, what);
    if (!(v >= lo && v <= hi)) fuzz::fail(std::string(what) + " out of its range: " + std::to_string(v));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> warnings;
    View view;
    try {
        view = parseView(text, "fuzz.toml", "fuzz", &warnings);
    } catch (const InputError&) {
        return 0;  // rejected as documented
    }
    requireIn(view.latitude_deg, -90.0, 90.0, "latitude_deg");
    requireIn(view.longitude_deg, -180.0, 180.0, "longitude_deg");
    requireIn(view.altitude_m, 0.1, 1e9, "altitude_m");
    requireIn(view.heading_deg, -360.0, 360.0, "heading_deg");
    requireIn(view.pitch_deg, -90.0, 90.0, "pitch_deg");
    requireIn(view.fov_deg, 1.0, 170.0, "fov_deg");
    if (view.sun_elevation_deg.has_value() != view.sun_azimuth_deg.has_value()) fuzz::fail("half a sun accepted");
    if (view.hasSun()) {
        requireIn(*view.sun_elevation_deg, -90.0, 90.0, "sun_elevation_deg");
        requireIn(*view.sun_azimuth_deg, -360.0, 360.0, "sun_azimuth_deg");
    }
    Scene scene;
    applyViewSun(view, scene);
    fuzz::requireFinite(subsolarDirection(view, scene), "sun direction");
    return 0;
}
