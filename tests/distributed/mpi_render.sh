#!/usr/bin/env bash
# mpi_render.sh <candela> <compare_exr> <folder>: `mpirun -n 2 candela render` renders the same sample indices as
# one process (equal per-pixel sample counts), and the same image up to the order of the additions; a rank that
# cannot read the scene makes one error line and exit status 1. Skips (77) without mpirun.
set -u
candela=$1 compare=$2 out=$3
source "$(dirname "$0")/mpi_common.sh"
enter_folder "$out"
args=(cornell-box --backend cpu --threads 1 --width 32 --height 24 --spp 24 --seed 3 --aov albedo,normal,depth)

"$candela" render "${args[@]}" --checkpoint single.exr -o single-image.exr >/dev/null 2>&1 || fail "single render"
"${mpirun[@]}" -n 2 "$candela" render "${args[@]}" --checkpoint mpi.exr -o mpi-image.exr >mpi.log 2>&1 ||
  fail "mpirun -n 2: $(cat mpi.log)"
grep -q "rendered 32x24 at 24 spp" mpi.log || fail "no report from rank 0: $(cat mpi.log)"
# Sums of floats added in another order: a few units in the last place of float.
"$compare" single.exr mpi.exr 1e-5 >compare.log || fail "films: $(cat compare.log)"
"$compare" single-image.exr mpi-image.exr 1e-5 >compare-image.log || fail "images: $(cat compare-image.log)"

# Stopped with SIGUSR1 (what mpirun forwards to the ranks; SIGTERM ends its job), then resumed by two ranks:
# the same sample indices as an uninterrupted render (equal counts), sums of tens of thousands of samples
# added in another order (1e-4).
small=(cornell-box --backend cpu --threads 1 --width 8 --height 8 --seed 5)
"${mpirun[@]}" -n 2 "$candela" render "${small[@]}" --spp 1000000 --checkpoint stop.exr --checkpoint-every 0.2s \
  -o never.exr >stop.log 2>&1 &
pid=$!
for _ in $(seq 600); do [ -e stop.exr ] && break; sleep 0.1; done
kill -USR1 $pid
wait $pid
status=$?
[ "$status" -ne 0 ] || fail "mpirun ended with status 0 after SIGUSR1"
done=$(sed -nE 's/^candela: SIGUSR1 stopped the render after ([0-9]+) of 1000000 samples per pixel.*/\1/p' stop.log)
[ -n "$done" ] || fail "no stop message: $(cat stop.log)"
[ ! -e never.exr ] || fail "the image was written after SIGUSR1"
total=$((done + 20))
"${mpirun[@]}" -n 2 "$candela" render "${small[@]}" --spp $total --resume stop.exr --checkpoint stop.exr \
  -o resumed.exr >resume.log 2>&1 || fail "resuming under mpirun: $(cat resume.log)"
"$candela" render "${small[@]}" --spp $total --checkpoint straight.exr -o straight-image.exr >/dev/null 2>&1 ||
  fail "uninterrupted render"
"$compare" straight.exr stop.exr 1e-4 >compare-stop.log || fail "after SIGUSR1 and resuming: $(cat compare-stop.log)"

# The scene is on one node's disk only.
printf 'v 0 0 -2\nv 1 0 -2\nv 0 1 -2\nf 1 2 3\n' >triangle.obj
failure=$(rank_without_scene "$out" triangle.obj "$out/triangle.png" "$candela" render triangle.obj --no-cache \
          --backend cpu --width 8 --height 8 --spp 2 -o "$out/triangle.png") || { echo "$failure"; exit 1; }
echo "mpirun -n 2 equals one process; a rank without the scene: $failure"
