#!/usr/bin/env bash
# Installs playwright-core, pinned by package-lock.json, into tests/serve/node_modules for the browser tests of
# candela serve (it drives the system's Chromium; no browser is downloaded). Does nothing when it is there already.
set -euo pipefail
cd "$(dirname "$0")"
installed=node_modules/playwright-core/package.json
wanted=$(node -p "require('./package-lock.json').packages['node_modules/playwright-core'].version")
if [ -f "$installed" ] && [ "$(node -p "require('./$installed').version")" = "$wanted" ]; then
  echo "playwright-core $wanted: present"
  exit 0
fi
if ! command -v npm >/dev/null; then
  echo "npm is not installed (scripts/install-dependencies.sh installs it): the browser tests are skipped"
  exit 77
fi
PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error
