#!/usr/bin/env bash
# outputs_survive.sh <candela> <folder>: writes that fail (a link to /dev/full, a full disk, an AOV that cannot
# be written) exit 1 with a "cannot write" line, and leave the previous outputs as they were, with no temporary
# file beside them.
set -u
candela=$1
dir=$2/outputs-survive
rm -rf "$dir"
mkdir -p "$dir"
cd "$dir" || exit 1
render=("$candela" render --spp 1 --width 64 --height 48 --backend cpu)

fail() {
  printf '%s\n' "$*"
  exit 1
}
# expect_failure <pattern> <command...>: exit status 1 and the pattern in the output.
expect_failure() {
  local pattern=$1 output status
  shift
  output=$("$@" 2>&1)
  status=$?
  [ "$status" -eq 1 ] || fail "expected exit status 1, got $status from: $* ($output)"
  grep -Eq -- "$pattern" <<<"$output" || fail "output does not match /$pattern/: $output"
}
# expect_content <file> <text>
expect_content() {
  [ "$(cat "$1")" = "$2" ] || fail "$1 was replaced: $(head -c 40 "$1" | tr -c '[:print:]' '.')"
}

ln -s /dev/full full.png
expect_failure "candela: cannot write 'full.png': it leads to '/dev/full', not a regular file" "${render[@]}" -o full.png

# A full disk, as a file size limit (SIGXFSZ ignored, so that writes fail with EFBIG).
for ext in png exr pfm; do
  echo previous > "out.$ext"
  expect_failure "candela: cannot write 'out\\.$ext': " \
    bash -c 'trap "" XFSZ; ulimit -f 1; exec "$@"' limited "${render[@]}" -o "out.$ext"
  expect_content "out.$ext" previous
done

# An AOV that cannot be written (its name is taken by a folder): the image and the other AOVs stay.
echo previous > aov.png
echo previous > aov.normal.png
mkdir aov.albedo.png
expect_failure "candela: cannot write 'aov\\.albedo\\.png': it is not a regular file" \
  "${render[@]}" --aov normal,albedo -o aov.png
expect_content aov.png previous
expect_content aov.normal.png previous

leftovers=$(ls -A | grep -c '\.tmp-')
[ "$leftovers" -eq 0 ] || fail "temporary files left: $(ls -A)"
exit 0
