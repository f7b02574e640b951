#!/usr/bin/env bash
# run_browser_test.sh <candela> <test>: one browser test of candela serve (browser_test.mjs). Exits 77, which CTest
# counts as skipped, with a line saying why, when Node, Chromium or playwright-core is missing.
set -euo pipefail
source "$(dirname "$0")/browser_requirements.sh"
[ "$2" != measure ] || command -v python3 >/dev/null || skip "python3 is not installed"
exec node "$here/browser_test.mjs" "$1" "$2"
