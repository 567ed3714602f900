#!/usr/bin/env bash
# The shadow benchmark table (a benchmark, not a test): each shadow method's direct light
# against the path tracer's `direct` AOV, and its GPU milliseconds, on the bundled sunlit
# room and the shared interiors (each skipped with a message when absent), at 320×180.
#
#   tools/bench-shadows.sh [REFERENCE_SPP] [ACCUMULATE]     (defaults 2048 and 64)
#
# Error: `bounce-render --gi none --accumulate N` (matched pixel sampling: the path
# tracer's pixels are box-filtered) against one reference of REFERENCE_SPP samples per
# pixel with r.Reference.MaxBounces 0 (its own noise is in the last column: a second
# reference of another seed against the first). Time: the median over 9 frames of the
# passes that make shadows (ShadowMaps, RayTracingScene and the Lighting pass that reads
# them), with r.Shadow.CacheStaticMaps 0, i.e. what a frame pays when the camera, a light
# or the geometry moves (a still scene draws its maps once).
set -euo pipefail
cd "$(dirname "$0")/.."
spp=${1:-2048}
accumulate=${2:-64}
scenes=(content/tests/sunlit_room.gltf)
for name in breakfast_room/breakfast_room.gltf sponza_dabrovic/sponza_dabrovic.gltf; do
  if [ -f "../shared/scenes/$name" ]; then
    scenes+=("../shared/scenes/$name")
  else
    echo "bench-shadows: skipping ../shared/scenes/$name (not found; the shared scenes are not in this checkout)" >&2
  fi
done
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build --target bounce-render bounce-compare bounce_reference >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
size=(--width 320 --height 180)
methods=(
  "ray-traced shadows|r.RayTracing.Shadows=1"
  "shadow maps 1024², whole-scene map only|r.Shadow.CSM.MaxCascades=0"
  "shadow maps 1024², 3 cascades (default)|r.Shadow.CSM.MaxCascades=3"
  "shadow maps 2048², 3 cascades|r.Shadow.MapSize=2048 r.Shadow.CSM.MaxCascades=3"
)
sets() { for s in $1; do printf -- '--set %s ' "$s"; done; }

echo "| scene | method | direct rel. RMSE | shadow ms (GPU) | frame ms | reference noise |"
echo "|---|---|--:|--:|--:|--:|"
for scene in "${scenes[@]}"; do
  for seed in 1 2; do
    build/bin/bounce-render --scene "$scene" --gi Reference "${size[@]}" --set r.Reference.MaxBounces=0 \
      --set r.Reference.SamplesPerPixel="$spp" --set r.Reference.Seed="$seed" --set r.Reference.ShowProgress=0 \
      --aov direct="$work/ref$seed.exr" --out "$work/ref$seed.png" >/dev/null 2>&1
  done
  noise=$(build/bin/bounce-compare "$work/ref2.exr" "$work/ref1.exr" | awk '/^relative RMSE/ {print $3}')
  for method in "${methods[@]}"; do
    label=${method%%|*}
    # shellcheck disable=SC2046
    build/bin/bounce-render --scene "$scene" --gi none "${size[@]}" $(sets "${method#*|}") \
      --accumulate "$accumulate" --aov direct="$work/direct.exr" --out "$work/direct.png" >/dev/null 2>&1
    error=$(build/bin/bounce-compare "$work/direct.exr" "$work/ref1.exr" | awk '/^relative RMSE/ {print $3}')
    # shellcheck disable=SC2046
    build/bin/bounce-render --scene "$scene" --gi none "${size[@]}" $(sets "${method#*|}") \
      --set r.Shadow.CacheStaticMaps=0 --frames 10 --stats "$work/stats.json" --out "$work/timed.png" >/dev/null 2>&1
    read -r shadowMs frameMs < <(python3 - "$work/stats.json" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
ms = sum(p["medianMs"] for p in d["passes"] if p["name"] in ("ShadowMaps", "RayTracingScene", "Lighting"))
print(f"{ms:.1f} {d['frameMs']:.1f}")
EOF
)
    echo "| $(basename "$scene" .gltf) | $label | $error | $shadowMs | $frameMs | $noise |"
  done
done
