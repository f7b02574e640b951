#!/usr/bin/env bash
# same_image_as_view.sh <candela> <folder> [options...]: candela view (on a private Xvfb display) and candela serve
# (watched by measure_client.py, which sends no input) render the same frames to the same --screenshot, bit for
# bit, for they make them with one frame step. Exits 77, which CTest counts as skipped, without python3 or Xvfb.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
candela=$1 folder=$2
shift 2
command -v python3 >/dev/null || { echo "skipped: python3 is not installed"; exit 77; }
command -v Xvfb >/dev/null || { echo "skipped: Xvfb is not installed"; exit 77; }
mkdir -p "$folder"
rm -f "$folder"/view.pfm "$folder"/serve.pfm "$folder"/serve.out
shared=(cornell-box --backend cpu --no-cache --width 96 --height 72 --frames 12 --seed 1 "$@")

"$here/../viewer/with_xvfb.sh" "$candela" view "${shared[@]}" --screenshot "$folder/view.pfm"

"$candela" serve "${shared[@]}" --port 0 --screenshot "$folder/serve.pfm" >"$folder/serve.out" &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT
for _ in $(seq 600); do
  grep -q "open http" "$folder/serve.out" && break
  sleep 0.1
done
url=$(grep -o "http://[^ ]*" "$folder/serve.out")
# The client watches until the server has sent its frames and closes the connection.
python3 "$here/measure_client.py" "$url" --seconds 60 --width 96 --height 72 --inputs 0 >/dev/null 2>&1 || true
wait "$server"
trap - EXIT
cmp "$folder/view.pfm" "$folder/serve.pfm"
echo "view and serve wrote the same image"
