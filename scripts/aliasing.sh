#!/usr/bin/env bash
# The aliasing check (issue 13; not in CI, tests/test_aliasing.cpp is its small version):
# each view in VIEWS (default: space orbit mountains) is rendered at SMALL (default
# 640x360) and, as the reference, at 4x the size (2560x1440) with one sample; the
# reference is averaged 4x4 down (`planet compare --reference-scale 4`: 16 samples on a
# regular grid in each small pixel, a box filter) and the small still is judged against it
# in linear luminance: mean relative error (and p99), with the false-colour error image
# beside it. The small still is rendered once per entry of SAMPLES (default "1 default":
# one unjittered frame, and `planet render`'s default accumulation).
#
#   bash scripts/aliasing.sh                  # all three views; out/aliasing/
#   VIEWS=mountains SAMPLES="1 4 8" bash scripts/aliasing.sh
#   ROOT=/tmp/snapshot bash scripts/aliasing.sh   # shaders and assets from elsewhere (planet --root)
#
# The references are kept and reused (delete out/aliasing/*-reference.exr, or set
# FRESH=1, after a change of the frame). On two llvmpipe cores a 2560x1440 reference takes
# about 20 s, a 640x360 still a few seconds a sample. Results: docs/PERFORMANCE.md
# "Aliasing (issue 13)". Prints one line per view and sample count:
#   view  samples  mean  p99   (relative luminance error, %)
set -euo pipefail
cd "$(dirname "$0")/.."
planet=${PLANET:-./build/planet}
views=${VIEWS:-"space orbit mountains"}
samples_list=${SAMPLES:-"1 default"}
small=${SMALL:-640x360}
width=${small%x*}
height=${small#*x}
big="$((width * 4))x$((height * 4))"
out=${OUT:-out/aliasing}
root_option=()
[ -z "${ROOT:-}" ] || root_option=(--root "$ROOT")
mkdir -p "$out"
[ -x "$planet" ] || { echo "aliasing.sh: no $planet (build first: cmake --build build)" >&2; exit 1; }

results=()
for view in $views; do
    reference="$out/$view-reference-$big.exr"
    if [ "${FRESH:-0}" = 1 ] || [ ! -f "$reference" ]; then
        echo "== $view: reference $big (one sample)" >&2
        "$planet" render "${root_option[@]}" --view "$view" --size "$big" --samples 1 --out "$reference" >/dev/null
    fi
    for s in $samples_list; do
        name="$out/$view-$small-s$s"
        if [ "$s" = default ]; then option=(); else option=(--samples "$s"); fi
        echo "== $view: $small, samples $s" >&2
        "$planet" render "${root_option[@]}" --view "$view" --size "$small" "${option[@]}" --out "$name.exr" --out "$name.png" >/dev/null
        report=$("$planet" compare "$name.exr" "$reference" --reference-scale 4 --diff "$name-error.png")
        mean=$(awk '$1 == "mean" && $2 != "luminance" { print $2 }' <<<"$report")
        p99=$(awk '$1 == "p99" { print $2 }' <<<"$report")
        results+=("$(printf '%-10s %-8s %8s %8s' "$view" "$s" "$mean" "$p99")")
    done
done
printf '%-10s %-8s %8s %8s   (relative luminance error against %s averaged 4x4, %%)\n' view samples mean p99 "$big"
printf '%s\n' "${results[@]}"
echo "images and error images (*-error.png) in $out/"
