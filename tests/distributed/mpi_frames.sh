#!/usr/bin/env bash
# mpi_frames.sh <candela> <compare_exr> <write_animated_gltf> <folder>: `mpirun -n 2 candela render --frames`
# renders every frame of an animated glTF as one process does, up to the order of the additions, and writes each
# frame once; a sequence of fewer frames than ranks too; a rank that cannot read the scene makes one error line,
# exit status 1 and no frame. Skips (77) without mpirun.
set -u
candela=$1 compare=$2 writer=$3 out=$4
source "$(dirname "$0")/mpi_common.sh"
enter_folder "$out"
scene=$("$writer" scene) || fail "writing the animated glTF"
args=("$scene" --no-cache --backend cpu --threads 1 --width 32 --height 24 --seed 3 --aov albedo,normal,depth --fps 2)

"$candela" render "${args[@]}" --spp 16 --frames 0:3 -o single_##.exr >single.out 2>single.log ||
  fail "single process: $(cat single.log)"
"${mpirun[@]}" -n 2 "$candela" render "${args[@]}" --spp 16 --frames 0:3 -o mpi_##.exr >mpi.out 2>mpi.log ||
  fail "mpirun -n 2: $(cat mpi.log)"
for f in 00 01 02 03; do
  # Every rank's standard output comes to mpirun's: a frame written by two ranks would be listed twice.
  written=$(grep -c "/mpi_$f\.exr\$" mpi.out)
  [ "$written" -eq 1 ] || fail "frame $f written $written times: $(cat mpi.out)"
  # Sums of floats added in another order: a few units in the last place of float.
  "$compare" "single_$f.exr" "mpi_$f.exr" 1e-5 >"compare_$f.log" || fail "frame $f: $(cat "compare_$f.log")"
done
# The quad moves between frames, so a frame posed at another frame's time would differ.
"$compare" single_00.exr single_01.exr 1e-5 >/dev/null && fail "frames 0 and 1 are the same image"

# One frame, two ranks: both take samples of it (rank 0 reports its share).
"$candela" render "${args[@]}" --spp 64 --frames 2:2 -o single_one_##.exr >/dev/null 2>&1 || fail "single frame"
"${mpirun[@]}" -n 2 "$candela" render "${args[@]}" --spp 64 --frames 2:2 -o one_##.exr >one.out 2>one.log ||
  fail "one frame on two ranks: $(cat one.log)"
"$compare" single_one_02.exr one_02.exr 1e-5 >compare_one.log || fail "one frame on two ranks: $(cat compare_one.log)"
share=$(sed -nE 's/.*rank 0 rendered ([0-9]+) of the 64 samples per pixel$/\1/p' one.log)
[ -n "$share" ] && [ "$share" -lt 64 ] || fail "one frame on two ranks: rank 1 rendered none of it: $(cat one.log)"

# The scene is on one node's disk only.
failure=$(rank_without_scene "$out" "$scene" "$out/lost_0.png" "$candela" render animated.gltf --no-cache \
          --backend cpu --width 8 --height 8 --spp 2 --frames 0:1 -o "$out/lost_#.png") || { echo "$failure"; exit 1; }
echo "mpirun -n 2 --frames equals one process, each frame written once; one frame on two ranks too; a rank" \
     "without the scene: $failure"
