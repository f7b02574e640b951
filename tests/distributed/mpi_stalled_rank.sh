#!/usr/bin/env bash
# mpi_stalled_rank.sh <candela> <compare_exr> <folder>: a rank stopped (SIGSTOP) in the middle of a render of three
# ranks does not lose the render: after --rank-timeout rank 0 warns, takes the stopped rank's samples over, and
# writes the image and the checkpoint, which holds the same sample indices as a single process's (equal counts)
# and the same sums up to the order of the additions. Skips (77) without mpirun.
set -u
candela=$1 compare=$2 out=$3
source "$(dirname "$0")/mpi_common.sh"
enter_folder "$out"
args=(render cornell-box --backend cpu --threads 1 --width 32 --height 24 --spp 1500 --seed 3)

# Rank 1 is stopped when the first checkpoint is written.
stop_rank_one stall "[ -e stall.exr ]" 0 "$out/stall.exr" -n 3 "$candela" "${args[@]}" --rank-timeout 3s \
  --checkpoint "$out/stall.exr" --checkpoint-every 0.5s -o "$out/stall-image.exr"
expect_line stall.log "candela: warning: rank 1 did not finish its batches within 3 s (--rank-timeout); rank 0 renders its samples again and the rest of the render alone"
[ -s stall-image.exr ] || fail "no image: $(cat stall.log)"
"$candela" "${args[@]}" --checkpoint "$out/single.exr" -o "$out/single-image.exr" >/dev/null 2>&1 || fail "single render"
"$compare" single.exr stall.exr 1e-4 >compare.log || fail "films: $(cat compare.log)"
"$compare" single-image.exr stall-image.exr 1e-4 >compare-image.log || fail "images: $(cat compare-image.log)"
echo "a stopped rank's samples were rendered by rank 0; the image and checkpoint were written"
