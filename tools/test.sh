#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine (as root), builds Bounce and runs every test.
# Used by the README and by CI (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"
