#!/usr/bin/env bash
# Installs what is missing, builds, and renders the built-in Cornell box.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-dependencies.sh
./scripts/build.sh
mkdir -p out
image=$(./build/src/candela render cornell-box --spp 256 -o out/cornell-box.png)
echo "rendered the Cornell box to $image"
