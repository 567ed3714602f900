#!/bin/bash
# Packs build/ into a bundle that runs Bounce's renders, tests and benchmark on another
# x86-64 Linux machine with a real GPU and its Vulkan driver but none of Debian 12's
# packages (a CUDA image, say): the built programs and plugins, the Debian libraries they
# link (the Vulkan loader and glvnd too: a vendor ICD such as libGLX_nvidia needs
# libGLdispatch), the validation layer, and glibc as a fallback for an older system.
#
#   bash tools/gpu-bundle.sh [DIR]     # default DIR: .gpu (git-ignored)
#   then, on the GPU machine, in a checkout of the same commit:
#   bash DIR/gpu-check.sh OUT          # OUT: where the logs and images go
#
# The tests and CTest files name the build's absolute paths, so gpu-check.sh links the
# checkout to the path it was built at when that path does not exist there.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
DIR=${1:-.gpu}
[ -x build/bin/bounce-render ] || { echo "gpu-bundle: build first (build/bin/bounce-render is missing)" >&2; exit 2; }
STAGE=$(mktemp -d)
trap 'rm -rf "$STAGE"' EXIT
mkdir -p "$STAGE/build" "$STAGE/.gpu/lib" "$STAGE/.gpu/fallback" "$STAGE/.gpu/glibc" "$STAGE/.gpu/layers"

# Programs and plugins without debug info (RelWithDebInfo triples their size); symbolic
# links (a plugin's shaders folder points into the source tree) stay links.
(cd build && find bin lib plugins test-plugins -type f -o -type l) | while read -r f; do
  mkdir -p "$STAGE/build/$(dirname "$f")"
  case "$f" in
    */CMakeFiles/*) ;;
    *.so | bin/*) [ -L "build/$f" ] && cp -P "build/$f" "$STAGE/build/$f" || strip --strip-debug -o "$STAGE/build/$f" "build/$f" ;;
    *.bplugin | */shaders) cp -P "build/$f" "$STAGE/build/$f" ;;
  esac
done
(cd build && find . -name CTestTestfile.cmake -o -name "*_tests.cmake" -o -name "*_include.cmake" | grep -v CMakeFiles) |
  while read -r f; do mkdir -p "$STAGE/build/$(dirname "$f")" && cp "build/$f" "$STAGE/build/$f"; done

# Every library the programs link, except glibc's and the C++ runtime's (the system's are
# newer; ours are the fallback), plus glvnd.
LIBS=$(for f in build/bin/* build/lib/*.so build/plugins/*/*.so; do ldd "$f"; done | awk '/=>/ {print $3}' |
  grep -v "^$ROOT" | sort -u)
for l in $LIBS; do
  case "$(basename "$l")" in
    libc.so* | libm.so* | libdl.so* | libpthread.so* | librt.so*) cp -L "$l" "$STAGE/.gpu/glibc/" ;;
    libstdc++.so* | libgcc_s.so*) cp -L "$l" "$STAGE/.gpu/fallback/" ;;
    *) cp -L "$l" "$STAGE/.gpu/lib/" ;;
  esac
done
for l in libGLdispatch.so.0 libGLX.so.0 libEGL.so.1 libOpenGL.so.0 libGL.so.1; do
  [ -e "/lib/x86_64-linux-gnu/$l" ] && cp -L "/lib/x86_64-linux-gnu/$l" "$STAGE/.gpu/lib/"
done
cp -L /lib64/ld-linux-x86-64.so.2 "$STAGE/.gpu/glibc/"
cp -L /usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so "$STAGE/.gpu/layers/"
sed 's#"library_path": *"[^"]*"#"library_path": "./libVkLayer_khronos_validation.so"#' \
  /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json >"$STAGE/.gpu/layers/VkLayer_khronos_validation.json"
echo "$ROOT" >"$STAGE/.gpu/built-at"

mkdir -p "$DIR"
tar -C "$STAGE" -cf - build .gpu | xz -T2 -6 >"$DIR/bundle.tar.xz"
cp tools/gpu-check.sh "$DIR/gpu-check.sh"
echo "gpu-bundle: $DIR/bundle.tar.xz ($(du -h "$DIR/bundle.tar.xz" | cut -f1)) and $DIR/gpu-check.sh"
