#!/usr/bin/env bash
# Remakes tests/reference/sky_rays.csv and sky_full_reference.csv, the rays and the
# CPU double-precision sky at full table size that tests/test_sky_accuracy.cpp holds
# the `auto` tables to (issue 14). About 10 minutes on two cores (the full tables
# in double). Run it after a change to the atmosphere model, and commit both files.
set -euo pipefail
cd "$(dirname "$0")/.."
planet=${PLANET_EXE:-build/planet}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Cameras 1, 5, 20 and 100 km up (5 and 20 km fall between the r layers of the
# smaller tables); the sun from the zenith to 5 deg below the horizon; views from
# the zenith to the nadir, dense about each camera's horizon and the limb; five
# azimuths.
{
  echo "altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg"
  for h in 1000 5000 20000 100000; do
    for s in 0 30 60 75 80 85 90 93 95; do
      for v in 0 30 60 80 85 88 89.5 90 90.5 92 95 96.5 97 97.5 98 99 99.5 100 101 102 105 120 150 180; do
        for a in 0 45 90 135 180; do echo "$h,$s,$v,$a"; done
      done
    done
  done
} > "$work/rays.csv"
printf '[clouds]\nenabled = false\n' > "$work/clear.toml"
PLANET_CACHE="$work/cache" "$planet" sky-probe --preset "$work/clear.toml" --tables full --reference \
  --in "$work/rays.csv" --out "$work/all.csv"
# Keep the rays that see some light (above sky_accuracy.h's floor, 1e-6 /sr, in a channel).
awk -F, 'NR == 1 || $5 >= 1e-6 || $6 >= 1e-6 || $7 >= 1e-6' "$work/all.csv" > tests/reference/sky_full_reference.csv
cut -d, -f1-4 tests/reference/sky_full_reference.csv > tests/reference/sky_rays.csv
echo "wrote tests/reference/sky_rays.csv and sky_full_reference.csv ($(($(wc -l < tests/reference/sky_rays.csv) - 1)) rays)"
