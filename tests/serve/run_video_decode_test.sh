#!/usr/bin/env bash
# run_video_decode_test.sh <write_h264_frames>: encodes frames of a test pattern with serve's H.264 encoder and
# decodes them in a headless Chromium with the page's VideoStream (video_decode.mjs). Exits 77, which CTest counts
# as skipped, with a line saying why, when Node, Chromium or playwright-core is missing.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
skip() { echo "skipped: $1"; exit 77; }
command -v node >/dev/null || skip "node is not installed (scripts/install-dependencies.sh installs nodejs)"
chromium="${CHROMIUM:-/usr/bin/chromium}"
[ -x "$chromium" ] || skip "no Chromium at $chromium (scripts/install-dependencies.sh installs chromium; CHROMIUM names another)"
[ -d "$here/node_modules/playwright-core" ] || skip "playwright-core is not installed (tests/serve/install-browser-test-deps.sh)"
export CHROMIUM="$chromium"
folder=$(mktemp -d)
trap 'rm -rf "$folder"' EXIT
# An odd width: the coded pictures have a column more, which the page leaves out.
"$1" "$folder" 321 180 8
node "$here/video_decode.mjs" "$folder" 321 180 8
