#!/usr/bin/env bash
# Runs the sanitizer build's test suite, or one shard of it, under ASan and UBSan:
#     bash tests/run_sanitized.sh BUILD [SHARD SHARDS]        e.g. build-sanitize 0 2
# CTest's sanitized.unit_tests.N run this (tests/sanitized_suite.cmake). Any ASan, UBSan or
# LeakSanitizer report fails the run (UBSan is built with -fno-sanitize-recover), as does a
# failing test.
#
# The suites that need GL are left out: a fixture on test::GLTest, SharedRendererTest or CliFixture, or a
# test that makes a HeadlessContext or runs the planet executable (runCommand), as found in
# tests/*.cpp. Under ASan, llvmpipe makes them take about 8 minutes on two cores, and Mesa's
# own leaks cannot be suppressed (they come from unloaded modules, with no frames to match).
# PLANET_SANITIZE_GL=1 runs them too (by hand), with leak detection off.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" 2>/dev/null && pwd || echo "$1")
bin=$build/tests/planet_tests
if [ ! -x "$bin" ]; then
  echo "error: $bin is not built: run bash scripts/build_sanitize.sh first" >&2
  exit 1
fi
export GTEST_SHARD_INDEX=${2:-0} GTEST_TOTAL_SHARDS=${3:-1}
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
filter='*'
if [ "${PLANET_SANITIZE_GL:-0}" = 1 ]; then
  export ASAN_OPTIONS=detect_leaks=0
else
  export ASAN_OPTIONS=detect_leaks=1
  gl_suites=$(awk '
    FNR == 1 { suite = "" }
    /^class [A-Za-z0-9_]+ *: *public .*(GLTest|SharedRendererTest|CliFixture)/ { name = $2; sub(/[^A-Za-z0-9_].*/, "", name); print name }
    /^(TEST|TEST_F|TEST_P)\(/ { suite = $0; sub(/^[A-Z_]+\(/, "", suite); sub(/,.*/, "", suite) }
    suite != "" && /runCommand\(|HeadlessContext/ { print suite }' "$here"/*.cpp "$here"/*.h | sort -u)
  filter='*-'
  for s in $gl_suites; do filter+="$s.*:*/$s.*:"; done
  echo "sanitized run without the suites that need GL: $(echo $gl_suites)"
fi
cd "$build/tests"  # the tests' caches and outputs stay in the sanitizer build
exec "$bin" --gtest_filter="$filter"
