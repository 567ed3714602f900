#!/usr/bin/env bash
# Runs a libFuzzer target for a while, building the sanitizer/fuzzer folder first when needed.
#
#   bash tools/fuzz.sh TARGET SECONDS [libFuzzer options...]
#   bash tools/fuzz.sh all SECONDS          # each target in turn, SECONDS each
#   bash tools/fuzz.sh list                 # the target names
#
# Targets (tests/fuzz/fuzz_*.cpp): ini, cvar, console, script, plugin_descriptor, gltf,
# ddgi_volume.
# Seeds are read from tests/fuzz/corpus/<target>/ (checked in, never written); what the
# fuzzer learns goes to $BUILD/fuzz-corpus/<target>/, and a crashing input to
# $BUILD/fuzz-artifacts/. Reproduce one with: $BUILD/fuzz/fuzz_<target> FILE.
# BOUNCE_ASAN_BUILD: the build folder (default build-asan, shared with tools/test.sh's
# sanitizer stage). BOUNCE_FUZZ_KEEP_GOING=1: for long runs, go on after a finding
# (libFuzzer's fork mode) and collect every crashing input. Exit status: 0 when no
# target found anything.
set -euo pipefail
cd "$(dirname "$0")/.."
targets=(ini cvar console script plugin_descriptor gltf ddgi_volume)
build=${BOUNCE_ASAN_BUILD:-build-asan}

if [ "${1:-}" = list ]; then printf '%s\n' "${targets[@]}"; exit 0; fi
if [ $# -lt 2 ]; then sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; fi
which=$1 seconds=$2
shift 2
if [ "$which" = all ]; then run=("${targets[@]}"); else run=("$which"); fi
for t in "${run[@]}"; do
  printf '%s\n' "${targets[@]}" | grep -qx "$t" || { echo "fuzz.sh: no target '$t' (targets: ${targets[*]})" >&2; exit 2; }
done

if [ ! -f "$build/build.ninja" ] || ! grep -q 'BOUNCE_FUZZ:BOOL=ON' "$build/CMakeCache.txt"; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DBOUNCE_SANITIZE=ON -DBOUNCE_FUZZ=ON >/dev/null
fi
ninja -C "$build" -j"$(nproc)" fuzzers >/dev/null

# The largest input each target is tried with: glTF files need room for buffers.
max_len() { case $1 in gltf) echo 65536 ;; script | console) echo 8192 ;; *) echo 16384 ;; esac; }

failed=()
for t in "${run[@]}"; do
  work="$build/fuzz-corpus/$t"
  mkdir -p "$work" "$build/fuzz-artifacts"
  echo "fuzz.sh: $t for ${seconds}s"
  # -close_fd_mask=3: the engine's own messages about bad input are not news here;
  # libFuzzer and the sanitizers still report on a copy of stderr.
  # -timeout=25: one input running longer is a hang (the first also starts the engine).
  keep_going=()
  [ "${BOUNCE_FUZZ_KEEP_GOING:-0}" = 0 ] || keep_going=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  if ! LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}" \
    UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
    "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=25 -rss_limit_mb=4096 \
    -max_len="$(max_len "$t")" -close_fd_mask=3 -print_final_stats=1 "${keep_going[@]}" \
    -artifact_prefix="$build/fuzz-artifacts/$t-" "$@" "$work" "tests/fuzz/corpus/$t" 2>"$build/fuzz-$t.log"; then
    failed+=("$t")
    echo "fuzz.sh: $t FOUND A PROBLEM (log: $build/fuzz-$t.log; input in $build/fuzz-artifacts/):" >&2
    grep -E 'ERROR|runtime error|SUMMARY|Test unit written|fuzz_|crashes:' "$build/fuzz-$t.log" | head -20 >&2
  else
    grep -E '^stat::number_of_executed_units|^Done' "$build/fuzz-$t.log" | tr '\n' ' '
    echo
  fi
done
[ ${#failed[@]} -eq 0 ] || { echo "fuzz.sh: problems found by: ${failed[*]}" >&2; exit 1; }
