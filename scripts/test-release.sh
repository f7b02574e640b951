#!/usr/bin/env bash
# Builds ./build (Release, as quickstart.sh does) with warnings as errors and runs the whole test suite there.
# Extra arguments go to the CMake configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/run-step.sh
step ./scripts/build.sh -DCANDELA_WERROR=ON "$@"
step ctest --test-dir build --output-on-failure --parallel "$(nproc)"
