#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine (as root), builds Bounce and runs its main job on
# the bundled Cornell box. Extra arguments go to bounce-render (e.g. --gi none).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$(nproc)" --target bounce-render bounce_ambient
./build/bin/bounce-render --scene content/cornell_box.gltf --gi Ambient --width 512 --height 512 "$@"
