#!/usr/bin/env bash
# cold_start.sh [candela binary] [runs]: the GPU backend's time to its first frame on a GPU machine, with OptiX's
# disk cache empty (cold: the first start on a machine, which compiles the GPU programs) and holding the programs
# (warm), `runs` times each (default 3). Each run is `candela bench` of the Cornell box at 1920x1080, one warm-up
# launch and one timed launch of one sample per pixel, and prints the time to its first frame (bench's
# backend_start_seconds, the CUDA and OptiX contexts, plus first_frame_seconds, the scene upload, the programs'
# compile, the schedule's probe and the first launch), of which program_compile_seconds waited for the first
# frame's programs (the warm-up launch is the first frame, and may be the megakernel's while the wavefront's
# programs compile; the timed one waits for them), the process's wall time, and the compile's last lines. A cold run also times `candela render --denoise atrous` (wall time: its first frame
# compiles the AOV path tracer's programs and the ray programs, nothing else) in a cache of its own. Only the
# programs a run uses are compiled, all at once when its first frame is known, so a cold bench compiles neither
# ReSTIR's nor the AOV path tracer's.
#
# Cold is a fresh empty folder in CANDELA_OPTIX_CACHE, where the backend points OptiX's disk cache
# (optixDeviceContextSetCacheLocation): OptiX then neither reads nor writes its default one (/var/tmp/OptixCache_$USER),
# so nothing of the driver's needs clearing or turning off. OptiX's own variables would get in the way:
# OPTIX_CACHE_PATH takes precedence over the folder set, and OPTIX_CACHE_MAXSIZE=0 turns the cache off (every start
# cold), so both are unset here. CUDA's JIT cache (CUDA_CACHE_PATH) serves only PTX that the driver compiles for a
# GPU the build has no SASS for: candela's CUDA kernels carry SASS for CMAKE_CUDA_ARCHITECTURES (90: H100/H200) and
# OptiX compiles its modules itself; a fresh folder per cold run keeps it out of the measurement all the same.
set -euo pipefail
candela=$(realpath "${1:-build/src/candela}")
runs=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unset OPTIX_CACHE_PATH OPTIX_CACHE_MAXSIZE
bench=(bench cornell-box --backend optix --width 1920 --height 1080 --spp 1 --warmup 1)

# json_number <key> <json line>
json_number() { grep -o "\"$1\":[-0-9.e+]*" <<<"$2" | cut -d: -f2; }

# timed <cache folder> <log> <candela arguments...>: runs candela with that cache, its output in <log>.out and
# <log>.err; prints its wall seconds. A failure ends the script with candela's messages.
timed() {
  local cache=$1 log=$2
  shift 2
  local start end
  start=$(date +%s.%N)
  if ! CANDELA_OPTIX_CACHE=$cache CUDA_CACHE_PATH=$cache/cuda "$candela" "$@" >"$log.out" 2>"$log.err"; then
    echo "candela $* failed:" >&2
    cat "$log.err" >&2
    exit 1
  fi
  end=$(date +%s.%N)
  awk -v s="$start" -v e="$end" 'BEGIN {printf "%.2f", e - s}'
}

# compiles <stderr file>: the lines that end the compiles candela reported (at start-up, and at exit where the
# background modules were still compiling).
compiles() {
  local lines
  lines=$(grep -E '^optix: compil(ed|ing the GPU programs failed)' "$1" | tr '\n' ' ' || true)
  echo "${lines:-no compile reported (over within half a second)}"
}

# bench_run <label> <cache folder>: one bench run and its line.
bench_run() {
  local label=$1 cache=$2 log=$work/run
  local wall json
  wall=$(timed "$cache" "$log" "${bench[@]}")
  json=$(tail -1 "$log.out")
  local start first programs total
  start=$(json_number backend_start_seconds "$json")
  first=$(json_number first_frame_seconds "$json")
  programs=$(json_number program_compile_seconds "$json")
  total=$(awk -v a="$start" -v b="$first" 'BEGIN {printf "%.2f", a + b}')
  echo "$label: first frame after $total s (backend_start_seconds $start + first_frame_seconds $first, of which" \
    "program_compile_seconds $programs), wall $wall s; $(compiles "$log.err")"
  if [ "$label" = "cold 1" ]; then grep -m1 '^optix: .* driver ' "$log.err" || true; fi
}

echo "candela: $candela"
for run in $(seq "$runs"); do
  mkdir "$work/cold$run" "$work/aovs$run"
  bench_run "cold $run" "$work/cold$run"
  wall=$(timed "$work/aovs$run" "$work/aovs" render cornell-box --backend optix --width 1920 --height 1080 --spp 1 \
    --denoise atrous -o "$work/aovs$run/image.png")
  echo "cold $run, render --denoise atrous: wall $wall s; $(compiles "$work/aovs.err")"
done
for run in $(seq "$runs"); do
  bench_run "warm $run" "$work/cold1"
done
