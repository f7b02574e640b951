#!/usr/bin/env bash
# Builds ./build-tsan with ThreadSanitizer (-O1 -g1, as test-sanitized.sh) and runs the tests of the threaded parts
# there, those labelled `threads`: the device threads (test_devices), a stop signal that ends a render's sample
# schedule from another thread (test_sample_dispenser), ClientHub under concurrent browsers and a real
# `candela serve` driven by concurrent WebSocket and HTTP clients, then SIGTERM (test_serve_threads). Only what
# they need is built; the viewer's window and MPI are left out of this build. halt_on_error makes the first report
# fail the test it comes from (the server, a child process, then exits with TSan's status 66).
# TBB is not instrumented, so nothing here runs tbb::parallel_for on more than one thread: the server runs on one
# CPU (tests/serve/serve_process.h). The distributed schedule is not here: it runs one thread per MPI rank, and
# what its ranks share goes through MPI, which TSan cannot see. Warnings are not errors in this build: under TSan's
# instrumentation GCC's flow-based warnings see impossible sizes (a memset of 2^64 bytes where a vector shrinks in
# scene/loaders/pbrt/pbrt_ply.cpp); test-release.sh holds the code to -Werror. No suppressions are needed.
# Extra arguments go to the CMake configure step.
#
# On a shared 2-core machine (load 4 to 9) the stage took 4.8 minutes of CPU time and 5.3 of wall time from an
# empty ./build-tsan, nearly all of it the build; the tests take under 3 seconds. On 2 cores of its own that is
# about 3 minutes, which makes test.sh about 35 minutes instead of 32.
set -euo pipefail
cd "$(dirname "$0")/.."
# GCC's TSan runtime expects the program's memory where it lays out its shadow: on kernels with more than 28 bits
# of mmap randomisation (vm.mmap_rnd_bits, 32 on recent Ubuntu kernels) its programs stop with "unexpected memory
# mapping", so there this stage runs without address randomisation (setarch -R; the build runs the tests too, to
# list them, and every child inherits it).
if [ "$(cat /proc/sys/vm/mmap_rnd_bits 2>/dev/null || echo 0)" -gt 28 ] && [ -z "${CANDELA_TSAN_NO_ASLR:-}" ]; then
  CANDELA_TSAN_NO_ASLR=1 exec setarch "$(uname -m)" -R "$0" "$@"
fi
source scripts/run-step.sh
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
step cmake -S . -B build-tsan "${generator[@]}" -DCANDELA_SANITIZE_THREAD=ON -DCANDELA_WERROR=OFF \
  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DCANDELA_BUILD_BENCHMARKS=OFF -DCANDELA_DEVICE_COMPILE_CHECK=OFF \
  -DCANDELA_BUILD_VIEWER=OFF -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON "$@"
step cmake --build build-tsan --parallel "$(nproc)" --target test_devices test_sample_dispenser test_serve_threads
export TSAN_OPTIONS="${TSAN_OPTIONS:-halt_on_error=1 second_deadlock_stack=1}"
step ctest --test-dir build-tsan --label-regex '^threads$' --output-on-failure --parallel "$(nproc)"
