#!/usr/bin/env bash
# viewer_interop.sh <candela> <image_compare> <output dir>: the OptiX viewer's two ways to the screen on a machine
# with an NVIDIA GPU and an X display whose OpenGL runs on that GPU (Xvfb with NVIDIA's client GLX,
# __GLX_VENDOR_LIBRARY_NAME=nvidia; that library loads libX11-xcb, libxcb-glx, -dri3, -present, -randr, -sync and
# -xfixes at run time and, where one is missing, lists no FBConfig). `candela view` runs twice with the same scene, seed and frames, once through
# CUDA-OpenGL interop and once through the host copy (--no-interop), and a headless `candela render` of the same
# scene and samples runs with another seed. Checks, each printed as PASS or FAIL:
#   - each run took the path it was asked for;
#   - the two windows show the same pixels: exactly, since both paths put the same floats (the accumulated film
#     times 1/frames, one IEEE multiplication on the device or on the host) into the same RGBA32F texture, drawn
#     by the same shader on the same GPU at one texel per pixel;
#   - the two runs' films (--screenshot) are the same, so that equal windows do not come from equal mistakes in
#     rendering;
#   - the window shows the film as the PNG writer tone maps it, to one 8-bit step (GLSL against CPU);
#   - the film agrees statistically with the headless render (image_compare agree), and disagrees with a
#     direct-light-only render, which shows the comparison can tell;
#   - with the OptiX AI denoiser chosen, the film is denoised, or the viewer says why it cannot be and shows
#     the plain interop window.
# Prints the fps each run's panel showed at the end. Exit status: the number of failed checks. Leaves the images
# and logs in <output dir>. Size and length: WIDTH, HEIGHT, FRAMES (default 1280 x 720, 300 frames).
set -uo pipefail
if [ $# -ne 3 ]; then
  echo "usage: viewer_interop.sh <candela> <image_compare> <output dir>" >&2
  exit 2
fi
candela=$(realpath "$1") compare=$(realpath "$2") out=$3
width=${WIDTH:-1280} height=${HEIGHT:-720} frames=${FRAMES:-300}
if [ -z "${DISPLAY:-}" ]; then
  echo "viewer_interop.sh: DISPLAY is not set; start Xvfb and export DISPLAY first" >&2
  exit 2
fi
mkdir -p "$out"
common=(cornell-box --backend optix --width "$width" --height "$height")
source "$(dirname "$0")/checks_common.sh"

# view <name> [options]: one viewer run; its log is <name>.log.
view() {
  local name=$1
  shift
  "$candela" view "${common[@]}" --seed 1 --max-depth 8 --frames "$frames" --screenshot "$out/$name.png" \
    --window-capture "$out/$name-window.png" --state-file "$out/$name-state.json" "$@" >"$out/$name.log" 2>&1
  local status=$?
  check "${name}_runs" "$status" "candela view exited $status; $(grep -E '^(window|display):' "$out/$name.log" | tr '\n' ' ')"
}
fps() { sed -nE 's/^viewer: .*the panel showed ([0-9.]+) fps, ([0-9.]+) ms\/frame/\1 fps (\2 ms\/frame)/p' "$out/$1.log"; }

view interop
grep -q '^display: CUDA-OpenGL interop' "$out/interop.log"
check interop_path $? "$(grep '^display:' "$out/interop.log")"
view copy --no-interop
grep -q '^display: host copy .*interop switched off' "$out/copy.log"
check copy_path $? "$(grep '^display:' "$out/copy.log")"

result=$("$compare" exact "$out/interop-window.png" "$out/copy-window.png" --crop "$width" "$height" 2>&1)
check windows_identical $? "$result"
result=$("$compare" exact "$out/interop.png" "$out/copy.png" 2>&1)
check films_identical $? "$result"
result=$("$compare" exact "$out/interop-window.png" "$out/interop.png" --crop "$width" "$height" --tolerance 1 2>&1)
check window_shows_film $? "$result"

"$candela" render "${common[@]}" --seed 2 --max-depth 8 --spp "$frames" -o "$out/render.png" >"$out/render.log" 2>&1
check render_runs $? "candela render, seed 2, $frames spp"
"$candela" render "${common[@]}" --seed 3 --max-depth 1 --spp "$frames" -o "$out/direct.png" >"$out/direct.log" 2>&1
check direct_render_runs $? "candela render, seed 3, direct light only"
result=$("$compare" agree "$out/interop.png" "$out/render.png" 2>&1)
check agrees_with_render $? "$result"
result=$("$compare" agree "$out/interop.png" "$out/direct.png" 2>&1)
[ $? -eq 1 ]
check disagrees_with_direct_only $? "$result"

# The OptiX AI denoiser chosen at start: it denoises (the film differs from the plain one), or, where it cannot
# run (a driver without the denoiser's weights, OptiX error 7990), the panel says why and the viewer renders on
# as if none had been chosen: then its window is the plain interop window, pixel for pixel.
view denoised --denoise optix
if grep -q '^no OptiX AI denoiser: ' "$out/denoised.log"; then
  result=$("$compare" exact "$out/denoised-window.png" "$out/interop-window.png" --crop "$width" "$height" 2>&1)
  check optix_denoiser_unavailable_renders_on $? "$(grep '^no OptiX AI denoiser: ' "$out/denoised.log"); $result"
else
  result=$("$compare" exact "$out/denoised.png" "$out/interop.png" 2>&1)
  [ $? -eq 1 ]
  check optix_denoiser_changes_the_film $? "$result"
fi

echo "fps: interop $(fps interop); host copy $(fps copy); OptiX AI denoiser chosen $(fps denoised);" \
  "$width x $height, $frames frames, 1 sample per pixel each"
echo "viewer interop: $failures failed"
exit "$failures"
