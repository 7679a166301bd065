// Fuzzes parseProbeCases (app/sky_probe_cases.h). Bad input must come out as an InputError;
// any other exception, a crash or a sanitizer report fails. Accepted rows must hold finite
// numbers in their ranges, each echoed by a non-empty field.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "app/sky_probe_cases.h"
#include "fuzz/fuzz_check.h"
#include "scene/toml_error.h"

using namespace planet;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<ProbeRow> rows;
    try {
        rows = parseProbeCases(text, "fuzz.csv");
    } catch (const InputError&) {
        return 0;  // rejected as documented
    }
    for (const ProbeRow& row : rows) {
        const double values[4] = {row.altitudeM, row.sunZenithDeg, row.viewZenithDeg, row.viewAzimuthDeg};
        const double lo[4] = {0.0, 0.0, 0.0, -360.0}, hi[4] = {1e9, 180.0, 180.0, 360.0};
        for (int c = 0; c < 4; ++c) {
            fuzz::requireFinite(values[c], kProbeInputColumns[c]);
            if (!(values[c] >= lo[c] && values[c] <= hi[c])) fuzz::fail(std::string(kProbeInputColumns[c]) + " out of range");
            if (row.text[c].empty()) fuzz::fail("an empty field accepted");
        }
    }
    return 0;
}
