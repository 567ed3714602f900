#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine (as root), builds Bounce and runs its main job:
# renders the bundled Cornell box with VXGI to out/cornell_box.png and prints the GPU
# time of every render-graph pass. Extra arguments go to bounce-render (e.g. --gi none).
# Two frames: the first voxelizes the scene, the second (the one written and timed)
# finds the clip-map up to date and only traces cones.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$(nproc)" --target bounce-render bounce_vxgi bounce_ambient bounce_reference
mkdir -p out
./build/bin/bounce-render --scene content/cornell_box.gltf --gi VXGI --width 512 --height 512 --frames 2 \
  --out out/cornell_box.png --aov radiance=out/cornell_box_radiance.exr --stats out/cornell_box_stats.json "$@"
echo "wrote out/cornell_box.png, out/cornell_box_radiance.exr and out/cornell_box_stats.json"
