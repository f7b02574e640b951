#!/usr/bin/env bash
# gpu_scale_bench.sh <candela> <candela-generate-scene> <environment .hdr> <work dir> [triangles ...]: large
# scenes on the GPU, for docs/performance.md. For each size (default 10M and 30M triangles) it writes the
# generated town as glTF, then runs `candela bench` on the OptiX backend twice, lit by the environment map, at
# 1920x1080, depth 8, one sample per pixel per launch, median of 50 CUDA-event launches after 5: the first run
# reads the glTF and writes the scene cache, the second reads the cache. Each run prints its JSON line (with
# load_seconds, backend_start_seconds, and first_frame_seconds: acceleration structures, uploads and the programs'
# compile, program_compile_seconds of it, up to the end of the first launch) and the most GPU memory in use meanwhile, as nvidia-smi saw it every 50 ms.
set -euo pipefail
if [ $# -lt 4 ]; then
  echo "usage: gpu_scale_bench.sh <candela> <candela-generate-scene> <environment .hdr> <work dir> [triangles ...]" >&2
  exit 2
fi
candela=$1 generate=$2 environment=$3 work=$4
shift 4
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(10000000 30000000)
mkdir -p "$work"
for triangles in "${sizes[@]}"; do
  scene=$work/town-$triangles
  start=$(date +%s%N)
  "$generate" --triangles "$triangles" --out "$scene" --format gltf >/dev/null
  echo "generated $triangles triangles in $((($(date +%s%N) - start) / 1000000)) ms: $(du -sh "$scene" | cut -f1)"
  for run in first-load cached; do
    nvidia-smi --query-gpu=memory.used --format=csv,noheader,nounits -lms 50 >"$work/memory.txt" &
    sampler=$!
    "$candela" bench "$scene/scene.gltf" --env "$environment" --cache-dir "$work/cache" --backend optix \
      --width 1920 --height 1080 --max-depth 8 --spp 50 --warmup 5 2>"$work/bench.log"
    kill "$sampler"
    wait "$sampler" 2>/dev/null || true
    echo "$run: most GPU memory in use $(sort -n "$work/memory.txt" | tail -1) MiB (idle $(head -1 "$work/memory.txt") MiB)"
  done
  rm -rf "$scene" "$work/cache"
done
