# Sourced by the GPU check scripts: each check prints PASS or FAIL with what it saw, and `failures` counts the
# failed ones for the script's exit status.
failures=0

# check <name> <status> <what it saw>: passes where <status> is 0.
check() {
  if [ "$2" -eq 0 ]; then echo "PASS $1: $3"; else echo "FAIL $1: $3"; failures=$((failures + 1)); fi
}

# expect <name> <expected status> <pattern> <command...>: the command's status and a line of its output. Passes
# with the first matching line; fails with the whole output, on the lines after the FAIL line.
expect() {
  local name=$1 expected=$2 pattern=$3
  shift 3
  local output status
  output=$("$@" 2>&1)
  status=$?
  if [ "$status" -eq "$expected" ] && grep -Eq -- "$pattern" <<<"$output"; then
    check "$name" 0 "$(grep -E -- "$pattern" <<<"$output" | head -1)"
  else
    check "$name" 1 "status $status (expected $expected), output:"$'\n'"$output"
  fi
}
