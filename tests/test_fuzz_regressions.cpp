// Inputs the fuzzers (fuzz/) turned up, kept as tests of the normal build. Each is also in
// the fuzzers' seed corpus (fuzz/corpus/). All are toml++'s: version 3.3.0, as Debian ships it,
// asserts (debug builds) or reaches __builtin_unreachable (any build) on them, where the
// library we link (GCC, release) reports a syntax error or reads them right. These tests pin
// that down for the presets and views users write.
#include <gtest/gtest.h>

#include <string>

#include "app/views.h"
#include "scene/preset.h"
#include "test_util.h"

namespace planet {
namespace {

using test::contains;
using test::expectInputError;

TEST(FuzzRegressions, ATableHeaderStartingWithAnInvalidCharacterIsASyntaxError) {
    // parse_key's precondition (upstream PR #301): "[" then neither a bare key character nor a quote.
    const InputError preset = expectInputError([] { parsePreset("name = \"x\"\n[planet]\n[\x11" "de_m = 0.4\n", "p.toml"); });
    EXPECT_EQ(preset.file, "p.toml");
    EXPECT_EQ(preset.line, 3);
    EXPECT_TRUE(contains(preset.what(), "TOML syntax error")) << preset.what();
    const InputError view = expectInputError([] { parseView("[[/cean]\x03\n", "v.toml", "v"); });
    EXPECT_EQ(view.line, 1);
}

TEST(FuzzRegressions, ANonAsciiCharacterAfterAKeyIsASyntaxError) {
    // U+03CE after a key: toml++'s whitespace table reaches its "unreachable" default (upstream #295).
    const InputError e = expectInputError([] {
        parsePreset("[[ocean.wave]]\norigin = [0.0, 0.0, 1.0]\namplitude\xcf\x8e = 1.0\nwavelength_m = 5.0\n", "w.toml");
    });
    EXPECT_EQ(e.line, 3);
    EXPECT_TRUE(contains(e.what(), "TOML syntax error")) << e.what();
}

TEST(FuzzRegressions, ALineEndingBackslashKeepsTheNonAsciiCharacterAfterIt) {
    // The same table, reached from a multi-line string's line-ending backslash (upstream #190).
    const PresetLoad p = parsePreset("description = \"\"\"\\\n\xc2\xa7 and \xcf\x8e\"\"\"\n", "d.toml");
    EXPECT_EQ(p.description, "\xc2\xa7 and \xcf\x8e");
}

}  // namespace
}  // namespace planet
