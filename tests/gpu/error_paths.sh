#!/usr/bin/env bash
# error_paths.sh [candela binary]: the OptiX backend's failures as a user meets them, on a machine with an
# NVIDIA GPU. Each check prints PASS or FAIL with what it saw; the exit status counts the failures.
# Needs root for two checks: hiding libnvoptix (a private mount namespace) and filling the GPU's memory
# (PyTorch). Those are reported as SKIP where that is not possible.
set -uo pipefail
candela=$(realpath "${1:-build/src/candela}")
work=$(mktemp -d)
tiny=(--spp 1 --width 16 --height 16)
source "$(dirname "$0")/checks_common.sh"

expect startup_line 0 "^optix: .+ driver [0-9.]+ \(CUDA [0-9.]+\), OptiX ABI [0-9]+ .*RT cores: " \
  "$candela" render --backend optix "${tiny[@]}" -o "$work/a.png"
expect auto_picks_optix 0 "^backend: optix \(auto: found " "$candela" render "${tiny[@]}" -o "$work/b.png"
expect no_cuda_device 1 "^candela: no CUDA device found" \
  env CUDA_VISIBLE_DEVICES= "$candela" render --backend optix "${tiny[@]}" -o "$work/c.png"
expect auto_without_device_is_cpu 0 "^backend: cpu \(auto: no usable GPU: no CUDA device found" \
  env CUDA_VISIBLE_DEVICES= "$candela" render "${tiny[@]}" -o "$work/d.png"
expect denoiser_without_weights_continues 0 "candela: .*(OptiX error 7990).*kept without denoising|^$work/e.png" \
  "$candela" render --backend optix --denoise optix "${tiny[@]}" -o "$work/e.png"
expect restir_megakernel_renders 0 "^$work/g.png" "$candela" render --backend optix --restir di "${tiny[@]}" -o "$work/g.png"
expect restir_wavefront_refused 1 "^candela: --restir runs in the megakernel schedule only" \
  env CANDELA_GPU_SCHEDULE=wavefront "$candela" render --backend optix --restir di "${tiny[@]}" -o "$work/h.png"

# libnvoptix missing: /dev/null mounted over the library, in a mount namespace of this check alone.
library=$(ldconfig -p | awk '/libnvoptix\.so\.1 /{print $NF; exit}')
[ -n "$library" ] || library=$(find / -xdev -name 'libnvoptix.so.1' 2>/dev/null | head -1)
if [ -n "$library" ] && unshare -m true 2>/dev/null; then
  hide="mount --bind /dev/null '$(realpath "$library")'"
  expect libnvoptix_missing 1 "^candela: the NVIDIA driver's OptiX library libnvoptix.so.1 was not found \(OptiX error 7804\)" \
    unshare -m sh -c "$hide && exec '$candela' render --backend optix ${tiny[*]} -o '$work/f.png'"
else
  echo "SKIP libnvoptix_missing: no libnvoptix.so.1 found or no mount namespaces here"
fi

# Out of device memory: another process holds all but 2 GiB, the render asks for a 3 GiB accumulation buffer.
if python3 -c 'import torch; assert torch.cuda.is_available()' 2>/dev/null; then
  python3 - "$work/hog_ready" <<'PY' &
import sys, time, torch
free, total = torch.cuda.mem_get_info()
hold = torch.empty(free - 2 * 2**30, dtype=torch.uint8, device="cuda")
open(sys.argv[1], "w").close()
time.sleep(300)
PY
  hog=$!
  for _ in $(seq 120); do [ -e "$work/hog_ready" ] && break; sleep 0.5; done
  expect out_of_memory 1 "^candela: out of device memory: asked for 3.00 GiB for the film's radiance sums" \
    "$candela" render --backend optix --spp 1 --width 16384 --height 16384 -o "$work/g.exr"
  kill "$hog"
  wait "$hog" 2>/dev/null
else
  echo "SKIP out_of_memory: no PyTorch with CUDA to fill the GPU's memory"
fi

rm -rf "$work"
echo "error paths: $failures failed"
exit "$failures"
