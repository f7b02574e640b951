#!/usr/bin/env bash
# Installs what is missing, then runs every check CI runs, each a script of its own:
#   test-release.sh     the Release build in ./build with warnings as errors, and the whole test suite
#   test-sanitized.sh   a second build in ./build-sanitize with AddressSanitizer + UndefinedBehaviorSanitizer,
#                       and the test suite there
#   check-format.sh     every C++ file as .clang-format says (scripts/format.sh applies it)
# Both test suites replay every fuzz seed and regression input (tests/fuzz). Stops at the first stage that fails.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-dependencies.sh
./scripts/test-release.sh
./scripts/test-sanitized.sh
./scripts/check-format.sh
