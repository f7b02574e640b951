#!/usr/bin/env bash
# Installs the Debian 12 / Ubuntu 24.04 packages candela builds against, skipping those already present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libembree-dev libtbb-dev libglm-dev libstb-dev libtinyobjloader-dev libtinygltf-dev
  nlohmann-json3-dev libcli11-dev libopenexr-dev libgtest-dev libxxhash-dev zlib1g-dev
  # texture decoding; libjpeg-dev is libjpeg62-turbo-dev on Debian, libjpeg-turbo8-dev on Ubuntu
  libpng-dev libjpeg-dev libwebp-dev
  # CPU benchmarks of the filters (bench/)
  libbenchmark-dev
  # the viewer, and its tests on a virtual display with Mesa's software OpenGL
  libglfw3-dev libimgui-dev libgl-dev libgl1-mesa-dri libglx-mesa0 xvfb xdotool
  # candela serve (the viewer in a web browser), its JPEG frames and its H.264 video stream
  libboost-dev libturbojpeg0-dev libx264-dev
  # distributed rendering under mpirun (Open MPI), and its tests
  libopenmpi-dev openmpi-bin
  # scripts/check-format.sh (one version: others break lines differently)
  clang-format-14
  # tests that run candela and watch it (peak memory of glTF loads, signals while writing)
  python3
  # the Python module (python/) and its tests
  python3-dev python3-numpy pybind11-dev
  # cpack -G DEB: dpkg-shlibdeps finds the package's dependencies (and its test, api_debian_package)
  dpkg-dev file
)
# The browser tests of candela serve: Node drives Chromium through playwright-core (tests/serve/
# install-browser-test-deps.sh fetches it with npm into tests/serve/node_modules). Where the archive cannot
# install them (Ubuntu ships Chromium as a snap), everything else is still installed and those tests skip,
# saying why. npm comes with NodeSource's nodejs; Debian ships it as a package of its own.
browser_packages=(chromium nodejs)
command -v npm >/dev/null || browser_packages+=(npm)
# glTF's KHR_draco_mesh_compression and EXT_meshopt_compression. Installed where the archive has them (Debian 12:
# bookworm/main); candela builds without them and then refuses glTF files that require the extensions, naming them.
draco_packages=(libdraco-dev libmeshoptimizer-dev)

missing_among() {
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
mapfile -t missing < <(missing_among "${packages[@]}")
mapfile -t missing_browser < <(missing_among "${browser_packages[@]}")
mapfile -t missing_draco < <(missing_among "${draco_packages[@]}")
if [ ${#missing[@]} -eq 0 ] && [ ${#missing_browser[@]} -eq 0 ] && [ ${#missing_draco[@]} -eq 0 ]; then
  echo "dependencies: all present"
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -qq
install() { DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "$@"; }
if [ ${#missing[@]} -gt 0 ]; then
  echo "dependencies: installing ${missing[*]}"
  install "${missing[@]}"
fi
if [ ${#missing_draco[@]} -gt 0 ]; then
  echo "dependencies: installing ${missing_draco[*]} (for Draco- and meshopt-compressed glTF)"
  install "${missing_draco[@]}" ||
    echo "dependencies: could not install ${missing_draco[*]}; glTF files that require them will be refused"
fi
if [ ${#missing_browser[@]} -gt 0 ]; then
  echo "dependencies: installing ${missing_browser[*]} (for the browser tests)"
  install "${missing_browser[@]}" ||
    echo "dependencies: could not install ${missing_browser[*]}; the browser tests of candela serve will be skipped"
fi
