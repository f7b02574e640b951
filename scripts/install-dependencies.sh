#!/usr/bin/env bash
# Installs the Debian 12 / Ubuntu 24.04 packages candela builds against, skipping those already present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libembree-dev libtbb-dev libglm-dev libstb-dev libtinyobjloader-dev libtinygltf-dev
  nlohmann-json3-dev libcli11-dev libopenexr-dev libgtest-dev libxxhash-dev zlib1g-dev
  # texture decoding; libjpeg-dev is libjpeg62-turbo-dev on Debian, libjpeg-turbo8-dev on Ubuntu
  libpng-dev libjpeg-dev
  # CPU benchmarks of the filters (bench/)
  libbenchmark-dev
  # the viewer, and its tests on a virtual display with Mesa's software OpenGL
  libglfw3-dev libimgui-dev libgl-dev libgl1-mesa-dri libglx-mesa0 xvfb xdotool
  # candela serve (the viewer in a web browser), and its browser tests: Node drives Chromium through playwright-core
  # (tests/serve/install-browser-test-deps.sh fetches it with npm into tests/serve/node_modules)
  libboost-dev libturbojpeg0-dev chromium nodejs
  # scripts/check-format.sh (one version: others break lines differently)
  clang-format-14
)
# npm comes with NodeSource's nodejs; Debian ships it as a package of its own.
command -v npm >/dev/null || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "dependencies: all present"
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "dependencies: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
