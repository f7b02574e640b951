#!/usr/bin/env bash
# same_interactive_options.sh <candela>: `candela view --help` and `candela serve --help` list the interactive
# options (app/interactive) alike: the same names, defaults, limits and descriptions, in the same order. Each
# front end's own options are left out of the comparison, and each must be there.
set -euo pipefail
candela=$1
view_own='--no-interop|--window-capture|--state-file'
serve_own='--port|--bind|--token|--no-token|--stream'

# The entries of `candela <command> --help` under Positionals and Options, one line each.
entries() {
  "$candela" "$1" --help | awk '
    /^(Positionals|Options):/ { listing = 1; next }
    !listing || /^$/ { next }
    /^  [^ ]/ { if (entry != "") print entry; entry = $0; next }
    { sub(/^ +/, " "); entry = entry $0 }
    END { if (entry != "") print entry }'
}

status=0
for own in "view:$view_own" "serve:$serve_own"; do
  command=${own%%:*}
  IFS='|' read -ra names <<<"${own#*:}"
  # Listed once, then searched: grep -q leaving a pipe early would fail the listing (pipefail) on a busy machine.
  listed=$(entries "$command")
  for name in "${names[@]}"; do
    grep -Eq "^  $name( |$)" <<<"$listed" || { echo "candela $command --help lacks $name"; status=1; }
  done
done
shared_view=$(entries view | grep -Ev "^  ($view_own)( |$)")
shared_serve=$(entries serve | grep -Ev "^  ($serve_own)( |$)")
if [ "$shared_view" != "$shared_serve" ]; then
  echo "view and serve list the interactive options differently:"
  diff <(echo "$shared_view") <(echo "$shared_serve") || true
  status=1
fi
count=$(grep -c . <<<"$shared_view")
[ "$count" -ge 20 ] || { echo "only $count shared entries found: is the help's layout another?"; status=1; }
[ $status -eq 0 ] && echo "view and serve share $count option entries"
exit $status
