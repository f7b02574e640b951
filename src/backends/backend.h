#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "image/image.h"
#include "kernel/camera.h"
#include "kernel/render_settings.h"
#include "scene/scene.h"

namespace candela {

struct FrameStats {
  uint64_t rays = 0;            // camera, bounce and shadow rays traced
  uint64_t invalidSamples = 0;  // NaN/Inf/negative path estimates dropped before the film
  double deviceMilliseconds = 0.0;  // GPU time of the launches (CUDA events); 0 where the backend has none
};

// A renderer of one scene: owns traversal structures, memory and launches; shading is the shared kernel code.
// Every render() call adds samples to a progressive film; changing the camera or the settings restarts it.
class Backend {
 public:
  virtual ~Backend() = default;

  virtual std::string name() const = 0;        // "cpu", "optix"
  virtual std::string deviceName() const = 0;  // the processor or GPU that runs it

  virtual void setScene(const Scene& scene) = 0;
  // Cheap edits of the scene last set, for interactive controls: the traversal structures stay, the film
  // restarts. setMaterials returns false, changing nothing, when the change needs setScene instead (see
  // FlatScene::replaceMaterials: a different count, emission, or a material newly needing tangents).
  virtual bool setMaterials(const std::vector<Material>& materials) = 0;
  virtual void setEnvironment(const Environment& environment) = 0;
  virtual void setCamera(const Camera& camera) = 0;
  virtual void setSettings(const RenderSettings& settings) = 0;

  // Adds `samplesPerPixel` samples to every pixel.
  virtual FrameStats render(uint32_t samplesPerPixel) = 0;
  virtual uint32_t accumulatedSamples() const = 0;
  // The mean of the accumulated samples.
  virtual Image readImage() const = 0;
};

}  // namespace candela
