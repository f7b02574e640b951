#!/usr/bin/env bash
# Configures and builds candela in ./build (Release). Extra arguments go to the CMake configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S . -B build "${generator[@]}" "$@"
cmake --build build --parallel "$(nproc)"
