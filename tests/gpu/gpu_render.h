#pragma once
// Set-up shared by the GPU tests: a backend of either kind with a scene, square image and settings.
#include <memory>

#include "backends/cpu/cpu_backend.h"
#include "backends/optix/optix_backend.h"
#include "scene/builtin_scenes.h"
#include "support/render_statistics.h"

namespace candela::test {

template <class BackendType>
std::unique_ptr<BackendType> makeBackend(const Scene& scene, const RenderSettings& settings) {
  auto backend = std::make_unique<BackendType>();
  backend->setScene(scene);
  backend->setSettings(settings);
  backend->setCamera(scene.camera.toCamera(float(settings.width) / float(settings.height)));
  return backend;
}

inline RenderSettings squareImage(uint32_t size, uint32_t seed) {
  RenderSettings settings;
  settings.width = settings.height = size;
  settings.seed = seed;
  return settings;
}

template <class BackendType>
PixelStatistics batchStatistics(const Scene& scene, const RenderSettings& settings, uint32_t batches,
                                uint32_t samplesPerBatch) {
  auto backend = makeBackend<BackendType>(scene, settings);
  return renderBatches(*backend, batches, samplesPerBatch);
}

}  // namespace candela::test
