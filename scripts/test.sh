#!/usr/bin/env bash
# Installs what is missing, then runs every check CI runs, each a script of its own:
#   test-release.sh     the Release build in ./build with warnings as errors, and the whole test suite
#   test-sanitized.sh   a second build in ./build-sanitize with AddressSanitizer + UndefinedBehaviorSanitizer,
#                       and the test suite there
#   test-thread-sanitized.sh
#                       a third build in ./build-tsan with ThreadSanitizer, of what the tests of the threaded
#                       parts need (device threads, stop signals, candela serve's hub and server), and those tests
#   check-format.sh     every C++ file as .clang-format says (scripts/format.sh applies it)
# Both test suites replay every fuzz seed and regression input (tests/fuzz). Stops at the first stage that fails.
# Each stage, and each step within it, ends with a line of its wall and CPU time (scripts/run-step.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/run-step.sh
step ./scripts/install-dependencies.sh
step ./scripts/test-release.sh
step ./scripts/test-sanitized.sh
step ./scripts/test-thread-sanitized.sh
step ./scripts/check-format.sh
