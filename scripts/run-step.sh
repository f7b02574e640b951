# shellcheck shell=bash
# Sourced by the test stages: `step CMD...` prints the command, runs it, then says how long it took (wall time, and
# the CPU time of the command and its children), so that a slow CI run shows which step grew; returns its status.
step() {
  printf '\n>>> %s\n' "$*"
  local start=$SECONDS status=0 before after
  before=$(awk '{print $16 + $17}' "/proc/$$/stat" 2>/dev/null || echo 0)
  "$@" || status=$?
  after=$(awk '{print $16 + $17}' "/proc/$$/stat" 2>/dev/null || echo 0)
  printf '<<< %d s wall, %d s CPU (status %d): %s\n' $((SECONDS - start)) $(((after - before) / $(getconf CLK_TCK))) \
    "$status" "$1"
  return "$status"
}
