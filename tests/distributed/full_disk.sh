#!/usr/bin/env bash
# full_disk.sh <candela> <folder>: checkpoints that cannot be written (here: a file size limit, as a full disk or
# a quota would refuse them) are warnings; the render goes on and writes its image. Stopped by SIGTERM with no
# checkpoint to hold its samples, it writes the image of them instead.
set -u
candela=$1 out=$2
mkdir -p "$out" && cd "$out" && rm -f ./*.exr ./*.png ./*.log
fail() { echo "FAILED: $*"; exit 1; }
# The PNG image (12 KB) fits under the limit, the checkpoint of its float sums (70 KB) does not. Beyond the limit a
# write fails with EFBIG once SIGXFSZ is ignored (as a full disk fails with ENOSPC).
limited() { (trap '' XFSZ; ulimit -f 40; exec "$candela" "$@"); }
args=(render cornell-box --backend cpu --width 64 --height 64 --max-depth 3)

limited "${args[@]}" --spp 40 --checkpoint ck.exr --checkpoint-every 0.1s -o image.png >/dev/null 2>run.log
status=$?
[ "$status" -eq 0 ] || fail "exit status $status: $(cat run.log)"
[ -s image.png ] || fail "no image: $(cat run.log)"
[ ! -e ck.exr ] || fail "a checkpoint beyond the size limit"
ls ./*.tmp* 2>/dev/null && fail "temporary files left"
grep -q "^candela: warning: no checkpoint after 40 samples per pixel: cannot write 'ck.exr': File too large; the render goes on$" run.log ||
  fail "no warning for the last checkpoint: $(cat run.log)"

# In a subshell of its own that becomes candela (exec), so that $! is candela's process.
(trap '' XFSZ; ulimit -f 40; exec "$candela" "${args[@]}" --spp 1000000 --checkpoint term.exr --checkpoint-every 0.1s \
  -o term.png >/dev/null 2>term.log) &
pid=$!
for _ in $(seq 300); do grep -q "warning: no checkpoint" term.log && break; sleep 0.1; done
kill -TERM $pid
wait $pid
status=$?
[ "$status" -eq 143 ] || fail "exit status after SIGTERM: $status, $(cat term.log)"
[ -s term.png ] || fail "no image after SIGTERM without a checkpoint: $(cat term.log)"
grep -q "SIGTERM stopped the render after [0-9]* of 1000000 samples per pixel; with no checkpoint" term.log ||
  fail "no stop message: $(cat term.log)"
echo "the renders went on without their checkpoints and wrote their images"
