#!/usr/bin/env bash
# run_video_decode_test.sh <write_h264_frames>: encodes frames of a test pattern with serve's H.264 encoder and
# decodes them in a headless Chromium with the page's VideoStream (video_decode.mjs). Exits 77, which CTest counts
# as skipped, with a line saying why, when Node, Chromium or playwright-core is missing.
set -euo pipefail
source "$(dirname "$0")/browser_requirements.sh"
folder=$(mktemp -d)
trap 'rm -rf "$folder"' EXIT
# An odd width: the coded pictures have a column more, which the page leaves out.
"$1" "$folder" 321 180 8
node "$here/video_decode.mjs" "$folder" 321 180 8
