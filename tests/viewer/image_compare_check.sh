#!/usr/bin/env bash
# image_compare_check.sh <candela> <image_compare> <work dir>: image_compare passes what it must pass and fails
# what it must fail, on small CPU renders of the Cornell box.
set -uo pipefail
candela=$1 compare=$2 work=$3
mkdir -p "$work"
render() { "$candela" render cornell-box --backend cpu --width 64 --height 48 --spp 16 "$@" >/dev/null 2>&1; }
render --seed 2 -o "$work/a.png" && render --seed 3 -o "$work/b.png" && render --seed 4 --max-depth 1 -o "$work/direct.png" ||
  { echo "candela render failed"; exit 1; }
failures=0
# expect <status> <image_compare arguments...>
expect() {
  local want=$1
  shift
  "$compare" "$@"
  local status=$?
  if [ "$status" -ne "$want" ]; then
    echo "FAIL: image_compare $* exited $status, expected $want"
    failures=$((failures + 1))
  fi
}
expect 0 exact "$work/a.png" "$work/a.png"
expect 1 exact "$work/a.png" "$work/b.png"
expect 0 exact "$work/a.png" "$work/b.png" --tolerance 255
expect 0 agree "$work/a.png" "$work/b.png"
expect 1 agree "$work/a.png" "$work/direct.png"
expect 0 exact "$work/a.png" "$work/b.png" --crop 1 1 --tolerance 255
expect 2 exact "$work/a.png" "$work/b.png" --crop 65 48
expect 2 exact "$work/a.png" "$work/missing.png"
exit "$failures"
