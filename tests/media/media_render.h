#pragma once
// The CPU renders of tests/media: batches of samples of a scene through participating media, deep enough that
// long random walks are not cut short.
#include "backends/cpu/cpu_backend.h"
#include "support/render_statistics.h"

namespace candela::test {

constexpr uint32_t kMediaBatches = 32;
constexpr uint32_t kMediaSamplesPerBatch = 8;

// kMediaBatches batches of kMediaSamplesPerBatch samples of `scene` at size x size pixels, seeded by `seed`.
inline PixelStatistics renderMediaScene(const Scene& scene, uint32_t size, uint32_t seed,
                                        SamplerKind sampler = SamplerKind::Independent) {
  CpuBackend backend;
  backend.setScene(scene);
  RenderSettings settings;
  settings.sampler = sampler;
  settings.width = settings.height = size;
  settings.maxDepth = 1000;
  settings.rouletteDepth = 1;
  settings.seed = seed;
  backend.setSettings(settings);
  backend.setCamera(scene.camera.toCamera(1.0f));
  return renderBatches(backend, kMediaBatches, kMediaSamplesPerBatch);
}

}  // namespace candela::test
