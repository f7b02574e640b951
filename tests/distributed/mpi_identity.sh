#!/usr/bin/env bash
# mpi_identity.sh <candela> <folder>: ranks that would render different jobs (another seed, size or AOV film, a
# scene file of the same name with other contents) are refused before rendering, in one line naming the rank and
# the difference, at once rather than after --rank-timeout; ranks that read the same files under other paths
# render together. Skips (77) without mpirun.
set -u
candela=$1 out=$2
source "$(dirname "$0")/mpi_common.sh"
enter_folder "$out"
common=(render --backend cpu --threads 1 --height 12 --spp 4 --rank-timeout 60s)

# refused <expected line> <rank 0's arguments> -- <rank 1's arguments>
refused() {
  local expected=$1 zero=() one=()
  shift
  while [ "$1" != -- ]; do zero+=("$1"); shift; done
  shift
  one=("$@")
  local start=$SECONDS text status lines
  text=$("${mpirun[@]}" -n 1 "${zero[@]}" : -n 1 "${one[@]}" 2>&1)
  status=$?
  [ "$status" -eq 1 ] || fail "$expected: exit status $status: $text"
  [ $((SECONDS - start)) -lt 30 ] || fail "$expected: refused only after $((SECONDS - start)) s"
  lines=$(grep '^candela:' <<<"$text" | grep -vc '^candela: warning:')
  [ "$lines" -eq 1 ] || fail "$lines error lines instead of one: $text"
  grep -qxF "$expected" <<<"$text" || fail "expected '$expected', got: $text"
  [ ! -e never.png ] || fail "an image was written: $text"
}

box=("$candela" "${common[@]}" cornell-box --width 16 -o "$out/never.png")
refused "candela: rank 1 of 2: renders another job than rank 0: its seed is '4', rank 0's is '3'" \
  "${box[@]}" --seed 3 -- "${box[@]}" --seed 4
refused "candela: rank 1 of 2: renders another job than rank 0: its maxDepth is '5', rank 0's is '4'" \
  "${box[@]}" --max-depth 4 -- "${box[@]}" --max-depth 5
box=("$candela" "${common[@]}" cornell-box -o "$out/never.png")
refused "candela: rank 1 of 2: renders another job than rank 0: its width is '20', rank 0's is '16'" \
  "${box[@]}" --width 16 -- "${box[@]}" --width 20
refused "candela: rank 1 of 2: renders another job than rank 0: its aovSums is 'yes', rank 0's is 'no'" \
  "${box[@]}" --width 16 -- "${box[@]}" --width 16 --aov albedo

# The same file under two paths renders; another file under the same name does not.
mkdir -p here elsewhere
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >here/tri.obj
cp here/tri.obj elsewhere/tri.obj
tri=("$candela" "${common[@]}" tri.obj --width 16)
text=$("${mpirun[@]}" -n 1 --wdir "$out/here" "${tri[@]}" -o "$out/same.png" : \
       -n 1 --wdir "$out/elsewhere" "${tri[@]}" -o "$out/same.png" 2>&1) || fail "the same file under two paths: $text"
[ -s same.png ] || fail "no image from the same file under two paths: $text"
printf 'v 0 0 0\nv 1 0 0\nv 0 2 0\nf 1 2 3\n' >elsewhere/tri.obj
text=$("${mpirun[@]}" -n 1 --wdir "$out/here" "${tri[@]}" -o "$out/never.png" : \
       -n 1 --wdir "$out/elsewhere" "${tri[@]}" -o "$out/never.png" 2>&1)
status=$?
[ "$status" -eq 1 ] || fail "another file of the same name: exit status $status: $text"
grep -Eqx "candela: rank 1 of 2: renders another job than rank 0: its scene is 'files [0-9a-f]{16}', rank 0's is 'files [0-9a-f]{16}'" <<<"$text" ||
  fail "another file of the same name said: $text"
echo "ranks of different jobs were refused, each in one line"
