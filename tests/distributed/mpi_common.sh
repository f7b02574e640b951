# Sourced by the mpirun tests: the launcher's command line, failing, the test's folder, a rank stopped in the middle
# of a job, and the check of a rank without the scene.
command -v mpirun >/dev/null || { echo "mpirun not found: skipped"; exit 77; }
mpirun=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpirun+=(--allow-run-as-root)
fail() { echo "FAILED: $*"; exit 1; }

# enter_folder <folder>: makes <folder> (the test's own, under the build folder) the working directory, with
# nothing left in it from an earlier run.
enter_folder() {
  mkdir -p "$1" || fail "cannot make $1"
  cd "$1" || fail "cannot enter $1"
  rm -rf ./*
}

# stop_rank_one <name> <when> <delay> <text> <mpirun arguments...>: runs `mpirun <mpirun arguments...>` in the
# background under `timeout`, so that a job that hangs ends the test, with its standard output in <name>.out and
# its errors in <name>.log. Once the command <when> succeeds (`[ -e stall.exr ]`, asked every 0.05 s) and <delay>
# more seconds have passed, stops (SIGSTOP) rank 1 of the job: the process whose command line holds <text> (a path
# of this test's folder, which no other job names) and whose Open MPI rank is 1. Waits for the job, lets the
# stopped rank go (SIGCONT) and fails unless the job ended with exit status 0.
stop_rank_one() {
  local name=$1 when=$2 delay=$3 text=$4
  shift 4
  timeout 120 "${mpirun[@]}" "$@" >"$name.out" 2>"$name.log" &
  local launcher=$! stopped='' pid ready=''
  for _ in $(seq 1200); do eval "$when" && ready=1 && break; sleep 0.05; done
  [ -n "$ready" ] || fail "never $when: $(cat "$name.log")"
  sleep "$delay"
  for pid in $(pgrep -f "$text"); do
    [ "$(tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | sed -n 's/^OMPI_COMM_WORLD_RANK=//p')" = 1 ] && stopped=$pid
  done
  [ -n "$stopped" ] || fail "rank 1 not found"
  kill -STOP "$stopped"
  wait "$launcher"
  local status=$?
  kill -CONT "$stopped" 2>/dev/null
  [ "$status" -eq 0 ] || fail "exit status $status: $(cat "$name.log")"
}

# frames_as_one_process <name> <first:last> <candela> <compare_exr> <render arguments...>: renders the frames
# first..last (two digits each) as one process, into single_##.exr, and fails unless the job whose standard output
# is <name>.out wrote each frame <name>_##.exr once, the same as the single process's up to the order of the
# additions.
frames_as_one_process() {
  local name=$1 frames=$2 candela=$3 compare=$4 f written
  shift 4
  "$candela" render "$@" --frames "$frames" -o single_##.exr >single.out 2>single.log ||
    fail "single process: $(cat single.log)"
  for f in $(seq -f %02g "${frames%%:*}" "${frames##*:}"); do
    written=$(grep -c "/${name}_$f\.exr\$" "$name.out")
    [ "$written" -eq 1 ] || fail "frame $f written $written times: $(cat "$name.out") $(cat "$name.log")"
    "$compare" "single_$f.exr" "${name}_$f.exr" 1e-4 >"compare_$f.log" || fail "frame $f: $(cat "compare_$f.log")"
  done
}

# expect_line <file> <line>: fails unless <file> has the line <line>, whole.
expect_line() { grep -qxF "$2" "$1" || fail "no line '$2': $(cat "$1")"; }

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
