#!/usr/bin/env bash
# mpi_stalled_frames.sh <candela> <compare_exr> <write_animated_gltf> <folder>: a rank stopped (SIGSTOP) in the
# middle of a sequence (`--frames`) on two ranks loses no frame: after --rank-timeout rank 0 warns, renders the
# stopped rank's samples of that frame again and the remaining frames alone, and writes every frame once, each
# the same as a single process's up to the order of the additions. Skips (77) without mpirun.
set -u
candela=$1 compare=$2 writer=$3 out=$4
source "$(dirname "$0")/mpi_common.sh"
enter_folder "$out"
scene=$("$writer" scene) || fail "writing the animated glTF"
# Frames of 0.7 s (an idle machine) to 2 s (a busy one) on two ranks: rank 1 is stopped 0.3 s into the second
# frame, while it renders (a stop in its last batch is the same to rank 0: the rank is not ready in time).
args=("$scene" --no-cache --backend cpu --threads 1 --width 32 --height 24 --seed 3 --fps 2 --spp 1500)

stop_rank_one stall "[ -e stall_00.exr ]" 0.3 "$out/stall_##.exr" -n 2 "$candela" render "${args[@]}" \
  --frames 0:3 --rank-timeout 2s -o "$out/stall_##.exr"
expect_line stall.log "candela: warning: rank 1 did not finish its batches within 2 s (--rank-timeout); rank 0 renders its samples again and the rest of the render alone"
expect_line stall.log "candela: warning: the other ranks were let go when a rank stopped answering; rank 0 renders the remaining frames alone"
frames_as_one_process stall 0:3 "$candela" "$compare" "${args[@]}"
echo "a rank stopped in the second of four frames: every frame written once, as a single process renders it"
