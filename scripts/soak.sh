#!/usr/bin/env bash
# The long soak (not in CI): `planet bench --suite soak` for FRAMES frames (default 10000) at
# SIZE (default 64x36) along a path through every view, an edit every 100 frames (tables,
# waves, targets, every shader rebuilt), sampling resident memory and live GL objects every
# 100 frames into out/soak.csv. Exit status 1 when either grew after the warm-up.
# About 30 minutes for 10000 frames on two llvmpipe cores. Results: docs/PERFORMANCE.md "Soak".
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh >/dev/null
frames=${FRAMES:-10000}
size=${SIZE:-64x36}
mkdir -p out
./build/planet bench --suite soak --frames "$frames" --size "$size" --csv out/soak.csv "$@"
