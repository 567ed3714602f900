#!/usr/bin/env bash
# Installs every Debian 12 package Bounce needs to build, test and run.
# Idempotent: when everything is present it prints nothing and touches nothing.
set -euo pipefail

packages=(
  # toolchain
  cmake ninja-build g++ pkg-config git
  # Vulkan: loader, headers, lavapipe (the default device), validation layers
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers
  glslang-dev glslang-tools spirv-tools libspirv-cross-c-shared-dev
  # libraries
  libglm-dev libtinygltf-dev libtinyexr-dev libstb-dev nlohmann-json3-dev
  libspdlog-dev libfmt-dev libcli11-dev libembree-dev libtbb-dev libmeshoptimizer-dev
  libimgui-dev libglfw3-dev
  # tests: GoogleTest, and an X server for the viewer tests
  libgtest-dev libgmock-dev xvfb xauth
  # the sanitizer build and the fuzzers (clang 14 with its ASan/UBSan/libFuzzer runtimes),
  # the hostile-input runner, and CI's check of this list (../shared/tools/check-install-deps)
  clang-14 libclang-rt-14-dev python3 strace
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]} (run as root, or install them)" >&2
  exit 1
fi
echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
