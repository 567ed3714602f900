#!/bin/bash
# Runs, on a machine with a real GPU, what tools/gpu-bundle.sh packed: the Cornell box with
# VXGI and DDGI (PNG, indirect irradiance EXR, per-pass stats), every CTest test but the
# sanitizer, fuzz, soak and hostile-input ones (validation layers on), and the VXGI
# benchmark at 512² and 1024². Compare the EXRs with lavapipe's (bounce-render --aov
# indirect-irradiance=...) on the build machine.
#
#   bash BUNDLE_DIR/gpu-check.sh OUT     # run from the checkout's root
#
# The Vulkan driver is the one the system's loader files name, or $VK_ICD_FILENAMES.
set -u
ROOT=$PWD
OUT=$(mkdir -p "${1:-gpu-check-out}" && cd "${1:-gpu-check-out}" && pwd)
BUNDLE=$(cd "$(dirname "$0")" && pwd)
tar -xJf "$BUNDLE/bundle.tar.xz"
BUILT_AT=$(cat .gpu/built-at)
if [ "$BUILT_AT" != "$ROOT" ] && [ ! -e "$BUILT_AT" ]; then
  mkdir -p "$(dirname "$BUILT_AT")" && ln -s "$ROOT" "$BUILT_AT"
fi
ENV=$OUT/env.txt
{
  nvidia-smi -L 2>/dev/null
  ldd --version | head -1
  head -2 /etc/os-release
  echo "cores: $(nproc)"
} >"$ENV" 2>&1
if [ -z "${VK_ICD_FILENAMES:-}" ]; then
  ICD=$(ls /usr/local/nvidia/share/vulkan/icd.d/*.json /usr/share/vulkan/icd.d/*.json /etc/vulkan/icd.d/*.json 2>/dev/null |
    grep -v lvp | head -1)
  export VK_ICD_FILENAMES=$ICD VK_DRIVER_FILES=$ICD
fi
echo "driver: $VK_ICD_FILENAMES" >>"$ENV"
export VK_LAYER_PATH=$ROOT/.gpu/layers HOME=${TMPDIR:-/tmp}/bounce-gpu-check-home
export LD_LIBRARY_PATH=$ROOT/.gpu/lib:/usr/lib/x86_64-linux-gnu:/lib/x86_64-linux-gnu:$ROOT/.gpu/fallback
mkdir -p "$HOME"
B=build/bin
RUN=""
if ! $B/bounce-render --help >/dev/null 2>>"$ENV"; then
  echo "the system's glibc is too old: the bundle's is used" >>"$ENV"
  RUN="$ROOT/.gpu/glibc/ld-linux-x86-64.so.2 --library-path $ROOT/.gpu/glibc:$LD_LIBRARY_PATH"
fi
if ! VK_LOADER_DEBUG=error,driver timeout 60 $RUN $B/bounce-render --scene content/cornell_box.gltf --gi none \
  --width 64 --height 64 --out "$OUT/probe.png" >"$OUT/probe.txt" 2>&1; then
  echo "gpu-check: bounce-render found no usable device; see $OUT/probe.txt" >&2
  tail -20 "$OUT/probe.txt" >&2
  exit 3
fi
for gi in VXGI DDGI; do
  echo "== $gi" >>"$OUT/render.txt"
  BOUNCE_VALIDATION=1 timeout 120 $RUN $B/bounce-render --scene content/cornell_box.gltf --gi $gi \
    --out "$OUT/$gi.png" --aov "indirect-irradiance=$OUT/$gi.exr" >>"$OUT/render.txt" 2>&1
  echo "exit status $?" >>"$OUT/render.txt"
done
(cd build && time timeout 300 ctest -j"$(nproc)" --timeout 200 -E "hostile|soak|fuzz|ray_bench|Sdk" \
  --output-on-failure) >"$OUT/ctest.log" 2>&1
echo "ctest exit status $?" >>"$OUT/ctest.log"
timeout 120 $RUN $B/bounce-render-bench --gi VXGI --sizes 512 1024 --frames 10 \
  --variant "s64: r.VXGI.MapSize=64" --variant "s128: r.VXGI.MapSize=128" \
  --variant "r128: r.VXGI.MapSize=128 r.VXGI.ForceFullVoxelization=1" >"$OUT/bench.txt" 2>&1
echo "bench exit status $?" >>"$OUT/bench.txt"
grep -E "tests passed|tests failed" "$OUT/ctest.log"
