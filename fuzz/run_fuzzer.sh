#!/usr/bin/env bash
# Runs one libFuzzer target of a sanitizer build for a bounded time, starting from its corpus:
#     bash fuzz/run_fuzzer.sh BUILD NAME [SECONDS]     e.g. build-sanitize preset 600
# CTest's fuzz.NAME runs this (tests/sanitized_suite.cmake). The corpus in the repository,
# fuzz/corpus/NAME, is only read: new inputs go to BUILD/fuzz/NAME.corpus (kept from run to
# run), and an input that fails is saved as BUILD/fuzz/NAME-crash-<sha1> (or -leak-, -timeout-).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" 2>/dev/null && pwd || echo "$1")
name=$2
seconds=${3:-25}
bin=$build/fuzz/fuzz_$name
if [ ! -x "$bin" ]; then
  echo "error: $bin is not built: run bash scripts/build_sanitize.sh first" >&2
  exit 1
fi
dict=$here/toml.dict
[ "$name" = sky_probe_cases ] && dict=$here/csv.dict
mkdir -p "$build/fuzz/$name.corpus"
# -timeout: an input that takes 10 s is a hang; -rss_limit_mb: libFuzzer's default, said aloud.
exec "$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -dict="$dict" -print_final_stats=1 \
  -artifact_prefix="$build/fuzz/$name-" "$build/fuzz/$name.corpus" "$here/corpus/$name"
