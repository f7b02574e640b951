#!/usr/bin/env bash
# measure_video_psnr.sh <write_h264_frames> rest|moving <frame.png>...: encodes rendered frames with serve's H.264
# settings at rest or while moving (write_h264_frames.cpp), decodes them in a headless Chromium as the page does
# (video_decode.mjs) and prints each frame's PSNR against the PNG it came from, their mean and least, and the
# stream's rate. A measurement for docs/performance.md, not a test: exits 77 with a line saying why when Node,
# Chromium or playwright-core is missing.
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: measure_video_psnr.sh <write_h264_frames> rest|moving <frame.png>..." >&2; exit 2; }
source "$(dirname "$0")/browser_requirements.sh"
folder=$(mktemp -d)
trap 'rm -rf "$folder"' EXIT
encoder=$1
shift
"$encoder" "$folder" "$@" | tee "$folder/encoded.txt" | tail -2
read -r width height frames _ < <(tail -1 "$folder/encoded.txt")
node "$here/video_decode.mjs" "$folder" "$width" "$height" "$frames" report
