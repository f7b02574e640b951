#!/usr/bin/env bash
# expect.sh <exit status> <pattern or ''> <command...>: runs the command and checks its exit status and that
# its stderr+stdout match the extended regular expression.
expected_status=$1 pattern=$2
shift 2
output=$("$@" 2>&1)
status=$?
if [ "$status" -ne "$expected_status" ]; then
  printf 'expected exit status %s, got %s\n%s\n' "$expected_status" "$status" "$output"
  exit 1
fi
if [ -n "$pattern" ] && ! grep -Eq -- "$pattern" <<<"$output"; then
  printf 'output does not match /%s/:\n%s\n' "$pattern" "$output"
  exit 1
fi
exit 0
