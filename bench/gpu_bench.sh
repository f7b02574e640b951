#!/usr/bin/env bash
# gpu_bench.sh [candela binary]: the GPU timings of docs/performance.md. For each scene, one JSON line from
# `candela bench` at 1920x1080, 1 sample per pixel per launch, depth 8: 20 untimed launches, then 100 timed
# with CUDA events (median), then the raw-trace mode on the same rays.
set -euo pipefail
candela=${1:-build/src/candela}
for scene in cornell-box cornell-spheres; do
  "$candela" bench "$scene" --backend optix --width 1920 --height 1080 --max-depth 8 --spp 100 --warmup 20 \
    --raw-trace
done
