# Sourced by the test stages: `step CMD...` prints the command, then runs it.
step() {
  printf '\n>>> %s\n' "$*"
  "$@"
}
