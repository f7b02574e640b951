#!/usr/bin/env bash
# bundle.sh <build dir> <output dir>: copies candela, test_gpu, test_api_gpu, denoise_gpu_bench, sampler_convergence,
# light_sampler_convergence, restir_convergence, image_compare, compare_exr, candela-generate-scene, the GPU check and
# bench scripts (with checks_common.sh, which they source, and serve_client.py, which serve_first_frame.py
# imports) and the bench scenes, and the shared libraries the binaries load (not the C/C++ runtime's, not the NVIDIA
# driver's) into <output dir>, so that the GPU checks run on a machine that has the GPU but not the build
# dependencies:
#   LD_LIBRARY_PATH=<output dir>/lib <output dir>/test_gpu
set -euo pipefail
build=$1 out=$2
here=$(dirname "$(realpath "$0")")
mkdir -p "$out/lib"
cp "$build/src/candela" "$build/src/candela-generate-scene" "$build/tests/gpu/test_gpu" "$build/tests/gpu/test_api_gpu" "$build/bench/denoise_gpu_bench" "$build/bench/sampler_convergence" \
  "$build/bench/light_sampler_convergence" "$build/bench/restir_convergence" "$here/error_paths.sh" "$here/cold_start.sh" \
  "$here/../../bench/gpu_bench.sh" "$here/../../bench/gpu_town_bench.sh" "$build/tests/viewer/image_compare" "$here/viewer_interop.sh" \
  "$build/tests/distributed/compare_exr" "$here/multi_gpu.sh" "$here/checks_common.sh" \
  "$here/../../bench/multi_gpu_bench.sh" "$here/serve_first_frame.py" "$here/../serve/serve_client.py" "$out/"
cp -r "$here/../../bench/scenes" "$out/"
for binary in "$out/candela" "$out/test_gpu" "$out/test_api_gpu" "$out/denoise_gpu_bench" "$out/sampler_convergence" \
  "$out/light_sampler_convergence" "$out/restir_convergence" "$out/image_compare" "$out/compare_exr" "$out/candela-generate-scene"; do
  ldd "$binary" | awk '/=> \//{print $3}' | while read -r library; do
    case $(basename "$library") in
      libc.so* | libm.so* | libgcc_s.so* | libstdc++.so* | ld-linux* | libpthread.so* | libdl.so* | librt.so*) ;;
      libcuda.so* | libnvoptix.so*) ;;
      *) cp -L "$library" "$out/lib/" ;;
    esac
  done
done
du -sh "$out"
