#!/usr/bin/env bash
# gpu_bench.sh [candela binary] [shared scenes folder]: the GPU timings of docs/performance.md. For each scene,
# one JSON line from `candela bench` at 1920x1080, 1 sample per pixel per launch, depth 8: 20 untimed
# launches, then 100 timed with CUDA events (median), then the raw-trace mode on the same rays. The
# DamagedHelmet under an HDR map is timed when the shared scenes folder holds it; the cut-out layers (eight
# alpha-tested screens over a floor, scenes/ beside this script) when they are there.
set -euo pipefail
candela=${1:-build/src/candela}
shared=${2:-../shared/scenes}
options=(--backend optix --width 1920 --height 1080 --max-depth 8 --spp 100 --warmup 20 --raw-trace)
for scene in cornell-box cornell-spheres; do
  "$candela" bench "$scene" "${options[@]}"
done
helmet=$shared/damaged_helmet/glTF-Binary/DamagedHelmet.glb
if [ -e "$helmet" ]; then
  "$candela" bench "$helmet" --env "$shared/envmaps/royal_esplanade_1k.hdr" "${options[@]}"
fi
cutouts=$(dirname "$0")/scenes/cutout_layers/cutout-layers.json
if [ -e "$cutouts" ]; then
  "$candela" bench "$cutouts" "${options[@]}"
fi
