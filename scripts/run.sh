#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs planet; with no arguments,
# the explorer. Without a display the explorer renders a still and prints
# where it wrote it. Extra arguments go to planet, e.g.
#   bash scripts/run.sh render --view space --out space.png
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
exec build/planet "$@"
