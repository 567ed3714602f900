#!/usr/bin/env bash
# The VXGI benchmark tables (a benchmark, not a test): per-pass GPU ms on the Cornell box
# for map sizes 64 and 128, 4/8/16 diffuse cones, ambient-occlusion mode, and a frame that
# re-voxelizes everything (one bounce and the default bounces), all in one run so the ratios
# are comparable.
#
#   tools/bench-vxgi.sh [SIZES] [FRAMES] [extra bounce-render-bench arguments...]
#   tools/bench-vxgi.sh 256,512 3
#   tools/bench-vxgi.sh 256 4 --rounds 3   # on a shared machine: every column in each round
set -euo pipefail
cd "$(dirname "$0")/.."
sizes=${1:-256}
frames=${2:-4}
shift $(($# < 2 ? $# : 2))
variants=()
for map in 64 128; do
  for cones in 4 8 16; do
    variants+=(--variant "${map}³ ${cones} cones: r.VXGI.MapSize=${map} r.VXGI.DiffuseCones=${cones}")
  done
  variants+=(--variant "${map}³ AO: r.VXGI.MapSize=${map} r.VXGI.AmbientOcclusionMode=1")
  # Re-voxelized whole every frame: with the seed's one bounce, and with the default bounces,
  # where every voxelized surface also gathers its indirect light (r.VXGI.BounceCones cones).
  variants+=(--variant "${map}³ 8 cones, re-voxelized, 1 bounce: r.VXGI.MapSize=${map} r.VXGI.DiffuseCones=8 r.VXGI.Bounces=1 r.VXGI.ForceFullVoxelization=1")
  variants+=(--variant "${map}³ 8 cones, re-voxelized: r.VXGI.MapSize=${map} r.VXGI.DiffuseCones=8 r.VXGI.ForceFullVoxelization=1")
done
exec build/bin/bounce-render-bench --gi VXGI --sizes "$sizes" --frames "$frames" "${variants[@]}" "$@"
