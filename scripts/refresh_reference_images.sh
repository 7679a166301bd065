#!/usr/bin/env bash
# Refreshes the stored reference images (tests/reference/<view>.exr) after an
# intended change of what a frame shows. Builds the test executable if needed
# (in $BUILD_DIR, default build/), then runs the reference-image test with
# PLANET_UPDATE_REFERENCES=1, which renders each view exactly as the test compares
# it (= `planet render --preset earth --view VIEW --size 160x90 --tables reduced`)
# and writes it over the stored one instead of comparing.
#
#   bash scripts/refresh_reference_images.sh            # every view
#   bash scripts/refresh_reference_images.sh sea beach  # only these
#
# Then look at the change (e.g. build/planet compare NEW OLD --diff d.png, with the
# old one from `git show HEAD:tests/reference/VIEW.exr > old.exr`) and commit tests/reference/.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
[ -f "$build/build.ninja" ] || cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target planet_tests -j "$(nproc)"

filter='Earth/ReferenceImages.*'
if (($#)); then
  filter=""
  for view in "$@"; do filter+="${filter:+:}Earth/ReferenceImages.MatchStoredImage/$view"; done
fi
# From the tests' folder, as CTest runs them, so the atmosphere tables come from its cache.
cd "$build/tests"
PLANET_UPDATE_REFERENCES=1 ./planet_tests --gtest_filter="$filter" | grep -E '^wrote |FAILED|tests ran'
