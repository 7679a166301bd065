#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs the whole test suite with
# CTest. GL tests run headless on EGL (Mesa surfaceless on machines without a
# GPU); one test opens a real window under Xvfb. The suite also runs a second
# build, build-sanitize/ (clang, ASan + UBSan, scripts/build_sanitize.sh): its
# tests that need no GL and the fuzz targets (tests/sanitized_suite.cmake).
# The last line printed is CTest's summary.
set -uo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh || exit 1
bash scripts/build_sanitize.sh || exit 1
cmake -S . -B build -DPLANET_SANITIZED_BUILD=build-sanitize >/dev/null || exit 1
log=$(mktemp)
(cd build && ctest --output-on-failure -j "$(nproc)") 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
grep -E '^[0-9]+% tests passed' "$log" | tail -n 1
rm -f "$log"
exit "$status"
