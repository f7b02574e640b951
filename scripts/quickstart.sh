#!/usr/bin/env bash
# A first picture, soon: installs what is missing, builds only the `candela` command into ./build (not the test
# suite, the Python module or the benchmarks: scripts/test.sh builds everything), renders the built-in Cornell box
# at 512x512 with 32 samples per pixel through the a-trous denoiser, and says what to try next. Extra arguments go
# to the CMake configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-dependencies.sh

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
echo ">>> configuring ./build"
cmake -S . -B build "${generator[@]}" "$@"
echo ">>> building the candela command on $(nproc) cores"
NINJA_STATUS="[%p, %f of %t, %es] " cmake --build build --parallel "$(nproc)" --target candela

mkdir -p out
echo ">>> rendering the Cornell box: 512x512, 32 samples per pixel, a-trous denoiser"
image=$(./build/src/candela render cornell-box --width 512 --height 512 --spp 32 --denoise atrous \
  -o out/cornell-box.png)
cat <<MESSAGE

Your first image: $image

Next:
  build/src/candela view                       # the interactive viewer: move the camera, change materials
  build/src/candela serve --port 8080          # the same viewer in a web browser
  build/src/candela render model.glb --env sky.hdr --spp 256 --denoise atrous -o model.png
                                               # a glTF model of your own, lit by an HDR environment map
  build/src/candela render --help              # every option
  ./scripts/test.sh                            # build everything (the Python module too) and run the tests
MESSAGE
