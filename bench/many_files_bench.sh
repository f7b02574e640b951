#!/usr/bin/env bash
# many_files_bench.sh <candela> <candela-generate-scene> <work dir> [parts] [runs]: the load time and peak RSS of
# a scene file of many OBJ files that all name one material library, against the same geometry in one OBJ, for
# docs/performance.md. It generates the 1M-triangle town with 86 materials and 11 textures as one OBJ, splits it
# by objects into <parts> OBJ files (default 300) placed by one scene.json (split_obj_scene.py), and runs
# `candela load --no-cache` on each input <runs> times (default 3), interleaved, under /usr/bin/time -v.
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: many_files_bench.sh <candela> <candela-generate-scene> <work dir> [parts] [runs]" >&2
  exit 2
fi
candela=$1 generate=$2 work=$3 parts=${4:-300} runs=${5:-3}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
"$generate" --triangles 1000000 --materials 86 --textures 11 --format obj --out "$work/town" >/dev/null
python3 "$here/split_obj_scene.py" "$work/town/scene.obj" "$parts" "$work/parts"
for run in $(seq "$runs"); do
  for input in "$work/town/scene.obj" "$work/parts/scene.json"; do
    /usr/bin/time -v "$candela" load "$input" --no-cache >"$work/load.json" 2>"$work/time.txt"
    wall=$(grep "Elapsed (wall clock)" "$work/time.txt" | awk '{print $NF}')
    peak=$(grep "Maximum resident set size" "$work/time.txt" | awk '{print $NF}')
    echo "run $run $(basename "$(dirname "$input")")/$(basename "$input"): wall $wall, peak $peak KiB, $(cat "$work/load.json")"
  done
done
