#!/usr/bin/env bash
# mpi_stalled_between_frames.sh <candela> <compare_exr> <write_animated_gltf> <folder>: a rank stopped (SIGSTOP)
# between two frames of a sequence (`--frames`) on two ranks loses no frame: rank 0, which finds the rank missing
# when the next frame starts, warns in one line after --rank-timeout, lets it go and renders the remaining frames
# alone, writing every frame once, each the same as a single process's up to the order of the additions. Skips
# (77) without mpirun.
set -u
candela=$1 compare=$2 writer=$3 out=$4
source "$(dirname "$0")/mpi_common.sh"
enter_folder "$out"
scene=$("$writer" scene) || fail "writing the animated glTF"
# Once the films of a frame are added up (rank 0's "films of 2 ranks" line), rank 0 alone denoises and writes the
# frame while rank 1 goes on to the next one and waits for rank 0 there: rank 1 is stopped then.
args=("$scene" --no-cache --backend cpu --threads 1 --width 640 --height 480 --seed 3 --fps 2 --spp 2
      --denoise atrous)

stop_rank_one stall 'grep -q "^films of 2 ranks" stall.log' 0 "$out/stall_##.exr" -n 2 "$candela" render \
  "${args[@]}" --frames 0:2 --rank-timeout 2s -o "$out/stall_##.exr"
expect_line stall.log "candela: warning: the ranks did not all come to the next frame within 2 s (--rank-timeout); rank 0 lets them go and renders the remaining frames alone"
! grep -q "did not finish" stall.log || fail "rank 1 was stopped within a frame, not between frames: $(cat stall.log)"
frames_as_one_process stall 0:2 "$candela" "$compare" "${args[@]}"
echo "a rank stopped between the first two of three frames: every frame written once, as a single process renders it"
