# Sourced by the mpirun tests: the launcher's command line, failing, and the check of a rank without the scene.
command -v mpirun >/dev/null || { echo "mpirun not found: skipped"; exit 77; }
mpirun=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpirun+=(--allow-run-as-root)
fail() { echo "FAILED: $*"; exit 1; }

# rank_without_scene <folder> <scene file> <output> <candela> <render arguments...>: the scene is on one node's
# disk only. Copies <scene file> (and its .bin, if any) into <folder>/here, where rank 0 starts; rank 1 starts in
# <folder>/elsewhere. Checks one error line naming the scene from rank 1, exit status 1 and no <output>; prints
# the error line.
rank_without_scene() {
  local folder=$1 scene=$2 output=$3 candela=$4
  shift 4
  mkdir -p "$folder/here" "$folder/elsewhere"
  cp "$scene" "$folder/here/"
  [ -e "${scene%.*}.bin" ] && cp "${scene%.*}.bin" "$folder/here/"
  local text status lines name
  name=$(basename "$scene")
  text=$("${mpirun[@]}" -n 1 --wdir "$folder/here" "$candela" "$@" : \
         -n 1 --wdir "$folder/elsewhere" "$candela" "$@" 2>&1)
  status=$?
  [ "$status" -eq 1 ] || fail "a rank without the scene: exit status $status: $text"
  # (Rank 0 may warn, of a scene without a light for example; that is no error line.)
  lines=$(grep '^candela:' <<<"$text" | grep -vc '^candela: warning:')
  [ "$lines" -eq 1 ] || fail "a rank without the scene: $lines error lines from candela: $text"
  grep -Eq "^candela: rank 1 of 2: .*${name//./\\.}" <<<"$text" || fail "a rank without the scene said: $text"
  [ ! -e "$output" ] || fail "$output was written although a rank failed"
  grep '^candela: rank' <<<"$text"
}
