#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "backends/device_image.h"
#include "backends/film_sums.h"
#include "image/aov_images.h"
#include "image/image.h"
#include "kernel/camera.h"
#include "kernel/render_settings.h"
#include "scene/scene.h"

namespace candela {

class FilmDisplay;
class FilmFilters;

struct FrameStats {
  uint64_t rays = 0;                // camera, bounce and shadow rays traced
  uint64_t invalidSamples = 0;      // NaN/Inf/negative path estimates, or ones that would overflow a pixel's sums
  double deviceMilliseconds = 0.0;  // GPU time of the launches (CUDA events); 0 where the backend has none
  // Where a backend renders on several devices: each one's GPU time for its share (deviceMilliseconds is then the
  // slowest one's); empty otherwise.
  std::vector<double> perDeviceMilliseconds;
};

// What Backend::timeRawTrace measured.
struct RawTraceTiming {
  uint64_t raysPerFrame = 0;               // rays of the recorded sample, traced again by every timed launch
  std::vector<double> deviceMilliseconds;  // one per timed launch, from CUDA events
};

// How far a backend has got with compiling the programs its next frame needs (a GPU backend's first start on a
// machine: backends/optix/compile_progress.h).
struct ProgramCompileStatus {
  uint32_t tasksDone = 0, tasksKnown = 0;  // the compile's tasks; more become known as it goes
  double seconds = 0.0;                    // since it began
};

// What Backend::preparePrograms waits for: the programs of the next frame, or those of every frame of the
// current settings. They differ where a GPU backend's first frames render by the megakernel while the wavefront
// schedule's programs compile (backends/optix/program_use.h, pipelinesAwaited): a benchmark's timed frames wait
// for the schedule they measure.
enum class ProgramWait { NextFrame, EveryFrame };

// Thrown by Backend::setScene where this backend cannot render the scene though the CPU backend, which renders every
// valid scene, can: `--backend auto` then renders it on the CPU (app/backend_factory.h, setSceneOrFallBack).
class SceneUnsupported : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A renderer of one scene: owns traversal structures, memory and launches; shading is the shared kernel code.
// Every render() call adds samples to a progressive film; changing the camera or the settings restarts it.
class Backend {
 public:
  virtual ~Backend() = default;

  virtual std::string name() const = 0;        // "cpu", "optix"
  virtual std::string deviceName() const = 0;  // the processor or GPU that runs it

  // Throws SceneUnsupported where the scene uses what this backend does not render.
  virtual void setScene(const Scene& scene) = 0;
  // Cheap edits of the scene last set, for interactive controls: the traversal structures stay, the film
  // restarts. setMaterials returns false, changing nothing, when the change needs setScene instead (see
  // FlatScene::replaceMaterials: a different count, emission, or a material newly needing tangents).
  virtual bool setMaterials(const std::vector<Material>& materials) = 0;
  virtual void setEnvironment(const Environment& environment) = 0;
  // The scene last set again, with only the transforms of its instances and its punctual lights changed (an
  // animation posed at another time): a backend that can rebuilds only what depends on them. By default the
  // whole scene is set again.
  virtual void setInstanceTransforms(const Scene& scene) { setScene(scene); }
  // The same, with also the vertices (positions, normals, tangents; their counts unchanged) of the meshes
  // `deformed` changed (skinned or morphed meshes posed at another time): a backend that can rebuilds only the
  // structures of those meshes and what depends on the transforms. By default the whole scene is set again.
  virtual void setDeformedMeshes(const Scene& scene, const std::vector<uint32_t>& /*deformed*/) { setScene(scene); }
  virtual void setCamera(const Camera& camera) = 0;
  virtual void setSettings(const RenderSettings& settings) = 0;

  // Adds `samplesPerPixel` samples to every pixel: the sample indices from the next one (0 after a restart) on.
  virtual FrameStats render(uint32_t samplesPerPixel) = 0;
  // Samples render() added per pixel since the restart (a loaded film's samples are not counted).
  virtual uint32_t accumulatedSamples() const = 0;
  // The sample index of the next render() call's first sample; later calls continue after its last. A process
  // that renders a share of the samples (a distributed render, a resumed one) renders its indices this way.
  virtual void setNextSampleIndex(uint32_t index) = 0;

  // The film's sums, and replacing them: render() then adds to the loaded sums. loadFilm throws
  // std::invalid_argument when `film` has another size than the settings' or other AOVs than enabled.
  virtual FilmSums readFilm() const = 0;
  virtual void loadFilm(const FilmSums& film) = 0;
  // The mean of the accumulated samples.
  virtual Image readImage() const = 0;
  // The part of readImage() the camera sees emitted (PathResult::emitted): lights, emissive textures and the
  // environment seen directly or through mirrors and smooth glass. Recorded with the AOVs: throws
  // std::logic_error when they are not enabled.
  virtual Image readEmission() const = 0;

  // Whether render() also accumulates the AOVs (albedo, normal, depth at the first non-specular vertex) for
  // readAovs(). Off by default: paths then skip the code that records them. Changing it restarts the film.
  virtual void setAovsEnabled(bool enabled) = 0;
  virtual bool aovsEnabled() const = 0;
  // The mean AOVs of the accumulated samples. Throws std::logic_error when they are not enabled.
  virtual AovImages readAovs() const = 0;

  // The filters that run on this backend's film (backends/film_filters.h): the CPU's on readImage(), or a GPU
  // backend's own on its film in device memory.
  virtual const FilmFilters& filters() const = 0;
  // The display frames of this backend's film (backends/film_display.h): the accumulated or filtered image tone
  // mapped to 8-bit sRGB pixels, on the host, or on a GPU backend's device with only the bytes read back.
  virtual const FilmDisplay& display() const = 0;

  // Capabilities some backends have; callers ask for them here rather than for a backend's type.
  //
  // The traversal ceiling for this scene and ray mix (`bench --raw-trace`): records every ray of one sample per
  // pixel (the next sample index; the image is left alone), then times `frames` launches, after `warmup`
  // untimed ones, that trace exactly those rays again with no shading. Only where supportsRawTrace().
  virtual bool supportsRawTrace() const { return false; }
  virtual RawTraceTiming timeRawTrace(uint32_t /*warmup*/, uint32_t /*frames*/) {
    throw std::logic_error("the " + name() + " backend has no raw-trace mode");
  }
  // The image in GPU memory, for consumers on the same GPU; null where the image lives on the host.
  virtual const DeviceImage* deviceImage() const { return nullptr; }
  // While the programs the next frame needs are still compiling: how far that has got (render() would wait for
  // it). Nothing where there is nothing to wait for, as for a backend that compiles nothing.
  virtual std::optional<ProgramCompileStatus> startingCompile() const { return std::nullopt; }
  // Compiles the programs the next frame needs (with EveryFrame: those of every frame of these settings), all at
  // once, and returns once they are ready, as that frame's render() would, for a caller that times the wait apart
  // from the frame: the seconds it waited. 0 where there is nothing to compile.
  virtual double preparePrograms(ProgramWait /*wait*/ = ProgramWait::NextFrame) { return 0.0; }
  // Where a backend renders on several devices: how long the last read that found samples on the others took to
  // add them to the film it reads (milliseconds); 0 otherwise.
  virtual double lastCombineMilliseconds() const { return 0.0; }
};

}  // namespace candela
