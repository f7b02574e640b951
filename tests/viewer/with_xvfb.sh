#!/usr/bin/env bash
# Runs a command on a private Xvfb display (Mesa's software OpenGL) and stops the server afterwards.
# Exits 77, which CTest reads as "skipped", only when Xvfb is not installed.
set -euo pipefail
if ! command -v Xvfb >/dev/null; then
  echo "Xvfb is not installed (scripts/install-dependencies.sh installs it): skipping" >&2
  exit 77
fi

ready=$(mktemp)
trap 'rm -f "$ready"; [ -n "${server:-}" ] && kill "$server" 2>/dev/null; wait 2>/dev/null || true' EXIT
# -displayfd picks a free display number and writes it once the server accepts connections.
Xvfb -displayfd 3 -screen 0 1600x1000x24 -nolisten tcp 3>"$ready" 2>/dev/null &
server=$!
# Xvfb starts in well under a second when idle, but CI runs the whole suite in parallel on 2 cores, where it
# was seen to take over 5 s: wait up to 60 s (the loop ends as soon as the server is ready).
for _ in $(seq 1200); do
  [ -s "$ready" ] && break
  kill -0 "$server" 2>/dev/null || { echo "Xvfb failed to start" >&2; exit 1; }
  sleep 0.05
done
[ -s "$ready" ] || { echo "Xvfb did not become ready within 60 s" >&2; exit 1; }
export DISPLAY=":$(head -n1 "$ready")"
# Mesa's software rasteriser: the same pixels with or without a GPU in the machine.
export LIBGL_ALWAYS_SOFTWARE=1
"$@"
