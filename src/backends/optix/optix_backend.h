#pragma once
#include <array>
#include <memory>
#include <vector>

#include "backends/backend.h"
#include "backends/optix/acceleration_statistics.h"

namespace candela {

struct RawTraceTiming {
  uint64_t raysPerFrame = 0;               // rays of the recorded sample, traced again by every timed launch
  std::vector<double> deviceMilliseconds;  // one per timed launch, from CUDA events
};

// The GPU backend: OptiX traversal (one GAS per mesh under one IAS), the shared kernel's path loop in the raygen
// program, progressive accumulation in device memory. Per launch only the launch parameters go up; the image
// comes down in readImage().
class OptixBackend final : public Backend {
 public:
  // Prints the GPU, driver, OptiX ABI and RT-core version on stderr. Throws std::runtime_error with one
  // sentence when there is no usable GPU (no CUDA device, no or too old a driver, no libnvoptix).
  OptixBackend();
  ~OptixBackend() override;

  std::string name() const override { return "optix"; }
  std::string deviceName() const override;
  // GPU, driver, OptiX ABI and RT-core version on one line.
  std::string deviceDescription() const;

  void setScene(const Scene& scene) override;
  bool setMaterials(const std::vector<Material>& materials) override;
  void setEnvironment(const Environment& environment) override;
  void setCamera(const Camera& camera) override;
  void setSettings(const RenderSettings& settings) override;

  // FrameStats::deviceMilliseconds holds the launches' GPU time from CUDA events.
  FrameStats render(uint32_t samplesPerPixel) override;
  uint32_t accumulatedSamples() const override;
  Image readImage() const override;
  Image readEmission() const override;
  void setAovsEnabled(bool enabled) override;
  bool aovsEnabled() const override;
  AovImages readAovs() const override;
  // The CUDA versions of the CPU filters, run on the film in device memory; only the result comes back.
  Image readAtrousDenoised(const AtrousParams& params) const override;
  Image readBilateralFiltered(const BilateralParams& params) const override;

  // For consumers on the same GPU (CUDA-OpenGL interop): the CUDA device's UUID (cudaDeviceProp::uuid), and
  // readImage's pixels written to `destination`, device memory of width * height Vec3, without leaving the GPU.
  std::array<unsigned char, 16> deviceUuid() const;
  void writeImageToDevice(Vec3* destination) const;

  // The traversal ceiling for this scene and ray mix: records every ray of one sample per pixel (the next
  // sample index; the image is left alone), then times `frames` launches, after `warmup` untimed ones, that
  // trace exactly those rays again, in the same order per pixel, with no shading.
  RawTraceTiming timeRawTrace(uint32_t warmup, uint32_t frames);

  // setScene keeps the GAS of every mesh whose triangles did not change (meshes with equal triangles share
  // one) and rebuilds the IAS only when an instance or a GAS changed; setMaterials rebuilds the GASes of meshes
  // on which a material started or stopped using alpha or culling back faces.
  AccelerationStatistics accelerationStatistics() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace candela
