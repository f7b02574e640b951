# Sourced by the scripts that run a test in a headless Chromium: exits 77, which CTest counts as skipped, with a
# line saying why, when Node, Chromium or playwright-core is missing; else exports CHROMIUM.
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
skip() { echo "skipped: $1"; exit 77; }
command -v node >/dev/null || skip "node is not installed (scripts/install-dependencies.sh installs nodejs)"
chromium="${CHROMIUM:-/usr/bin/chromium}"
[ -x "$chromium" ] || skip "no Chromium at $chromium (scripts/install-dependencies.sh installs chromium; CHROMIUM names another)"
[ -d "$here/node_modules/playwright-core" ] || skip "playwright-core is not installed (tests/serve/install-browser-test-deps.sh)"
export CHROMIUM="$chromium"
