#!/usr/bin/env bash
# resume.sh <candela> <compare_exr> <folder>: a render stopped and resumed equals the uninterrupted render, on the
# CPU bit for bit (the resumed film continues the same additions in the same order). Covers a render that ends
# and is continued to more samples, one stopped by SIGTERM, and a resumption with other settings (refused).
set -u
candela=$1 compare=$2 out=$3
mkdir -p "$out" && cd "$out" && rm -f ./*.exr ./*.log
base=(render cornell-box --backend cpu --width 24 --height 16 --max-depth 4 --aov albedo)
args=("${base[@]}" --seed 7)
fail() { echo "FAILED: $*"; exit 1; }

# Ended, then continued to more samples.
"$candela" "${args[@]}" --spp 12 --checkpoint full.exr -o full-image.exr >/dev/null 2>&1 || fail "full render"
"$candela" "${args[@]}" --spp 5 --checkpoint part.exr -o part-image.exr >/dev/null 2>&1 || fail "partial render"
"$candela" "${args[@]}" --spp 12 --resume part.exr --checkpoint part.exr -o resumed-image.exr >/dev/null 2>&1 ||
  fail "resumed render"
"$compare" full.exr part.exr 0 >/dev/null || fail "checkpoints differ: $("$compare" full.exr part.exr 0)"
"$compare" full-image.exr resumed-image.exr 0 >/dev/null || fail "images differ"

# Other settings: one line, exit status 1, the checkpoint kept.
output=$("$candela" "${base[@]}" --spp 12 --seed 8 --resume part.exr -o other.exr 2>&1)
status=$?
[ "$status" -eq 1 ] || fail "resuming with another seed: exit status $status"
grep -Eq "^candela: cannot resume from 'part\.exr': it was rendered with seed '7', this render has '8'$" <<<"$output" ||
  fail "resuming with another seed said: $output"
output=$("$candela" "${args[@]}" --spp 3 --resume part.exr -o fewer.exr 2>&1)
grep -q "it holds 12 samples per pixel, more than the 3 asked for" <<<"$output" || fail "fewer samples said: $output"

# SIGTERM: the render stops at a sample boundary and writes its checkpoint, not the image.
"$candela" "${args[@]}" --spp 1000000 --checkpoint term.exr --checkpoint-every 0.2s -o never.exr 2>term.log &
pid=$!
for _ in $(seq 600); do [ -e term.exr ] && break; sleep 0.1; done
[ -e term.exr ] || fail "no periodic checkpoint: $(cat term.log)"
kill -TERM $pid
wait $pid
status=$?
[ "$status" -eq 143 ] || fail "exit status after SIGTERM: $status, $(cat term.log)"
[ ! -e never.exr ] || fail "the image was written after SIGTERM"
done=$(sed -nE 's/^candela: SIGTERM stopped the render after ([0-9]+) of 1000000 samples per pixel.*/\1/p' term.log)
[ -n "$done" ] || fail "no stop message: $(cat term.log)"
total=$((done + 3))
"$candela" "${args[@]}" --spp $total --checkpoint term.exr --resume term.exr -o term-image.exr >/dev/null 2>&1 ||
  fail "resuming after SIGTERM"
"$candela" "${args[@]}" --spp $total --checkpoint straight.exr -o straight-image.exr >/dev/null 2>&1 ||
  fail "uninterrupted render of $total"
"$compare" straight.exr term.exr 0 >/dev/null || fail "after SIGTERM: $("$compare" straight.exr term.exr 0)"
"$compare" straight-image.exr term-image.exr 0 >/dev/null || fail "images after SIGTERM differ"
echo "resumed renders equal the uninterrupted ones ($done samples before SIGTERM)"
