#!/usr/bin/env bash
# Installs what planet needs from Debian 12's packages (only what is missing,
# so a second run is quick) and builds it in Release under build/.
# Used by scripts/run.sh and scripts/test.sh; safe to run on its own.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config         # toolchain
  libglfw3-dev libepoxy-dev libegl-dev libgl-dev       # window, GL loader, headless EGL
  libegl-mesa0 libgl1-mesa-dri                         # Mesa llvmpipe: GL 4.5 without a GPU
  libglm-dev libopenexr-dev libimgui-dev libstb-dev    # math, HDR images, UI, PNG
  libcli11-dev libtomlplusplus-dev                     # command line, presets
  libgtest-dev glslang-tools xvfb xauth                # tests: GoogleTest, offline GLSL check, window test
  clang libclang-rt-14-dev llvm                        # tests: ASan/UBSan build, libFuzzer, readable reports
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"
