#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "backends/multi/device_split.h"
#include "backends/multi/device_threads.h"
#include "backends/optix/optix_backend.h"

namespace candela {

// The OptiX backend on several GPUs of one machine, behind the one Backend interface: one OptixBackend (OptiX
// context, scene copy, pipelines, film) per listed device, driven by one host thread each (DeviceThreads).
//
// Scene, material, environment, camera and settings changes go to every device at once. Each render() call is
// shared by planShares: its sample indices where it has at least one per device (progressive renders), else
// the image's rows in bands (interactive frames of one sample); the shares follow the devices' speeds measured
// in the previous calls (DeviceBalance). Every random number is a function of the pixel, the sample index and
// the seed, so the devices together draw exactly the samples one would, and the image is one device's up to
// the order of the float additions.
//
// The first device is the display device: its film receives the others' sums (OptixBackend::moveFilmRows,
// peer to peer where the GPUs allow it) whenever the film is read, so that renders which read only at the end
// combine only then; every read (images, sums, AOVs, filters, deviceImage) is the first device's film.
class MultiGpuBackend final : public Backend, public DeviceImage {
 public:
  // `deviceIndices`: CUDA device indices, at least two; a repeat makes another context on the same GPU (which
  // tests the splitting and combining on a machine of one GPU). Throws std::runtime_error as OptixBackend does.
  // The devices start at once, each compiling its programs where OptiX's disk cache does not hold them yet; the
  // first device's compile reports to `compileProgress` (OptixBackend's constructor), the others keep pace.
  explicit MultiGpuBackend(const std::vector<int>& deviceIndices, ProgramCompileListener compileProgress = {});
  ~MultiGpuBackend() override;

  std::string name() const override { return "optix"; }
  // "2 x NVIDIA H200 (GPUs 0, 1; combined peer to peer)"
  std::string deviceName() const override;

  void setScene(const Scene& scene) override;
  void setInstanceTransforms(const Scene& scene) override;
  bool setMaterials(const std::vector<Material>& materials) override;
  void setEnvironment(const Environment& environment) override;
  void setCamera(const Camera& camera) override;
  void setSettings(const RenderSettings& settings) override;

  // FrameStats::deviceMilliseconds is the slowest device's GPU time; perDeviceMilliseconds holds each one's.
  FrameStats render(uint32_t samplesPerPixel) override;
  uint32_t accumulatedSamples() const override { return accumulated_; }
  void setNextSampleIndex(uint32_t index) override { nextSample_ = index; }
  FilmSums readFilm() const override;
  void loadFilm(const FilmSums& film) override;
  Image readImage() const override;
  Image readEmission() const override;
  void setAovsEnabled(bool enabled) override;
  bool aovsEnabled() const override;
  // Every GPU's, at the same time.
  double preparePrograms(ProgramWait wait = ProgramWait::NextFrame) override;
  AovImages readAovs() const override;
  // The first device's filters, on the combined film.
  const FilmFilters& filters() const override;
  // The first device's display frames, of the combined film; a temporal source must be a filter this backend's
  // filters().temporal() made.
  const FilmDisplay& display() const override;
  double lastCombineMilliseconds() const override { return combineMilliseconds_; }

  const DeviceImage* deviceImage() const override { return this; }
  std::array<unsigned char, 16> deviceUuid() const override;
  void writeImageToDevice(Vec3* destination) const override;

  // On the first device alone: the traversal ceiling is a property of one GPU.
  bool supportsRawTrace() const override { return true; }
  RawTraceTiming timeRawTrace(uint32_t warmup, uint32_t frames) override;

  size_t deviceCount() const { return devices_.size(); }
  // What each device rendered of the last render() call.
  const std::vector<DeviceShare>& lastShares() const { return lastShares_; }

 private:
  class CombinedFilmFilters;
  class CombinedFilmDisplay;
  // Runs `task` on every device at once, each on its thread with its device current.
  void onEveryDevice(const std::function<void(OptixBackend&)>& task);
  // A change every device made: the films start again.
  void restart();
  // Moves the rows the other devices rendered since the last merge into the first device's film.
  void mergeFilms() const;
  // Returns task(first device's backend) run after mergeFilms(), with the first device current.
  template <typename Task>
  auto onMergedFilm(Task&& task) const;

  struct RowRange {
    uint32_t first = 0, end = 0;  // empty when first == end
  };

  std::vector<int> ordinals_;
  DeviceThreads threads_;
  std::vector<std::unique_ptr<OptixBackend>> devices_;
  bool peerToPeer_ = true;  // every other device's memory is reachable from the first one's directly
  RenderSettings settings_;
  DeviceBalance balance_;
  std::vector<DeviceShare> lastShares_;
  uint32_t accumulated_ = 0, nextSample_ = 0;
  mutable std::vector<RowRange> unmerged_;  // per device: rows holding sums not yet in the first device's film
  mutable double combineMilliseconds_ = 0.0;
  std::unique_ptr<CombinedFilmFilters> filters_;
  std::unique_ptr<CombinedFilmDisplay> display_;
};

}  // namespace candela
