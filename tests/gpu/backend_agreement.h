#pragma once
// The GPU agreement tests' comparison: a scene rendered by the CPU backend and by the OptiX backend, each with a
// seed of its own, compared block by block and by the image mean (render_comparison.h).
#include <cstdint>

#include "gpu_render.h"
#include "render_comparison.h"

namespace candela::test {

// The renders compared: size x size pixels, batches of samples, blocks of block x block pixels, significance alpha.
struct AgreementRun {
  uint32_t size = 64;
  uint32_t batches = 32;
  uint32_t samplesPerBatch = 32;
  uint32_t block = 4;
  double alpha = 0.01;
  LightSamplerKind lightSampler = LightSamplerKind::Bvh;
};

struct BackendStatistics {
  PixelStatistics cpu, gpu;
};

// `cpuScene` on the CPU backend seeded `seed`, `gpuScene` on the OptiX one seeded `seed + 1`.
inline BackendStatistics renderOnBoth(const Scene& cpuScene, const Scene& gpuScene, uint32_t seed,
                                      const AgreementRun& run = {}) {
  RenderSettings cpu = squareImage(run.size, seed), gpu = squareImage(run.size, seed + 1);
  cpu.lightSampler = gpu.lightSampler = run.lightSampler;
  return {batchStatistics<CpuBackend>(cpuScene, cpu, run.batches, run.samplesPerBatch),
          batchStatistics<OptixBackend>(gpuScene, gpu, run.batches, run.samplesPerBatch)};
}

// Expects the two backends' renders of `scene` to agree.
inline void expectBackendsAgree(const Scene& scene, uint32_t seed, const AgreementRun& run = {}) {
  const BackendStatistics s = renderOnBoth(scene, scene, seed, run);
  expectRendersAgree(s.cpu, s.gpu, run.block, run.batches, run.alpha);
}

}  // namespace candela::test
