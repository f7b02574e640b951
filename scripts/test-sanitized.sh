#!/usr/bin/env bash
# Builds ./build-sanitize with AddressSanitizer + UndefinedBehaviorSanitizer (-O1: several times faster tests
# than -O0, and no less checked) and runs the test suite there. Any report fails the test it comes from: UBSan
# does not recover (CANDELA_SANITIZE adds -fno-sanitize-recover) and ASan stops at the first error.
# Exclusions are in the CMake files next to the tests they concern, each with its reason: the viewer's tests
# under Xvfb run without leak detection (tests/viewer/CMakeLists.txt: Mesa's driver leaks where no suppression
# can name it). Extra arguments go to the CMake configure step.
#
# The whole suite runs: on a shared 2-core machine (load about 12) the build took 7.0 minutes of CPU time and
# the suite 4.0 (27.6 and 13.3 minutes of wall time), about 4 + 3 minutes on 2 cores of its own. The longest
# test is the denoisers' quality check on the material gallery.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/run-step.sh
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
step cmake -S . -B build-sanitize "${generator[@]}" -DCANDELA_SANITIZE=ON -DCANDELA_WERROR=ON \
  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DCANDELA_BUILD_BENCHMARKS=OFF -DCANDELA_DEVICE_COMPILE_CHECK=OFF "$@"
step cmake --build build-sanitize --parallel "$(nproc)"
export ASAN_OPTIONS="${ASAN_OPTIONS:-strict_string_checks=1:check_initialization_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
step ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)"
