#!/usr/bin/env bash
# Writes docs/report/: every GI technique's defaults (and the path tracer's samples curve)
# over the bundled Cornell box and sunlit room and the third-party interiors in
# ../shared/scenes (each skipped with a message when absent), at 160×90: the direct,
# indirect and whole-image error against a path-traced reference whose noise is measured,
# flicker and light responses, a Pareto plot per scene, Markdown, CSV and JSON.
#
#   bash tools/accuracy-report.sh [extra bounce-bench arguments]
#
# References are cached by scene content, settings and samples ($BOUNCE_REFERENCE_CACHE,
# else ~/.cache/bounce/references), so a second run renders only the techniques.
set -euo pipefail
cd "$(dirname "$0")/.."
scenes=(content/cornell_box.gltf content/tests/sunlit_room.gltf)
shared=../shared/scenes
for name in breakfast_room/breakfast_room.gltf sponza_dabrovic/sponza_dabrovic.gltf; do
  if [ -f "$shared/$name" ]; then
    scenes+=("$shared/$name")
  else
    echo "accuracy-report: skipping $shared/$name (not found; the shared scenes are not in this checkout)"
  fi
done
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build --target bounce-bench bounce_reference bounce_vxgi bounce_ddgi bounce_vpl bounce_ambient
rm -rf docs/report
build/bin/bounce-bench --scene "${scenes[@]}" --width 160 --height 90 --defaults-only --frames 3 \
  --reference-spp 256 --reference-budget 90 --out docs/report "$@"
