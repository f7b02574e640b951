#include "backends/optix/optix_backend.h"

#include <optix.h>
#include <optix_stubs.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "backends/film_display.h"
#include "backends/film_filters.h"
#include "backends/optix/acceleration.h"
#include "backends/optix/compile_progress_reporter.h"
#include "backends/optix/cuda_devices.h"
#include "backends/optix/device_display.h"
#include "backends/optix/device_film.h"
#include "backends/optix/device_restir_buffers.h"
#include "backends/optix/device_scene.h"
#include "backends/optix/film_addition.h"
#include "backends/optix/filters/cuda_filters.h"
#include "backends/optix/filters/cuda_temporal.h"
#include "backends/optix/launch_params.h"
#include "backends/optix/mean_image.h"
#include "backends/optix/optix_context.h"
#include "backends/optix/optix_error.h"
#include "backends/optix/pipeline.h"
#include "backends/optix/pixel_counters.h"
#include "backends/optix/program_modules.h"
#include "backends/optix/program_use.h"
#include "backends/optix/wavefront_schedule.h"
#include "backends/path_schedule.h"
#include "scene/flat_scene.h"

namespace candela {

using namespace optix;

namespace {

// Rays one path sample can trace: a closest-hit and a shadow ray per bounce, with margin for kernel growth.
uint32_t rayBoundPerSample(const RenderSettings& settings) { return 4 * (settings.maxDepth + 1); }

class CudaEvent {
 public:
  CudaEvent() { checkCuda(cudaEventCreate(&event_), "creating a CUDA event"); }
  ~CudaEvent() { cudaEventDestroy(event_); }
  CudaEvent(const CudaEvent&) = delete;
  CudaEvent& operator=(const CudaEvent&) = delete;
  cudaEvent_t get() const { return event_; }

 private:
  cudaEvent_t event_ = nullptr;
};

// CANDELA_GPU_SCHEDULE: auto (the default), megakernel or wavefront (backends/path_schedule.h).
PathSchedule requestedSchedule() {
  const char* text = std::getenv("CANDELA_GPU_SCHEDULE");
  if (!text) return PathSchedule::Auto;
  if (std::optional<PathSchedule> schedule = parsePathSchedule(text)) return *schedule;
  std::fprintf(stderr, "optix: CANDELA_GPU_SCHEDULE=%s is none of auto, megakernel, wavefront; using auto\n", text);
  return PathSchedule::Auto;
}

struct LaunchResult {
  CounterTotals totals{};
  float milliseconds = 0.0f;
};

}  // namespace

struct OptixBackend::State {
  State(int deviceIndex, ProgramCompileListener listener, ProgramStart programs)
      : context(deviceIndex),
        compileListener(std::move(listener)),
        programStart(programs),
        startDeferred(programs == ProgramStart::AtFirstFrame) {}

  OptixContext context;
  ProgramCompileListener compileListener;
  ProgramStart programStart;
  // ProgramStart::AtFirstFrame before the first frame: what it renders may still change, so nothing compiles yet.
  bool startDeferred;
  // Each compiled once something needs it (startNeeded), in the background.
  ProgramModules modules{context.get()};
  // Made when first needed (makePipelines): of the full kernel's modules, then of the lean kernel's (pipelineSlot).
  std::array<std::unique_ptr<Pipeline>, 2 * kPipelineKinds> pipelines;
  FlatScene flat;
  DeviceScene scene;
  AccelerationStructures acceleration;
  bool hasScene = false;
  // The scene needs only the lean kernel (program_use.h): so the modules compiled before a scene is set assume.
  bool leanKernel = true;
  Camera camera;
  RenderSettings settings;

  bool aovsEnabled = false;
  DeviceFilm film;
  DeviceFilm incoming;                 // another device's film rows on their way into this one (moveFilmRows)
  std::unique_ptr<CudaAtrous> atrous;  // made at the first a-trous read, for the image's size
  DeviceBuffer filtered;               // the filters' output
  DeviceBuffer smoothed;               // the display frames' smoothing pass's output
  DeviceBuffer emissionMeans;          // the film's emission as means, for smoothing a filter's output
  DeviceDisplay display;
  DeviceBuffer counters;
  DeviceBuffer totals{sizeof(CounterTotals), "the counter totals"};
  DeviceBuffer parameters{sizeof(LaunchParameters), "the launch parameters"};
  CudaEvent start, stop;
  uint32_t accumulated = 0;
  uint32_t nextSample = 0;
  WavefrontSchedule wavefront;
  DeviceRestirBuffers restir;
  PathScheduleChoice schedule{requestedSchedule()};
  std::string reportedSchedule;
  std::optional<std::pair<PathScheduleChoice, bool>> reported;  // the choice and stand-in of reportedSchedule

  uint32_t pixelCount() const { return settings.width * settings.height; }

  LaunchParameters baseParameters() const {
    LaunchParameters p;
    p.scene = scene.view();
    p.camera = camera;
    p.settings = settings;
    p.traversable = acceleration.topLevel();
    p.batchInstances = acceleration.batchInstances();
    p.firstBatchId = acceleration.firstBatchId();
    p.film = film.view();
    p.counters = counters.as<PixelCounters>();
    return p;
  }

  // Runs `work`, which waits for the modules `compiling`, telling the listener how their compile goes where that
  // takes longer than a moment.
  template <class Work>
  void whileCompiling(const std::vector<ProgramModule>& compiling, const Work& work) {
    ProgramCompileProgress about;
    about.gpuName = context.info().name;
    about.cacheDirectory = context.cacheDirectory();
    CompileProgressReporter reporter(compileListener, about, [&] { return modules.tasks(compiling); });
    work();
    reporter.finish();
  }

  // The pipeline of `kind` for the scene's kernel, lean or full.
  size_t pipelineIndex(PipelineKind kind) const { return size_t(kind) + (leanKernel ? kPipelineKinds : 0); }
  std::unique_ptr<Pipeline>& pipelineSlot(PipelineKind kind) { return pipelines[pipelineIndex(kind)]; }

  // Makes the pipelines of `kinds` not made yet, once their modules are compiled.
  void makePipelines(const std::vector<PipelineKind>& kinds) {
    whileCompiling(modulesOf(kinds, leanKernel), [&] {
      for (PipelineKind kind : kinds)
        if (!pipelineSlot(kind))
          pipelineSlot(kind) = std::make_unique<Pipeline>(context.get(), modules, pipelinePrograms(kind), leanKernel);
    });
  }

  // What the next frame renders, and so which pipelines it launches (program_use.h).
  ProgramUse use() const {
    return {schedule.decided() ? schedule.next() : PathSchedule::Auto, aovsEnabled, settings.restir != RestirMode::Off,
            !flat.media.empty(), schedule.requested() == PathSchedule::Auto};
  }
  std::vector<ProgramModule> neededModules() const { return modulesOf(pipelinesNeeded(use()), leanKernel); }
  std::vector<ProgramModule> awaitedModules() const { return modulesOf(pipelinesAwaited(use()), leanKernel); }

  // Begins compiling the modules the next frame needs, where they have not begun: called wherever what it renders
  // may have changed, so that the compile runs while the caller sets up the rest (or renders on the CPU).
  void startNeeded() {
    if (startDeferred) return;
    for (ProgramModule module : neededModules()) modules.start(module, CompilePriority::Needed);
  }

  // Compiles the modules of the next frame's pipelines (or of every frame's), all at once (each pipeline waits for
  // its own, one after the other), and makes the pipelines.
  void preparePrograms(ProgramWait wait) {
    startDeferred = false;
    startNeeded();
    makePipelines(wait == ProgramWait::EveryFrame ? pipelinesNeeded(use()) : pipelinesAwaited(use()));
  }

  // An interactive session (ProgramStart::InBackground) also compiles, after its first frame on the GPU, the
  // modules of what a control is likely to switch to, at low priority, so that the switch does not wait long.
  void prefetchLikely() {
    if (programStart != ProgramStart::InBackground) return;
    for (ProgramModule module : modulesOf(pipelinesLikely(use()), leanKernel))
      modules.start(module, CompilePriority::Prefetch);
  }

  // Waits for the compiles that have begun, which cannot be cancelled (OptiX destroys no module while its tasks
  // run); a finished module is in OptiX's disk cache, so that the next start need not compile it.
  void finishCompiles() {
    const std::vector<ProgramModule> begun = modules.startedModules();
    whileCompiling(begun, [&] {
      for (ProgramModule module : begun) modules.get(module);
    });
  }

  const Pipeline& pipeline(RaygenProgram program) {
    const PipelineKind kind = pipelineLaunching(program);
    if (!pipelineSlot(kind)) makePipelines({kind});
    return *pipelineSlot(kind);
  }

  // Uploads the parameters, launches one raygen program over `rows` rows of the image from p.firstRow on and
  // sums their counters, timing both with CUDA events; waits for the result.
  LaunchResult launch(RaygenProgram program, const LaunchParameters& p, uint32_t rows) {
    cudaStream_t stream = context.stream();
    const Pipeline& pipe = pipeline(program);
    checkCuda(cudaMemcpyAsync(parameters.as<void>(), &p, sizeof p, cudaMemcpyHostToDevice, stream),
              "uploading the launch parameters");
    return timed(p, rows, [&] {
      checkOptix(optixLaunch(pipe.get(), stream, parameters.address(), sizeof p, &pipe.bindingTable(program),
                             settings.width, rows, 1),
                 "launching the device programs");
    });
  }

  // One sample per pixel of `rows` rows from p.firstRow on through the wavefront schedule, timed as launch().
  LaunchResult launchWavefront(const LaunchParameters& p, uint32_t rows) {
    return timed(p, rows, [&] {
      wavefront.enqueueSample(pipeline(RaygenProgram::PathTrace), context.stream(), p, settings.width, rows,
                              settings.maxDepth);
    });
  }

  // Runs `enqueue`, which leaves per-pixel counters for `rows` rows from p.firstRow on, and sums the counters,
  // timing both with CUDA events; waits for the result.
  template <class Enqueue>
  LaunchResult timed(const LaunchParameters& p, uint32_t rows, const Enqueue& enqueue) {
    cudaStream_t stream = context.stream();
    checkCuda(cudaEventRecord(start.get(), stream), "recording a CUDA event");
    enqueue();
    sumPixelCounters(counters.as<PixelCounters>() + size_t(p.firstRow) * settings.width, rows * settings.width,
                     totals.as<CounterTotals>(), stream);
    checkCuda(cudaEventRecord(stop.get(), stream), "recording a CUDA event");
    LaunchResult result;
    checkCuda(cudaMemcpyAsync(&result.totals, totals.as<void>(), sizeof result.totals, cudaMemcpyDeviceToHost, stream),
              "reading the launch's counters");
    checkCuda(cudaStreamSynchronize(stream), "running the device programs");
    checkCuda(cudaEventElapsedTime(&result.milliseconds, start.get(), stop.get()), "reading a CUDA event");
    return result;
  }

  // Samples p.firstSample on (p.samplesPerPixel of them) without AOVs, by the schedule of the choice; the
  // wavefront takes one sample per sequence of launches, and sets p.samplesPerPixel to 1.
  LaunchResult launchPaths(LaunchParameters& p, uint32_t rows) {
    if (!schedule.decided()) probeSchedule();
    startNeeded();  // the schedule decided may need another pipeline than the probe's
    const bool standIn = schedule.next() == PathSchedule::Wavefront && !wavefrontCompiled();
    report(standIn);
    if (standIn) return launch(RaygenProgram::Render, p, rows);
    if (schedule.next() == PathSchedule::Wavefront) {
      try {
        wavefront.reserve(size_t(settings.width) * rows);
      } catch (const std::runtime_error& e) {  // out of device memory
        if (schedule.requested() == PathSchedule::Wavefront) throw;
        schedule.wavefrontUnavailable();
        std::fprintf(stderr, "optix: %s\n", e.what());
        report();
      }
    }
    if (schedule.next() == PathSchedule::Wavefront) {
      p.samplesPerPixel = 1;
      return launchWavefront(p, rows);
    }
    return launch(RaygenProgram::Render, p, rows);
  }

  // Auto's probe (backends/path_schedule.h): sample 0 of every pixel by the megakernel, into a film of its own.
  void probeSchedule() {
    DeviceFilm probeFilm;
    probeFilm.resize(settings.width, settings.height, false);
    probeFilm.clear(context.stream());
    LaunchParameters p = baseParameters();
    p.film = probeFilm.view();
    p.firstSample = 0;
    p.samplesPerPixel = 1;
    const LaunchResult r = launch(RaygenProgram::Render, p, settings.height);
    schedule.decide(double(r.totals.rays) / double(pixelCount()));
    report();
  }

  // Whether the wavefront can launch without waiting, or must, where it was requested rather than Auto's choice.
  bool wavefrontCompiled() const {
    if (schedule.requested() == PathSchedule::Wavefront || pipelines[pipelineIndex(PipelineKind::Wavefront)])
      return true;
    return modules.finished(modulesOf({PipelineKind::Wavefront}, leanKernel));
  }

  // Says which schedule renders, when that changed; `standIn`: the megakernel renders while the wavefront that Auto
  // chose compiles.
  // The line is made only when the choice or the stand-in changed, not at every launch.
  void report(bool standIn = false) {
    if (reported && reported->first == schedule && reported->second == standIn) return;
    const std::string line =
        schedule.describe() + (standIn ? "; the megakernel renders until the wavefront's programs have compiled" : "");
    if (line != reportedSchedule) std::fprintf(stderr, "optix: %s\n", line.c_str());
    reportedSchedule = line;
    reported.emplace(schedule, standIn);
  }

  // The film and the per-pixel counters for the current size; the film with AOV sums while they are enabled.
  void allocateFilm() {
    film.resize(settings.width, settings.height, aovsEnabled);
    const size_t counterBytes = size_t(pixelCount()) * sizeof(PixelCounters);
    if (counters.size() != counterBytes) {
      counters = DeviceBuffer();
      counters = DeviceBuffer(counterBytes, "the per-pixel counters");
    }
  }

  // Restarts the film; ReSTIR's history survives only a camera move, which its temporal reuse follows.
  void restart(bool keepRestirHistory = false) {
    accumulated = 0;
    nextSample = 0;
    film.clear(context.stream());
    if (!keepRestirHistory) restir.dropHistory();
  }

  // One sample per pixel of the whole image by ReSTIR DI's four launches (kernel/restir/restir_passes.h), sample
  // index `sample`; the wavefront schedule does not run them.
  LaunchResult launchRestir(uint32_t sample) {
    LaunchParameters p = baseParameters();
    p.restir = restir.view(accumulated == 0);
    p.firstSample = sample;
    p.samplesPerPixel = 1;
    LaunchResult total;
    for (RaygenProgram program :
         {RaygenProgram::RestirPrimary, RaygenProgram::RestirPresample, RaygenProgram::RestirCandidates,
          aovsEnabled ? RaygenProgram::RestirShadeWithAovs : RaygenProgram::RestirShade}) {
      const LaunchResult r = launch(program, p, settings.height);
      total.totals.rays += r.totals.rays;
      total.totals.invalidSamples += r.totals.invalidSamples;
      total.milliseconds += r.milliseconds;
    }
    restir.endSample(camera);
    return total;
  }

  Vec3* filterOutput() {
    const size_t bytes = size_t(pixelCount()) * sizeof(Vec3);
    if (filtered.size() != bytes) {
      filtered = DeviceBuffer();
      filtered = DeviceBuffer(bytes, "the filtered image");
    }
    return filtered.as<Vec3>();
  }

  // The a-trous and bilateral filters of the film, enqueued: their result is in filterOutput().
  Vec3* enqueueAtrous(const AtrousParams& params) {
    if (!aovsEnabled) throw std::logic_error("the a-trous filter without setAovsEnabled(true)");
    validateAtrousParams(params);
    if (!atrous || atrous->width() != settings.width || atrous->height() != settings.height) {
      atrous.reset();
      atrous = std::make_unique<CudaAtrous>(settings.width, settings.height);
    }
    atrous->run(film.view(), nullptr, nullptr, filterOutput(), params, context.stream());
    return filterOutput();
  }

  Vec3* enqueueBilateral(const BilateralParams& params) {
    if (!aovsEnabled) throw std::logic_error("the bilateral filter without setAovsEnabled(true)");
    validateBilateralParams(params);
    cudaBilateral(film.view(), filterOutput(), settings.width, settings.height, params, context.stream());
    return filterOutput();
  }

  // An image of the film's size in `buffer`, (re)made when the size changed.
  Vec3* imageBuffer(DeviceBuffer& buffer, const char* what) {
    const size_t bytes = size_t(pixelCount()) * sizeof(Vec3);
    if (buffer.size() != bytes) {
      buffer = DeviceBuffer();
      buffer = DeviceBuffer(bytes, what);
    }
    return buffer.as<Vec3>();
  }
  Vec3* smoothingOutput() { return imageBuffer(smoothed, "the smoothed image"); }
  Vec3* emissionMeansOutput() { return imageBuffer(emissionMeans, "the emission's means"); }

  Image downloadFiltered() const {
    Image image(settings.width, settings.height);
    checkCuda(cudaStreamSynchronize(context.stream()), "filtering the image");
    filtered.download(image.pixels.data(), image.pixels.size() * sizeof(Vec3));
    return image;
  }
};

// The temporal filter on the backend's film in device memory.
class OptixBackend::DeviceTemporalDenoiser : public TemporalDenoiser {
 public:
  DeviceTemporalDenoiser(const OptixBackend& backend, const TemporalParams& params)
      : backend_(backend), filter_(params) {}
  Image denoise(const Camera& camera, bool filmContinues) override {
    enqueue(camera, filmContinues);
    return backend_.state_->downloadFiltered();
  }
  void reset() override { filter_.reset(); }
  const TemporalParams& params() const override { return filter_.params(); }

  // The filter enqueued: its result is in the backend's State::filterOutput().
  Vec3* enqueue(const Camera& camera, bool filmContinues) {
    State& s = *backend_.state_;
    if (!s.aovsEnabled) throw std::logic_error("the temporal filter without setAovsEnabled(true)");
    filter_.run(s.film.view(), s.settings.width, s.settings.height, camera, s.accumulated, filmContinues,
                s.filterOutput(), s.context.stream());
    return s.filterOutput();
  }
  const OptixBackend& backend() const { return backend_; }

 private:
  const OptixBackend& backend_;
  CudaTemporal filter_;
};

// The CUDA filters on the film in device memory; only their result is read back.
class OptixBackend::DeviceFilmFilters final : public FilmFilters {
 public:
  explicit DeviceFilmFilters(const OptixBackend& backend) : backend_(backend) {}

  Image atrous(const AtrousParams& params) const override {
    backend_.state_->enqueueAtrous(params);
    return backend_.state_->downloadFiltered();
  }

  Image bilateral(const BilateralParams& params) const override {
    backend_.state_->enqueueBilateral(params);
    return backend_.state_->downloadFiltered();
  }

  std::unique_ptr<TemporalDenoiser> temporal(const TemporalParams& params) const override {
    return std::make_unique<DeviceTemporalDenoiser>(backend_, params);
  }

 private:
  const OptixBackend& backend_;
};

// Display frames of the film, or of a filter's output, made on the device (DeviceDisplay).
class OptixBackend::DeviceFilmDisplay final : public FilmDisplay {
 public:
  explicit DeviceFilmDisplay(const OptixBackend& backend) : backend_(backend) {}

  DisplayFrame read(const DisplayRequest& request) const override {
    const auto start = std::chrono::steady_clock::now();
    State& s = *backend_.state_;
    displaySize(s.settings.width, s.settings.height, request.divisor);  // refuses a divisor before any filter runs
    if (request.smoothing) validateBilateralParams(*request.smoothing);
    const bool filtered = !std::holds_alternative<AccumulatedImage>(request.source) || request.smoothing;
    DisplayFrame frame = s.display.read([&] { return enqueueSource(s, request); }, filtered, request.display,
                                        request.divisor, s.context.stream());
    frame.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return frame;
  }

 private:
  // Enqueues the request's filter and smoothing; returns where their result (or the film) is.
  LinearPixels enqueueSource(State& s, const DisplayRequest& request) const {
    const FilmView film = s.film.view();
    Vec3* values = film.radiance;
    uint32_t* samples = film.samples;
    if (const auto* atrous = std::get_if<AtrousFiltered>(&request.source)) values = s.enqueueAtrous(atrous->params);
    if (const auto* bilateral = std::get_if<BilateralFiltered>(&request.source))
      values = s.enqueueBilateral(bilateral->params);
    if (const auto* temporal = std::get_if<TemporalFiltered>(&request.source)) {
      auto* denoiser = dynamic_cast<DeviceTemporalDenoiser*>(temporal->denoiser);
      if (!denoiser || &denoiser->backend() != &backend_)
        throw std::invalid_argument("a display frame through a temporal filter of another backend");
      values = denoiser->enqueue(temporal->camera, temporal->filmContinues);
    }
    if (values != film.radiance) samples = nullptr;  // a filter's output: means
    if (request.smoothing) {
      FilmView image;  // the source, with the film's emission kept apart where the film records it
      image.radiance = values;
      image.samples = samples;
      if (s.aovsEnabled && samples) {
        image.emission = film.emission;  // sums over the same counts as the source's
      } else if (s.aovsEnabled) {
        image.emission = s.emissionMeansOutput();  // beside a filter's means, the emission's means
        cudaMeans(film.emission, film.samples, image.emission, s.pixelCount(), s.context.stream());
      }
      cudaBilateral(image, s.smoothingOutput(), s.settings.width, s.settings.height, *request.smoothing,
                    s.context.stream());
      values = s.smoothingOutput();
      samples = nullptr;
    }
    return {values, samples, s.settings.width, s.settings.height};
  }

  const OptixBackend& backend_;
};

OptixBackend::OptixBackend(int deviceIndex, ProgramCompileListener compileProgress, ProgramStart start)
    : state_(std::make_unique<State>(deviceIndex, std::move(compileProgress), start)),
      filters_(std::make_unique<DeviceFilmFilters>(*this)),
      display_(std::make_unique<DeviceFilmDisplay>(*this)) {
  std::fprintf(stderr, "optix: %s\n", deviceDescription().c_str());
  setSettings(RenderSettings{});  // begins compiling the modules of a first frame of these settings
  if (start == ProgramStart::Wait) state_->preparePrograms(ProgramWait::NextFrame);
}

OptixBackend::~OptixBackend() {
  try {
    state_->finishCompiles();
  } catch (const std::exception&) {  // a module that did not compile, which no launch used
  }
}

std::string OptixBackend::deviceName() const { return state_->context.info().name; }

std::string OptixBackend::deviceDescription() const { return state_->context.describe(); }

void OptixBackend::setScene(const Scene& scene) {
  State& s = *state_;
  s.hasScene = false;
  FlatScene flat = FlatScene::build(scene);
  // OptiX's curves are round: flat and ribbon curves have no primitive of their own there (docs/design.md).
  for (const CurveSegment& segment : flat.curveSegments)
    if (segment.type != CurveType::Cylinder)
      throw SceneUnsupported("flat and ribbon curves are rendered by the CPU backend only (--backend cpu or auto)");
  s.scene.upload(flat);
  // s.flat is the scene of the structures' last update until this one succeeds.
  s.acceleration.update(s.context.get(), s.context.stream(), &s.flat, flat, s.scene.view());
  s.flat = std::move(flat);
  s.leanKernel = leanKernelSuffices(s.flat);
  s.hasScene = true;
  s.schedule.reset();
  s.startNeeded();
  s.restart();
}

bool OptixBackend::setMaterials(const std::vector<Material>& materials) {
  State& s = *state_;
  if (!s.hasScene || materials.size() != s.flat.materials.size()) return false;
  bool cutoutsChange = false;
  for (size_t i = 0; i < materials.size(); ++i)
    cutoutsChange = cutoutsChange || materialSbtIndex(materials[i]) != materialSbtIndex(s.flat.materials[i]);
  if (!s.flat.replaceMaterials(materials)) return false;
  s.scene.updateMaterials(s.flat);
  s.leanKernel = leanKernelSuffices(s.flat);
  s.startNeeded();
  if (cutoutsChange) s.acceleration.update(s.context.get(), s.context.stream(), &s.flat, s.flat, s.scene.view());
  s.restart();
  return true;
}

void OptixBackend::setEnvironment(const Environment& environment) {
  State& s = *state_;
  if (!s.hasScene) throw std::logic_error("OptixBackend::setEnvironment before setScene");
  s.flat.replaceEnvironment(environment);
  s.scene.updateEnvironment(s.flat);
  s.restart();
}

void OptixBackend::setInstanceTransforms(const Scene& scene) {
  State& s = *state_;
  if (!s.hasScene || !s.flat.replaceInstanceTransforms(scene)) return setScene(scene);
  s.hasScene = false;  // until the structures match the new transforms
  s.scene.updateInstances(s.flat);
  s.acceleration.updateInstanceTransforms(s.context.get(), s.context.stream(), s.flat, s.scene.view());
  s.hasScene = true;
  s.restart();
}

void OptixBackend::setCamera(const Camera& camera) {
  state_->camera = camera;
  state_->restart(/*keepRestirHistory=*/true);
}

void OptixBackend::setSettings(const RenderSettings& settings) {
  State& s = *state_;
  if (settings.restir != RestirMode::Off && s.schedule.requested() == PathSchedule::Wavefront)
    throw std::invalid_argument(
        "--restir runs in the megakernel schedule only: unset CANDELA_GPU_SCHEDULE=wavefront, or use --restir off");
  s.settings = settings;
  s.allocateFilm();
  if (settings.restir != RestirMode::Off) {
    s.restir.reset(settings.width, settings.height);
  } else {
    s.restir.reset(0, 0);
  }
  s.schedule.reset();
  s.startNeeded();
  s.restart();
}

FrameStats OptixBackend::render(uint32_t samplesPerPixel) {
  return renderRows(samplesPerPixel, 0, state_->settings.height);
}

FrameStats OptixBackend::renderRows(uint32_t samplesPerPixel, uint32_t firstRow, uint32_t rows) {
  State& s = *state_;
  if (!s.hasScene) throw std::logic_error("OptixBackend::render before setScene");
  if (size_t(firstRow) + rows > s.settings.height) throw std::logic_error("OptixBackend::renderRows past the image");
  if (rows == 0) return {};
  if (s.startDeferred) s.preparePrograms(ProgramWait::NextFrame);
  // Per-pixel ray counts are 32-bit: long requests are split into launches that cannot overflow them.
  const uint32_t maxPerLaunch = std::max(1u, 0xFFFFFFFFu / rayBoundPerSample(s.settings));
  FrameStats stats;
  // Scenes with participating media render on a megakernel of their own (device/media_programs.cu).
  const bool media = !s.flat.media.empty();
  if (media && s.settings.restir != RestirMode::Off)
    throw std::invalid_argument("--restir does not render participating media: use --restir off");
  if (media && s.schedule.requested() == PathSchedule::Wavefront)
    throw std::invalid_argument(
        "the wavefront schedule does not render participating media: unset CANDELA_GPU_SCHEDULE=wavefront");
  if (s.settings.restir != RestirMode::Off) {
    // Spatial reuse reads the neighbours' reservoirs of the same launch: a band of rows would read rows no launch
    // of this device wrote.
    if (firstRow != 0 || rows != s.settings.height)
      throw std::invalid_argument("--restir renders whole images: on several GPUs it needs a sample per GPU per call");
    for (uint32_t i = 0; i < samplesPerPixel; ++i) {
      const LaunchResult r = s.launchRestir(s.nextSample);
      stats.rays += r.totals.rays;
      stats.invalidSamples += r.totals.invalidSamples;
      stats.deviceMilliseconds += r.milliseconds;
      ++s.accumulated;
      ++s.nextSample;
    }
    s.prefetchLikely();
    return stats;
  }
  for (uint32_t done = 0; done < samplesPerPixel;) {
    LaunchParameters p = s.baseParameters();
    p.firstSample = s.nextSample;
    p.samplesPerPixel = std::min(samplesPerPixel - done, maxPerLaunch);
    p.firstRow = firstRow;
    LaunchResult r =
        media ? s.launch(s.aovsEnabled ? RaygenProgram::RenderMediaWithAovs : RaygenProgram::RenderMedia, p, rows)
        : s.aovsEnabled ? s.launch(RaygenProgram::RenderWithAovs, p, rows)
                        : s.launchPaths(p, rows);
    stats.rays += r.totals.rays;
    stats.invalidSamples += r.totals.invalidSamples;
    stats.deviceMilliseconds += r.milliseconds;
    s.accumulated += p.samplesPerPixel;
    s.nextSample += p.samplesPerPixel;
    done += p.samplesPerPixel;
  }
  s.prefetchLikely();
  return stats;
}

void OptixBackend::setPathSchedule(PathSchedule schedule) {
  state_->schedule.request(schedule);
  state_->startNeeded();
}

void OptixBackend::setWavefrontTailPaths(uint32_t paths) { state_->wavefront.setTailPaths(paths); }

std::string OptixBackend::pathScheduleDescription() const { return state_->schedule.describe(); }

uint32_t OptixBackend::accumulatedSamples() const { return state_->accumulated; }

void OptixBackend::setNextSampleIndex(uint32_t index) { state_->nextSample = index; }

FilmSums OptixBackend::readFilm() const { return state_->film.download(); }

void OptixBackend::loadFilm(const FilmSums& film) { state_->film.upload(film); }

Image OptixBackend::readImage() const { return state_->film.readImage(); }

Image OptixBackend::readEmission() const { return state_->film.readEmission(); }

void OptixBackend::setAovsEnabled(bool enabled) {
  state_->aovsEnabled = enabled;
  state_->allocateFilm();
  state_->startNeeded();
  state_->restart();
}

std::optional<ProgramCompileStatus> OptixBackend::startingCompile() const {
  const State& s = *state_;
  const std::vector<ProgramModule> awaited = s.awaitedModules();
  if (s.modules.finished(awaited)) return std::nullopt;
  const CompileTaskCounts tasks = s.modules.tasks(awaited);
  return ProgramCompileStatus{tasks.done, tasks.known, s.modules.secondsCompiling(awaited)};
}

double OptixBackend::preparePrograms(ProgramWait wait) {
  const auto start = std::chrono::steady_clock::now();
  state_->preparePrograms(wait);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool OptixBackend::aovsEnabled() const { return state_->aovsEnabled; }

AovImages OptixBackend::readAovs() const {
  const State& s = *state_;
  if (!s.aovsEnabled) throw std::logic_error("OptixBackend::readAovs without setAovsEnabled(true)");
  return s.film.readAovs();
}

const FilmFilters& OptixBackend::filters() const { return *filters_; }

const FilmDisplay& OptixBackend::display() const { return *display_; }

std::array<unsigned char, 16> OptixBackend::deviceUuid() const {
  cudaDeviceProp properties{};
  checkCuda(cudaGetDeviceProperties(&properties, state_->context.deviceOrdinal()), "reading the GPU's properties");
  std::array<unsigned char, 16> uuid{};
  std::memcpy(uuid.data(), properties.uuid.bytes, uuid.size());
  return uuid;
}

void OptixBackend::writeImageToDevice(Vec3* destination) const {
  const State& s = *state_;
  writeMeanImage(s.film.view(), s.pixelCount(), destination, s.context.stream());
  checkCuda(cudaGetLastError(), "launching the image copy");
  checkCuda(cudaStreamSynchronize(s.context.stream()), "copying the image on the device");
}

int OptixBackend::deviceOrdinal() const { return state_->context.deviceOrdinal(); }

void OptixBackend::moveFilmRows(OptixBackend& source, uint32_t firstRow, uint32_t rows) {
  State& s = *state_;
  State& from = *source.state_;
  if (&source == this) throw std::logic_error("OptixBackend::moveFilmRows from itself");
  if (size_t(firstRow) + rows > s.settings.height) throw std::logic_error("OptixBackend::moveFilmRows past the image");
  if (rows == 0) return;
  const uint32_t first = firstRow * s.settings.width, count = rows * s.settings.width;
  {
    CurrentDevice here(deviceOrdinal());
    s.incoming.resize(s.settings.width, s.settings.height, s.aovsEnabled);
    s.incoming.copyPixels(from.film, source.deviceOrdinal(), deviceOrdinal(), first, count, s.context.stream());
    addFilmPixels(s.film.view(), s.incoming.view(), first, count, s.aovsEnabled, s.context.stream());
    checkCuda(cudaGetLastError(), "launching the film addition");
    checkCuda(cudaStreamSynchronize(s.context.stream()), "adding another device's film");
  }
  CurrentDevice there(source.deviceOrdinal());
  from.film.clearPixels(first, count, from.context.stream());
  checkCuda(cudaStreamSynchronize(from.context.stream()), "clearing the film rows moved to another device");
}

AccelerationStatistics OptixBackend::accelerationStatistics() const { return state_->acceleration.statistics(); }

RawTraceTiming OptixBackend::timeRawTrace(uint32_t warmup, uint32_t frames) {
  State& s = *state_;
  if (!s.hasScene) throw std::logic_error("OptixBackend::timeRawTrace before setScene");
  const size_t pixels = s.pixelCount();
  LaunchParameters p = s.baseParameters();
  p.firstSample = s.nextSample;
  p.samplesPerPixel = 1;
  p.recording.slotsPerPixel = rayBoundPerSample(s.settings);
  const size_t slots = size_t(p.recording.slotsPerPixel) * pixels;
  DeviceBuffer rays(slots * sizeof(RecordedRay), "the recorded rays");
  DeviceBuffer rayTypes(slots, "the recorded ray types");
  DeviceBuffer counts(pixels * sizeof(uint32_t), "the recorded ray counts");
  p.recording.rays = rays.as<RecordedRay>();
  p.recording.rayTypes = rayTypes.as<uint8_t>();
  p.recording.counts = counts.as<uint32_t>();

  const LaunchResult recorded = s.launch(RaygenProgram::Record, p, s.settings.height);
  RawTraceTiming timing;
  timing.raysPerFrame = recorded.totals.rays;
  for (uint32_t i = 0; i < warmup + frames; ++i) {
    LaunchResult r = s.launch(RaygenProgram::RawTrace, p, s.settings.height);
    if (r.totals.rays != recorded.totals.rays)
      throw std::runtime_error("the raw-trace mode replayed " + std::to_string(r.totals.rays) + " of " +
                               std::to_string(recorded.totals.rays) + " recorded rays: a path traced more rays " +
                               "than the recording holds");
    if (i >= warmup) timing.deviceMilliseconds.push_back(r.milliseconds);
  }
  return timing;
}

}  // namespace candela
