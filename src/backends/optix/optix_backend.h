#pragma once
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "backends/backend.h"
#include "backends/optix/acceleration_statistics.h"
#include "backends/optix/compile_progress.h"
#include "backends/path_schedule.h"

namespace candela {

// The GPU backend: OptiX traversal (one GAS per mesh under one IAS), the shared kernel's path loop in the raygen
// program, progressive accumulation in device memory. Per launch only the launch parameters go up; the image
// comes down in readImage().
class OptixBackend final : public Backend, public DeviceImage {
 public:
  // Prints the GPU, driver, OptiX ABI and RT-core version on stderr. Throws std::runtime_error with one
  // sentence when there is no usable GPU (no CUDA device, no or too old a driver, no libnvoptix). Takes CUDA
  // device `deviceIndex` modulo the devices there are. Compiles only the programs of what it renders
  // (backends/optix/program_use.h), from the moment it knows: those of a first frame of default settings at once,
  // the AOV path tracer's once AOVs are enabled, ReSTIR's once settings choose it, the raw trace's at
  // timeRawTrace. With ProgramStart::Wait it returns once the first frame's are compiled; with InBackground at
  // once (startingCompile() says how the compile goes), and after its first frame also compiles, at low priority,
  // the programs a control is likely to switch to; with AtFirstFrame it compiles nothing until the first frame
  // (or preparePrograms), which compiles what that frame needs, all at once. A launch waits for the programs it needs
  // (where the schedule is Auto's, the megakernel renders while the wavefront's compile: program_use.h,
  // pipelinesAwaited), and the destructor for every compile begun. `compileProgress` hears of these waits while they
  // last longer than a moment: a first start on the machine, when OptiX's disk cache does not hold the programs.
  explicit OptixBackend(int deviceIndex = 0, ProgramCompileListener compileProgress = {},
                        ProgramStart start = ProgramStart::Wait);
  ~OptixBackend() override;

  std::string name() const override { return "optix"; }
  std::string deviceName() const override;
  // GPU, driver, OptiX ABI and RT-core version on one line.
  std::string deviceDescription() const;

  void setScene(const Scene& scene) override;
  bool setMaterials(const std::vector<Material>& materials) override;
  void setEnvironment(const Environment& environment) override;
  // Keeps every GAS and the device copy of the scene: uploads the instance records and light tables again and
  // builds the IAS over the new transforms (AccelerationStructures::updateInstanceTransforms).
  void setInstanceTransforms(const Scene& scene) override;
  void setCamera(const Camera& camera) override;
  void setSettings(const RenderSettings& settings) override;

  // FrameStats::deviceMilliseconds holds the launches' GPU time from CUDA events.
  FrameStats render(uint32_t samplesPerPixel) override;
  // How renders without AOVs organise their launches (backends/path_schedule.h; renders with AOVs always use the
  // megakernel). The default is CANDELA_GPU_SCHEDULE's, else auto.
  void setPathSchedule(PathSchedule schedule);
  // The wavefront follows the paths left to their ends in one launch once at most `paths` are left (0: never);
  // the default suits the device (backends/optix/wavefront_schedule.h). For tests and measurements.
  void setWavefrontTailPaths(uint32_t paths);
  // The schedule in use and, for auto, why.
  std::string pathScheduleDescription() const;
  uint32_t accumulatedSamples() const override;
  void setNextSampleIndex(uint32_t index) override;
  FilmSums readFilm() const override;
  void loadFilm(const FilmSums& film) override;
  Image readImage() const override;
  Image readEmission() const override;
  void setAovsEnabled(bool enabled) override;
  bool aovsEnabled() const override;
  // The compile of the programs the next frame needs, while it runs.
  std::optional<ProgramCompileStatus> startingCompile() const override;
  double preparePrograms(ProgramWait wait = ProgramWait::NextFrame) override;
  AovImages readAovs() const override;
  // The CUDA versions of the CPU filters, run on the film in device memory; only the result comes back.
  // The CUDA version of the temporal filter, its history kept in device memory; only the result comes back.
  const FilmFilters& filters() const override;
  // Display frames made on the GPU from the film or the CUDA filters' output; only the 8-bit pixels come back.
  // A temporal source must be a filter this backend's filters().temporal() made.
  const FilmDisplay& display() const override;

  // The image stays on the GPU for consumers there (CUDA-OpenGL interop).
  const DeviceImage* deviceImage() const override { return this; }
  std::array<unsigned char, 16> deviceUuid() const override;
  void writeImageToDevice(Vec3* destination) const override;

  // Traces the recorded rays again in the same order per pixel.
  bool supportsRawTrace() const override { return true; }
  RawTraceTiming timeRawTrace(uint32_t warmup, uint32_t frames) override;

  // For a backend that shares the image between several (MultiGpuBackend): render() on the rows
  // [firstRow, firstRow + rows) only, whose pixels take the samples while the others keep theirs; and adding the
  // film sums of `source`, a backend of the same settings and AOVs on this GPU or another, in the rows
  // [firstRow, firstRow + rows) to this one's, clearing them there, so that those samples move rather than count
  // twice. renderRows counts its samples in accumulatedSamples() as render() does; moveFilmRows changes no count.
  FrameStats renderRows(uint32_t samplesPerPixel, uint32_t firstRow, uint32_t rows);
  void moveFilmRows(OptixBackend& source, uint32_t firstRow, uint32_t rows);
  // The CUDA device the backend renders on.
  int deviceOrdinal() const;

  // setScene keeps the GAS of every mesh whose triangles did not change (meshes with equal triangles share
  // one) and rebuilds the IAS only when an instance or a GAS changed; setMaterials rebuilds the GASes of meshes
  // on which a material started or stopped using alpha or culling back faces.
  AccelerationStatistics accelerationStatistics() const;

 private:
  class DeviceTemporalDenoiser;
  class DeviceFilmFilters;
  class DeviceFilmDisplay;
  struct State;
  std::unique_ptr<State> state_;
  std::unique_ptr<DeviceFilmFilters> filters_;
  std::unique_ptr<DeviceFilmDisplay> display_;
};

}  // namespace candela
