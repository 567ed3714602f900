#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine (as root), builds Bounce and runs every test.
# Used by the README and by CI (.ci/run). Stages, each timed:
#   1. the normal build (build/) and all its tests, the hostile-input corpus included;
#   2. the sanitizer build (build-asan/, clang, ASan+UBSan): the CPU-side suites and the
#      hostile-input corpus, and the fuzz targets built;
#   3. each fuzz target for $BOUNCE_FUZZ_SECONDS (default 60) seconds.
# For a quicker local run: BOUNCE_SANITIZER_STAGE=0 skips stages 2 and 3;
# BOUNCE_FUZZ_SECONDS=0 skips stage 3.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc)
fuzz_seconds=${BOUNCE_FUZZ_SECONDS:-60}
timings=()
stage() {  # stage NAME COMMAND...: runs it and records how long it took
  local name=$1 start=$SECONDS
  shift
  echo "test.sh: == $name"
  "$@"
  timings+=("$(printf '%-28s %5d s' "$name" $((SECONDS - start)))")
}
report() { [ ${#timings[@]} -eq 0 ] || printf 'test.sh: %s\n' "${timings[@]}"; }
trap report EXIT

stage "build" bash -c "cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null &&
  cmake --build build -j$jobs"
stage "tests" ctest --test-dir build --output-on-failure -j"$jobs"

if [ "${BOUNCE_SANITIZER_STAGE:-1}" != 0 ]; then
  stage "sanitizer build" bash -c "CC=clang-14 CXX=clang++-14 cmake -S . -B build-asan -G Ninja \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBOUNCE_SANITIZE=ON -DBOUNCE_FUZZ=ON >/dev/null &&
    cmake --build build-asan -j$jobs && cmake --build build-asan -j$jobs --target fuzzers"
  # The Vulkan validation layer leaks one 112-byte block when it is unloaded at exit;
  # tests/sanitizers/lsan.supp suppresses exactly that.
  export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  stage "sanitizer tests" ctest --test-dir build-asan --output-on-failure -j"$jobs"
  if [ "$fuzz_seconds" != 0 ]; then
    stage "fuzzing (${fuzz_seconds}s each)" bash tools/fuzz.sh all "$fuzz_seconds"
  fi
fi
