#!/usr/bin/env bash
# run_browser_test.sh <candela> <test>: one browser test of candela serve (browser_test.mjs). Exits 77, which CTest
# counts as skipped, with a line saying why, when Node, Chromium or playwright-core is missing.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
skip() { echo "skipped: $1"; exit 77; }
command -v node >/dev/null || skip "node is not installed (scripts/install-dependencies.sh installs nodejs)"
chromium="${CHROMIUM:-/usr/bin/chromium}"
[ -x "$chromium" ] || skip "no Chromium at $chromium (scripts/install-dependencies.sh installs chromium; CHROMIUM names another)"
[ -d "$here/node_modules/playwright-core" ] || skip "playwright-core is not installed (tests/serve/install-browser-test-deps.sh)"
[ "$2" != measure ] || command -v python3 >/dev/null || skip "python3 is not installed"
export CHROMIUM="$chromium"
exec node "$here/browser_test.mjs" "$1" "$2"
