#!/usr/bin/env bash
# Builds planet, its tests and the fuzz targets (fuzz/) with clang, AddressSanitizer and
# UBSan into build-sanitize/. scripts/test.sh runs them as part of the main suite
# (tests/sanitized_suite.cmake). Needs the packages scripts/setup.sh installs.
set -euo pipefail
cd "$(dirname "$0")/.."

# -O2: at -O1 glm's small vectors are copied through ASan's memcpy (the CPU reference runs 20x slower);
# line tables for readable reports.
# Warnings stay warnings here: clang's differ from GCC's, which the main build holds to -Werror.
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only" \
  -DPLANET_FUZZ=ON -DPLANET_WERROR=OFF >/dev/null
cmake --build build-sanitize -j "$(nproc)"
