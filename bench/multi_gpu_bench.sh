#!/usr/bin/env bash
# multi_gpu_bench.sh [candela] [candela-generate-scene] [environment .hdr] [work dir]: the multi-GPU numbers of
# docs/performance.md. `candela bench` on the OptiX backend at 1920x1080, depth 8, one sample per pixel per
# launch (each launch split into bands of rows between the devices), median of 100 CUDA-event launches after 20,
# first on GPU 0 alone and then on DEVICES (default all): the Cornell box, and the 10M-triangle town of
# candela-generate-scene as glTF under the environment map. Each run prints its JSON line (with the devices'
# median times per launch and the combine cost) and the most memory in use on each GPU meanwhile, as nvidia-smi
# saw it every 50 ms. The speed-up is the ratio of `seconds` (the timed launches, wall clock). Where DISPLAY is
# set (Xvfb as for tests/gpu/viewer_interop.sh), the viewer's frame time too: 300 frames of the Cornell box at
# 1920x1080, each split into bands and combined on GPU 0 for display, as the panel measured it.
set -euo pipefail
candela=${1:-build/src/candela}
generate=${2:-build/src/candela-generate-scene}
environment=${3:-../shared/scenes/envmaps/royal_esplanade_1k.hdr}
work=${4:-/tmp/candela-multi-gpu-bench}
devices=${DEVICES:-all}
options=(--backend optix --width 1920 --height 1080 --max-depth 8 --spp 100 --warmup 20)
mkdir -p "$work"

# run <label> <bench arguments...>: one bench line and the peak memory per GPU.
run() {
  local label=$1
  shift
  nvidia-smi --query-gpu=index,memory.used --format=csv,noheader,nounits -lms 50 >"$work/memory.txt" &
  local sampler=$!
  "$candela" bench "$@" 2>"$work/bench.log"
  kill "$sampler"
  wait "$sampler" 2>/dev/null || true
  echo "$label: most memory in use per GPU (MiB): $(sort -t, -k1,1n -k2,2n "$work/memory.txt" |
    awk -F', ' '{peak[$1] = $2} END {for (g in peak) printf "GPU %s %s  ", g, peak[g]}')"
}

for scene in cornell-box; do
  run "$scene, GPU 0" "$scene" "${options[@]}" --devices 0
  run "$scene, $devices" "$scene" "${options[@]}" --devices "$devices"
done

town=$work/town-10m
[ -e "$town/scene.gltf" ] || "$generate" --triangles 10000000 --out "$town" --format gltf >/dev/null
for pass in cache "GPU 0" "$devices"; do  # the first run writes the scene cache, so that both timed runs read it
  selection=$([ "$pass" = cache ] || [ "$pass" = "GPU 0" ] && echo 0 || echo "$devices")
  run "town 10M, $pass" "$town/scene.gltf" --env "$environment" --cache-dir "$work/cache" "${options[@]}" \
    --devices "$selection"
done

if [ -n "${DISPLAY:-}" ]; then
  for selection in 0 "$devices"; do
    echo "viewer, devices $selection: $("$candela" view cornell-box --backend optix --width 1920 --height 1080 \
      --frames 300 --devices "$selection" 2>&1 | grep '^viewer:')"
  done
else
  echo "viewer: skipped, DISPLAY is not set"
fi
