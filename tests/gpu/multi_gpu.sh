#!/usr/bin/env bash
# multi_gpu.sh <candela> <compare_exr> <output dir>: `--devices` through the command line on a machine with an
# NVIDIA GPU. DEVICES (default 0,0: two contexts on GPU 0; 0,1 on a machine of two GPUs) renders against the
# first of them alone. Checks, each printed as PASS or FAIL (SKIP where the machine cannot run it):
#   - `render` on DEVICES writes the film (checkpoint) and image of one device, up to the order of the float
#     additions (1e-5 relative, as the MPI test), with the AOVs: one sample per launch, so the rows are split in
#     bands that follow the devices' times, and the films are combined once, at the end;
#   - `bench` on DEVICES reports each device's time and the combine cost;
#   - `view` on DEVICES (where DISPLAY is set) shows the film of one device after the same frames;
#   - bad device lists end with one line and the usage (2) or failure (1) status.
# Exit status: the number of failed checks. Leaves the images and logs in <output dir>.
set -uo pipefail
if [ $# -ne 3 ]; then
  echo "usage: multi_gpu.sh <candela> <compare_exr> <output dir>" >&2
  exit 2
fi
candela=$(realpath "$1") compare=$(realpath "$2") out=$3
devices=${DEVICES:-0,0}
first=${devices%%,*}
mkdir -p "$out"
source "$(dirname "$0")/checks_common.sh"

args=(cornell-box --backend optix --width 320 --height 240 --spp 48 --seed 3 --aov albedo,normal,depth)
"$candela" render "${args[@]}" --devices "$first" --checkpoint "$out/one.exr" -o "$out/one-image.exr" \
  >"$out/one.log" 2>&1
status=$?
"$candela" render "${args[@]}" --devices "$devices" --checkpoint "$out/group.exr" -o "$out/group-image.exr" \
  >"$out/group.log" 2>&1
check render_runs $((status + $?)) "$(grep -E '^(backend|rendered)' "$out/group.log" | tr '\n' ' ')"
"$compare" "$out/one.exr" "$out/group.exr" 1e-5 >"$out/compare-film.log" 2>&1
check render_film_equals_one_device $? "$(tail -1 "$out/compare-film.log")"
"$compare" "$out/one-image.exr" "$out/group-image.exr" 1e-5 >"$out/compare-image.log" 2>&1
check render_image_equals_one_device $? "$(tail -1 "$out/compare-image.log")"

bench=$("$candela" bench cornell-box --backend optix --devices "$devices" --width 640 --height 480 --spp 32 \
  --warmup 4 2>"$out/bench.log")
echo "$bench" >"$out/bench.json"
count=$(tr ',' '\n' <<<"$devices" | wc -l)
grep -Eq "\"devices\":$count,\"median_device_ms_per_frame_by_device\":\[[0-9.e+-]+(,[0-9.e+-]+){$((count - 1))}\],\"combine_ms\":[0-9.e+-]+" \
  <<<"$bench"
check bench_reports_each_device $? "$bench"

if [ -n "${DISPLAY:-}" ]; then
  view=(view cornell-box --backend optix --width 256 --height 192 --seed 4 --frames 40)
  "$candela" "${view[@]}" --devices "$first" --screenshot "$out/view-one.exr" >"$out/view-one.log" 2>&1
  status=$?
  "$candela" "${view[@]}" --devices "$devices" --screenshot "$out/view-group.exr" >"$out/view-group.log" 2>&1
  check view_runs $((status + $?)) "$(grep -E '^(backend|display)' "$out/view-group.log" | tr '\n' ' ')"
  "$compare" "$out/view-one.exr" "$out/view-group.exr" 1e-5 >"$out/compare-view.log" 2>&1
  check view_image_equals_one_device $? "$(tail -1 "$out/compare-view.log")"
else
  echo "SKIP view: DISPLAY is not set (start Xvfb as for viewer_interop.sh)"
fi

tiny=(--width 16 --height 16 --spp 1 -o "$out/tiny.png")
expect missing_gpu 1 "^candela: --devices: there is no GPU 99: this machine has " \
  "$candela" render --backend optix --devices "$first,99" "${tiny[@]}"
expect malformed_list 2 "^candela: --devices: '0,x' is not 'all' or a comma-separated list of GPU indices" \
  "$candela" render --devices 0,x "${tiny[@]}"
expect cpu_backend 1 "^candela: --devices chooses GPUs: it needs the optix backend, not cpu" \
  "$candela" render --backend cpu --devices 0 "${tiny[@]}"
expect all_devices 0 "^backend: optix \(auto: found " "$candela" render --devices all "${tiny[@]}"
exit $failures
