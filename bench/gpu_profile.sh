#!/usr/bin/env bash
# gpu_profile.sh <candela> <output dir> <scene> [more bench arguments]: Nsight Compute's source counters and warp
# states for one 1-spp launch of the path tracer at 1920x1080, depth 8 (the fourth launch, after the first ones'
# start-up), exported as the source page that bench/ncu_source_summary.py reads:
#   bench/gpu_profile.sh build/src/candela profile cornell-box
#   bench/ncu_source_summary.py profile/source.csv
# The device program must be compiled with -lineinfo (src/backends/optix/CMakeLists.txt does) for the source lines.
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: gpu_profile.sh <candela> <output dir> <scene> [more bench arguments]" >&2
  exit 2
fi
candela=$1 out=$2
shift 2
mkdir -p "$out"
ncu --clock-control none --kernel-name regex:optixLaunch --launch-skip 3 --launch-count 1 --section SourceCounters \
  --section WarpStateStats --import-source yes --force-overwrite -o "$out/profile" \
  "$candela" bench "$@" --backend optix --width 1920 --height 1080 --max-depth 8 --spp 5 --warmup 0 >"$out/bench.log"
ncu --import "$out/profile.ncu-rep" --page source --csv --print-source cuda,sass >"$out/source.csv"
echo "$out/source.csv"
