#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include <tbb/global_control.h>

#include "app/animation_render.h"
#include "app/backend_factory.h"
#include "app/camera_path.h"
#include "app/camera_path_render.h"
#include "app/checkpoint/duration.h"
#include "app/checkpoint/stop_signals.h"
#include "app/denoising/denoiser_choice.h"
#include "app/distributed/mpi_launch.h"
#include "app/interactive/interactive_cli.h"
#include "app/render_job.h"
#include "app/scene_loading.h"
#include "app/serve/serve.h"
#include "app/viewer/viewer.h"
#include "io/atomic_file.h"
#include "io/available_memory.h"
#include "io/file_bytes.h"
#include "io/images/aov_io.h"
#include "io/images/image_io.h"
#include "io/load_diagnostics.h"
#include "scene/builtin_scenes.h"
#if CANDELA_HAS_MPI
#include "app/distributed/distributed_render.h"
#endif

using namespace candela;

namespace {

// The scene, built-in or a file, its --env and its --camera.
void addSceneOptions(CLI::App& cmd, std::string& sceneSpec, std::string& environmentPath, std::string& camera) {
  std::string scenes;
  for (const std::string& n : builtinSceneNames()) scenes += (scenes.empty() ? "" : ", ") + n;
  cmd.add_option("scene", sceneSpec, "Scene file (.obj, .gltf, .glb, .pbrt, .json) or built-in scene (" + scenes + ")")
      ->capture_default_str();
  cmd.add_option("--env", environmentPath, "Environment map (.hdr or .exr) that lights the scene");
  cmd.add_option("--camera", camera, "The scene's camera to take, by name or index (default: the first)");
}

// How scene files are read. The scene cache is on for the commands; the library's default is off.
void addSceneInputOptions(CLI::App& cmd, SceneCacheSettings& cache, OutsidePaths& outsidePaths) {
  cache.enabled = true;
  cmd.add_flag_callback(
      "--no-cache", [&cache] { cache.enabled = false; },
      "Load models afresh, neither reading nor writing the scene cache");
  cmd.add_option("--cache-dir", cache.directory,
                 "Folder of the scene cache (default: $CANDELA_CACHE_DIR, else $XDG_CACHE_HOME/candela, else "
                 "~/.cache/candela)");
  cmd.add_flag_callback(
      "--allow-outside-paths", [&outsidePaths] { outsidePaths = OutsidePaths::Allowed; },
      "Let models and scene files read files outside their own folders (refused by default; "
      "such models bypass the scene cache)");
  cmd.add_option_function<double>(
         "--max-file-gib", [](double gib) { setMaxInputFileBytes(uint64_t(gib * double(1 << 30))); },
         "Largest file a scene may read, in GiB (default: " + std::to_string(kDefaultMaxInputFileBytes >> 30) + ")")
      ->check(CLI::Range(0.001, 1e6));
  cmd.add_option_function<std::string>(
         "--max-memory", [](const std::string& size) { setProcessMemoryLimit(*parseMemorySize(size)); },
         "Most memory the process may use, like 8G or 512M (default: what the machine and its limits leave); a "
         "scene whose loading would need more is refused, naming the file and what is too large")
      ->check(CLI::Validator(
          [](std::string& size) { return parseMemorySize(size) ? std::string() : "'" + size + "' is not a size"; },
          "SIZE", ""));
}

// --backend, and --devices (the GPUs of the optix backend). A malformed device list is a usage error; GPUs that are
// not there are found when the backend starts.
void addBackendOptions(CLI::App& cmd, std::string& backend, DeviceRequest& devices) {
  cmd.add_option("--backend", backend,
                 "auto, cpu or optix (in this build: " + availableBackends() +
                     "). The optix backend's first start on a machine compiles its GPU programs, then keeps them in "
                     "$CANDELA_OPTIX_CACHE, else $XDG_CACHE_HOME/candela/optix, else ~/.cache/candela/optix")
      ->check(CLI::IsMember({"auto", "cpu", "optix"}))
      ->capture_default_str();
  cmd.add_option_function<std::string>(
         "--devices", [&devices](const std::string& text) { devices = parseDeviceRequest(text); },
         "GPUs to render on, optix backend: all (every GPU of the kind of GPU 0) or CUDA indices like 0,1; each "
         "frame is shared between them, and the first one shows the image (a repeat, like 0,0, puts two contexts "
         "on one GPU)")
      ->check(CLI::Validator(
          [](std::string& text) {
            try {
              parseDeviceRequest(text);
            } catch (const std::invalid_argument& e) {
              return std::string(e.what());
            }
            return std::string();
          },
          "all|I,J,...", ""))
      ->default_str("all");
}

// --seed and --sampler: the random numbers of the paths.
void addRandomSequenceOptions(CLI::App& cmd, uint32_t& seed, SamplerKind& sampler,
                              const std::string& seedHelp = "Seed of the random sequence") {
  cmd.add_option("--seed", seed, seedHelp)->capture_default_str();
  cmd.add_option_function<std::string>(
         "--sampler",
         [&sampler](const std::string& name) {
           sampler = name == "sobol" ? SamplerKind::Sobol : SamplerKind::Independent;
         },
         "Random numbers of the paths: sobol (Owen-scrambled Sobol points, stratified per pixel) or independent "
         "(white noise)")
      ->check(CLI::IsMember({"sobol", "independent"}))
      ->default_str("sobol");
}

// --tonemap, the tone mapper's name (parseToneMapper); `what` begins the help.
void addToneMapperOption(CLI::App& cmd, std::string& toneMapper, const std::string& what = "Tone mapper") {
  cmd.add_option("--tonemap", toneMapper, what + ": aces, reinhard or clamp (linear)")
      ->check(CLI::IsMember({"aces", "reinhard", "clamp"}))
      ->capture_default_str();
}

template <size_t N>
void addDenoiserOption(CLI::App& cmd, DenoiserChoice& denoiser, const DenoiserChoice (&choices)[N],
                       const std::string& what = "Denoiser") {
  std::map<std::string, DenoiserChoice> names;
  for (DenoiserChoice choice : choices) names[denoiserName(choice)] = choice;
  cmd.add_option("--denoise", denoiser, what + ": " + describeDenoisers({std::begin(choices), std::end(choices)}))
      ->transform(CLI::CheckedTransformer(names, CLI::ignore_case))
      ->default_str(denoiserName(denoiser));
}

const char* textureFilterName(TextureFilter filter) {
  switch (filter) {
    case TextureFilter::Finest: return "finest";
    case TextureFilter::Trilinear: return "trilinear";
    case TextureFilter::Anisotropic: break;
  }
  return "anisotropic";
}

void addTextureFilterOption(CLI::App& cmd, TextureFilter& filter) {
  const std::map<std::string, TextureFilter> filters = {{"finest", TextureFilter::Finest},
                                                        {"trilinear", TextureFilter::Trilinear},
                                                        {"anisotropic", TextureFilter::Anisotropic}};
  cmd.add_option("--texture-filter", filter,
                 "Texture filtering over each pixel's footprint, traced by ray cones through mirror and glass: "
                 "finest (bilinear in the full-size texture), trilinear (mip levels) or anisotropic (mip levels, up "
                 "to 16 lookups along the footprint)")
      ->transform(CLI::CheckedTransformer(filters))
      ->default_str("anisotropic");
}

void addLightSamplerOption(CLI::App& cmd, LightSamplerKind& lightSampler) {
  cmd.add_option_function<std::string>(
         "--light-sampler",
         [&lightSampler](const std::string& name) {
           lightSampler = name == "bvh" ? LightSamplerKind::Bvh : LightSamplerKind::Power;
         },
         "How next-event estimation picks an emissive triangle: bvh (a light BVH, by how much each can light the "
         "shading point) or power (by emitted power alone)")
      ->check(CLI::IsMember({"bvh", "power"}))
      ->default_str("bvh");
}

const std::map<std::string, RestirMode> kRestirModes = {{"off", RestirMode::Off},
                                                        {"di", RestirMode::Di},
                                                        {"di-biased", RestirMode::DiBiased}};

void addRestirOption(CLI::App& cmd, RestirMode& restir) {
  cmd.add_option_function<std::string>(
         "--restir", [&restir](const std::string& name) { restir = kRestirModes.at(name); },
         "Direct light at the camera ray's first hit: off (next-event estimation and BSDF sampling, as at every "
         "vertex), di (ReSTIR DI: reservoirs reused across samples and nearby pixels, unbiased) or di-biased (the "
         "same with cheaper 1/M reuse weights, which leave a bias); on the CPU, or on one GPU outside the wavefront "
         "schedule")
      ->check(CLI::IsMember({"off", "di", "di-biased"}))
      ->default_str("off");
}

std::string restirModeName(RestirMode mode) {
  for (const auto& [name, value] : kRestirModes)
    if (value == mode) return name;
  return "off";
}

void addTextureLimitOptions(CLI::App& cmd, TextureLimits& limits) {
  cmd.add_option("--max-texture-size", limits.maxSize,
                 "Largest width or height of a texture in pixels; a larger one is decoded smaller, with a warning")
      ->check(CLI::Range(1u, 1u << 20))
      ->capture_default_str();
  cmd.add_option_function<uint64_t>(
         "--max-texture-memory", [&limits](uint64_t mib) { limits.maxBytes = mib << 20; },
         "MiB of decoded texture a scene may hold; over it, every texture is decoded "
         "smaller, with a warning (default: " +
             std::to_string(limits.maxBytes >> 20) + ")")
      ->check(CLI::Range(uint64_t(1), uint64_t(1) << 30));
}

void addRenderOptions(CLI::App& cmd, RenderJob& job) {
  addSceneOptions(cmd, job.sceneSpec, job.environmentPath, job.camera);
  addSceneInputOptions(cmd, job.sceneCache, job.outsidePaths);
  addTextureLimitOptions(cmd, job.textureLimits);
  cmd.add_option("--spp", job.samplesPerPixel, "Samples per pixel")
      ->check(CLI::Range(1u, 1u << 24))
      ->capture_default_str();
  cmd.add_option("--width", job.settings.width, "Image width in pixels")
      ->check(CLI::Range(1u, 16384u))
      ->capture_default_str();
  cmd.add_option("--height", job.settings.height, "Image height in pixels")
      ->check(CLI::Range(1u, 16384u))
      ->capture_default_str();
  cmd.add_option("--max-depth", job.settings.maxDepth,
                 "Longest path in bounces after the camera ray (1 = direct light only)")
      ->check(CLI::Range(1u, 1024u))
      ->capture_default_str();
  addRandomSequenceOptions(cmd, job.settings.seed, job.settings.sampler,
                           "Seed of the random sequence; same seed, same image");
  addTextureFilterOption(cmd, job.settings.textureFilter);
  addLightSamplerOption(cmd, job.settings.lightSampler);
  addRestirOption(cmd, job.settings.restir);
  // Validated while parsing, so a bad value is a usage error (exit status 2) like any other.
  auto validated = [](auto apply) {
    return CLI::Validator(
        [apply](std::string& text) {
          try {
            apply(text);
          } catch (const std::invalid_argument& e) {
            return std::string(e.what());
          }
          return std::string();
        },
        "", "");
  };
  cmd.add_option_function<std::string>(
         "--shading", [&job](const std::string& name) { job.materialOverrides.shading = parseShadingModel(name); },
         "Render every material with one shading model: phong, pbr or disney (default: each material's own)")
      ->check(validated([](const std::string& name) { parseShadingModel(name); }));
  std::string overrideNames;
  for (const OverrideParameter& p : overrideParameters())
    overrideNames += (overrideNames.empty() ? "" : ", ") + std::string(p.name);
  cmd.add_option_function<std::vector<std::string>>(
         "--override",
         [&job](const std::vector<std::string>& list) {
           for (const std::string& assignment : list) parseOverride(job.materialOverrides, assignment);
         },
         "Set a material parameter on every material, name=value in [0, 1]; repeatable. Names: " + overrideNames)
      ->type_size(1)
      ->allow_extra_args(false)
      ->check(validated([](const std::string& assignment) {
        MaterialOverrides scratch;
        parseOverride(scratch, assignment);
      }));
  addBackendOptions(cmd, job.backend, job.devices);
}

// --time, --frames, --fps and --animation of `candela render` (animation_render.h).
void addAnimationOptions(CLI::App& cmd, AnimationRequest& request) {
  CLI::Option* time = cmd.add_option_function<double>(
                             "--time", [&request](double seconds) { request.time = seconds; },
                             "Render the scene's animation at this time in seconds")
                          ->check(CLI::Validator(
                              [](std::string& text) {
                                double seconds = 0.0;
                                if (!CLI::detail::lexical_cast(text, seconds) || !std::isfinite(seconds))
                                  return "'" + text + "' is not a finite number of seconds";
                                return std::string();
                              },
                              "SECONDS", ""));
  CLI::Option* frames =
      cmd.add_option_function<std::string>(
             "--frames", [&request](const std::string& text) { request.frames = parseFrameRange(text); },
             "Render frames A to B of the animation (A:B), frame f at f/fps seconds, each to the output name with its "
             "last run of # replaced by the frame number (out_####.png; without #, _#### goes before the extension)")
          ->check(CLI::Validator(
              [](std::string& text) {
                try {
                  parseFrameRange(text);
                } catch (const std::invalid_argument& e) {
                  return std::string(e.what());
                }
                return std::string();
              },
              "A:B", ""))
          ->excludes(time);
  cmd.add_option("--fps", request.framesPerSecond, "Frames per second of --frames")
      ->check(CLI::Range(0.001, 1000.0))
      ->needs(frames)
      ->capture_default_str();
  cmd.add_option("--animation", request.clip, "The animation to play, by name or index (default: the first)");
}

std::string formatRate(double perSecond) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", perSecond / 1e6);
  return buffer;
}

// Fails early, before a long render, when the output cannot be written.
void checkOutputPath(const std::string& path) {
  if (!isSupportedImageExtension(path))
    throw std::runtime_error("cannot write '" + path + "': use a .png, .exr or .pfm file name");
  checkAtomicTarget(path);
}

// A duration option: 90, 90s, 10m, 2h.
void addDurationOption(CLI::App& cmd, const std::string& name, double& seconds, const std::string& help) {
  cmd.add_option_function<std::string>(
         name, [&seconds](const std::string& text) { seconds = parseDuration(text); }, help)
      ->check(CLI::Validator(
          [](std::string& text) {
            try {
              parseDuration(text);
            } catch (const std::invalid_argument& e) {
              return std::string(e.what());
            }
            return std::string();
          },
          "DURATION", ""));
}

// --checkpoint, --checkpoint-every, --resume and --time-limit (app/checkpoint/render_control.h).
void addRenderControlOptions(CLI::App& cmd, RenderControl& control) {
  CLI::Option* checkpoint = cmd.add_option(
      "--checkpoint", control.checkpointPath,
      "Keep the render resumable in this .exr file: the film with its sample counts and the settings, written "
      "every --checkpoint-every, when the render ends, and when SIGINT, SIGTERM or SIGUSR1 (under mpirun: "
      "SIGUSR1) stops it at a sample boundary");
  control.checkpointEverySeconds = 600.0;
  addDurationOption(cmd, "--checkpoint-every", control.checkpointEverySeconds,
                    "How often to write the --checkpoint, like 90s, 10m or 2h (default: 10m)");
  cmd.get_option("--checkpoint-every")->needs(checkpoint);
  cmd.add_option("--resume", control.resumePath,
                 "Continue the render of this checkpoint up to --spp samples per pixel; the scene and settings must "
                 "be the ones it was rendered with");
  addDurationOption(cmd, "--time-limit", control.timeLimitSeconds,
                    "Stop at the last sample boundary before this much time (like 55m) has passed since the start, "
                    "and write the image of the samples so far");
}

// Whether two paths name one file, the one existing or to be made.
bool sameFile(const std::string& a, const std::string& b) {
  std::error_code error;
  if (std::filesystem::equivalent(a, b, error)) return true;
  const std::filesystem::path ca = std::filesystem::weakly_canonical(std::filesystem::absolute(a), error);
  if (error) return false;
  const std::filesystem::path cb = std::filesystem::weakly_canonical(std::filesystem::absolute(b), error);
  return !error && ca == cb;
}

// Fails early, before a long render, when the checkpoint cannot be written, or would be replaced by the image.
void checkCheckpointPath(const std::string& path, const std::string& output) {
  if (path.empty()) return;
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (extension != ".exr") throw std::runtime_error("cannot write '" + path + "': a checkpoint is an .exr file");
  if (sameFile(path, output))
    throw std::runtime_error("-o and --checkpoint name the same file, '" + path +
                             "': the image would replace the checkpoint; give them two names");
  checkAtomicTarget(path);
}

// Writes the outputs of a render and reports it; returns the exit status.
int finishRender(const RenderJob& job, const RenderOutcome& outcome, const std::string& output,
                 const DisplaySettings& display) {
  const unsigned done = outcome.samplesPerPixel, asked = job.samplesPerPixel;
  if (outcome.end == RenderEnd::Signal && !outcome.checkpointFailed) {
    const int signal = StopOnSignals::requested();
    std::fprintf(stderr,
                 "candela: %s stopped the render after %u of %u samples per pixel; '%s' holds them (continue "
                 "with --resume)\n",
                 StopOnSignals::signalName(signal), done, asked, job.control.checkpointPath.c_str());
    return 128 + signal;
  }
  if (outcome.end == RenderEnd::TimeLimit)
    std::fprintf(stderr, "candela: the time limit stopped the render after %u of %u samples per pixel\n", done, asked);
  if (outcome.end == RenderEnd::Signal)  // and the checkpoint that would hold the samples could not be written
    std::fprintf(stderr,
                 "candela: %s stopped the render after %u of %u samples per pixel; with no checkpoint to hold them, "
                 "the image of them is written\n",
                 StopOnSignals::signalName(StopOnSignals::requested()), done, asked);
  std::vector<std::string> written = writeImageWithAovs(output, outcome.image, display, outcome.aovs, job.aovs);
  const RenderSettings& rendered = outcome.settings;
  double samples = double(rendered.width) * rendered.height * outcome.samplesPerPixel;
  std::fprintf(stderr, "rendered %ux%u at %u spp in %.2f s: %s Msamples/s, %s Mrays/s, %llu invalid samples dropped\n",
               rendered.width, rendered.height, outcome.samplesPerPixel, outcome.seconds,
               formatRate(samples / outcome.seconds).c_str(),
               formatRate(double(outcome.stats.rays) / outcome.seconds).c_str(),
               (unsigned long long)outcome.stats.invalidSamples);
  warnWhereTheCameraSeesNoLight(outcome, display);
  for (const std::string& path : written) std::printf("%s\n", std::filesystem::absolute(path).string().c_str());
  return 0;
}

#if !CANDELA_HAS_MPI
void warnNoMpi() {
  std::fprintf(stderr,
               "candela: warning: this build has no MPI support (libopenmpi-dev was not found when it "
               "was configured): this process renders the whole image on its own\n");
}
#endif

int runRender(const RenderJob& job, const std::string& output, const DisplaySettings& display,
              [[maybe_unused]] double rankTimeoutSeconds) {
  auto checkOutputs = [&] {
    checkOutputPath(output);
    checkCheckpointPath(job.control.checkpointPath, output);
  };
  auto writeOutputs = [&](const RenderOutcome& outcome) { return finishRender(job, outcome, output, display); };
#if CANDELA_HAS_MPI
  if (launchedByMpi()) return runDistributedRender(job, rankTimeoutSeconds, checkOutputs, writeOutputs);
#else
  if (launchedByMpi()) warnNoMpi();
#endif
  checkOutputs();
  const int status = writeOutputs(runRenderJob(job, /*showProgress=*/true));
  // Stopped by a signal: end as the signal would have ended the process, now that the checkpoint is written.
  StopOnSignals::endWithRequestedSignal();
  return status;
}

// `candela render --time` or `--frames`: alone, or under an MPI launcher with the ranks sharing every frame.
int runAnimation(const RenderJob& job, const AnimationRequest& request, const std::string& output,
                 const DisplaySettings& display, [[maybe_unused]] double rankTimeoutSeconds) {
#if CANDELA_HAS_MPI
  if (launchedByMpi())
    return runDistributedSequence(job, rankTimeoutSeconds, [&](const RenderJob& teamJob) {
      return runAnimatedRender(teamJob, request, output, display);
    });
#else
  if (launchedByMpi()) warnNoMpi();
#endif
  return runAnimatedRender(job, request, output, display);
}

// --camera-path FILE, --camera-orbit FRAMES: an image sequence (app/camera_path_render.h).
void addCameraPathOptions(CLI::App& cmd, CameraPathSource& source) {
  auto* file = cmd.add_option("--camera-path", source.file,
                              "Render an image sequence along the cameras of FILE, one per line: 'eye_x eye_y eye_z "
                              "target_x target_y target_z [fov_degrees]'; frame i goes to <output>.<i>.<ext>");
  auto* orbit =
      cmd.add_option("--camera-orbit", source.orbitFrames,
                     "Render an image sequence of FRAMES cameras on a circle around the scene camera's target")
          ->check(CLI::Range(uint32_t(1), uint32_t(kMaxCameraPathFrames)));
  cmd.add_option(
         "--camera-orbit-degrees", source.orbitDegrees,
         "The arc of --camera-orbit in degrees (360: a full turn; less: from the scene camera's eye to the arc's "
         "end, both in the sequence)")
      ->check(CLI::Range(-360.0f, 360.0f))
      ->capture_default_str();
  file->excludes(orbit);
}

int runCameraPath(const RenderJob& job, const CameraPathSource& source, const std::string& output,
                  const DisplaySettings& display) {
  if (!source.given()) throw std::runtime_error("--denoise temporal needs a sequence: --camera-path or --camera-orbit");
  checkOutputPath(output);
  TemporalParams temporal;
  temporal.atrous = job.atrous;
  runCameraPathRender(job, temporal, source, output, display);
  return 0;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

int runBench(const RenderJob& job) {
  RenderOutcome outcome = runRenderJob(job, /*showProgress=*/false);
  const RenderSettings& rendered = outcome.settings;
  double samples = double(rendered.width) * rendered.height * outcome.samplesPerPixel;
  double samplesPerFrame = double(rendered.width) * rendered.height;
  double raysPerFrame = double(outcome.stats.rays) / double(outcome.samplesPerPixel);
  nlohmann::ordered_json report = {
      {"scene", outcome.sceneName},
      {"width", rendered.width},
      {"height", rendered.height},
      {"spp", outcome.samplesPerPixel},
      {"max_depth", rendered.maxDepth},
      {"sampler", rendered.sampler == SamplerKind::Sobol ? "sobol" : "independent"},
      {"texture_filter", textureFilterName(rendered.textureFilter)},
      {"light_sampler", rendered.lightSampler == LightSamplerKind::Bvh ? "bvh" : "power"},
      {"restir", restirModeName(rendered.restir)},
      {"backend", outcome.backendName},
      {"device", outcome.deviceName},
      {"seconds", outcome.seconds},
      {"msamples_per_s", samples / outcome.seconds / 1e6},
      {"mrays_per_s", double(outcome.stats.rays) / outcome.seconds / 1e6},
      {"invalid_samples", outcome.stats.invalidSamples},
      {"warmup_frames", job.warmupFrames},
      {"median_ms_per_frame", median(outcome.frameMilliseconds)},
      {"load_seconds", outcome.loadSeconds},
      {"backend_start_seconds", outcome.backendStartSeconds},
      {"program_compile_seconds", outcome.programCompileSeconds},
      {"first_frame_seconds", outcome.firstFrameSeconds},
  };
  // GPU backends time every launch with device events: frame rate and throughput from the median launch.
  if (!outcome.deviceFrameMilliseconds.empty()) {
    const std::vector<double>& ms = outcome.deviceFrameMilliseconds;
    double m = median(ms);
    report["median_device_ms_per_frame"] = m;
    report["min_device_ms_per_frame"] = *std::min_element(ms.begin(), ms.end());
    report["max_device_ms_per_frame"] = *std::max_element(ms.begin(), ms.end());
    report["device_fps"] = 1000.0 / m;
    report["device_msamples_per_s"] = samplesPerFrame / m / 1e3;
    report["device_mrays_per_s"] = raysPerFrame / m / 1e3;
    report["rays_per_sample"] = raysPerFrame / samplesPerFrame;
  }
  // Several devices: each one's median GPU time for its share of a launch, and the final combine of the films.
  if (!outcome.perDeviceFrameMilliseconds.empty()) {
    const size_t devices = outcome.perDeviceFrameMilliseconds.front().size();
    nlohmann::ordered_json perDevice = nlohmann::ordered_json::array();
    for (size_t d = 0; d < devices; ++d) {
      std::vector<double> ms;
      for (const std::vector<double>& frame : outcome.perDeviceFrameMilliseconds) ms.push_back(frame[d]);
      perDevice.push_back(median(ms));
    }
    report["devices"] = devices;
    report["median_device_ms_per_frame_by_device"] = perDevice;
    report["combine_ms"] = outcome.combineMilliseconds;
  }
  if (!outcome.rawTraceMilliseconds.empty()) {
    double m = median(outcome.rawTraceMilliseconds);
    double rawRate = double(outcome.rawTraceRaysPerFrame) / m / 1e3;
    report["raw_trace_rays_per_frame"] = outcome.rawTraceRaysPerFrame;
    report["raw_trace_median_device_ms"] = m;
    report["raw_trace_mrays_per_s"] = rawRate;
    if (!outcome.deviceFrameMilliseconds.empty())
      report["path_ray_rate_fraction_of_raw"] = raysPerFrame / median(outcome.deviceFrameMilliseconds) / 1e3 / rawRate;
  }
  std::cout << report.dump() << std::endl;
  return 0;
}

int runLoad(const std::string& spec, const SceneLoadOptions& options) {
  auto start = std::chrono::steady_clock::now();
  Scene scene = loadScene(spec, options);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  size_t vertices = 0;
  for (const Mesh& m : scene.meshes) vertices += m.positions.size();
  nlohmann::ordered_json report = {
      {"scene", spec},
      {"seconds", seconds},
      {"meshes", scene.meshes.size()},
      {"instances", scene.instances.size()},
      {"triangles", scene.triangleCount()},
      {"vertices", vertices},
      {"materials", scene.materials.size()},
      {"textures", scene.textures.size()},
      {"scene_bytes", sceneMemoryBytes(scene)},
  };
  std::cout << report.dump() << std::endl;
  return 0;
}

// The options `candela view` and `candela serve` share (app/interactive/interactive_options.h), declared once for
// both, so that each names them with the same defaults and limits.
void addInteractiveCommandOptions(CLI::App& cmd, InteractiveOptions& options) {
  addSceneOptions(cmd, options.sceneSpec, options.environmentPath, options.camera);
  addSceneInputOptions(cmd, options.sceneCache, options.outsidePaths);
  addTextureLimitOptions(cmd, options.textureLimits);
  addBackendOptions(cmd, options.backend, options.devices);
  addRandomSequenceOptions(cmd, options.seed, options.sampler);
  addLightSamplerOption(cmd, options.lightSampler);
  addRestirOption(cmd, options.restir);
  addInteractiveOptions(cmd, options);
}

// Fails early, before the window opens or the port is bound, on what the shared options cannot do.
void checkInteractiveOptions(const InteractiveOptions& options) {
  if (!options.screenshot.empty()) checkOutputPath(options.screenshot);
  if (!inThisBuild(options.post.denoiser)) throw std::runtime_error(notInThisBuild(options.post.denoiser));
}

void addViewOptions(CLI::App& cmd, ViewerOptions& options) {
  addInteractiveCommandOptions(cmd, options.interactive);
  cmd.add_flag_callback(
      "--no-interop", [&options] { options.interop = false; },
      "OptiX backend: show the image through a copy to the host, not CUDA-OpenGL interop");
  cmd.add_option("--window-capture", options.windowCapture, "After --frames, write the whole window as a .png")
      ->needs(cmd.get_option("--frames"));
  cmd.add_option("--state-file", options.stateFile, "Where F12 writes the viewer's state as JSON")
      ->capture_default_str();
}

int runView(const ViewerOptions& options) {
  checkInteractiveOptions(options.interactive);
  if (!options.windowCapture.empty()) {
    if (options.interactive.frames == 0)
      throw std::runtime_error("--window-capture needs a number of --frames to render first");
    checkOutputPath(options.windowCapture);
    if (std::filesystem::path(options.windowCapture).extension() != ".png")
      throw std::runtime_error("cannot write '" + options.windowCapture + "': a window capture is a .png file");
  }
#ifdef CANDELA_HAS_VIEWER
  return runViewer(options);
#else
  throw std::runtime_error(
      "this build has no viewer: configure with CANDELA_BUILD_VIEWER=ON once libglfw3-dev, libimgui-dev and "
      "libgl-dev are installed (scripts/install-dependencies.sh)");
#endif
}

void addServeOptions(CLI::App& cmd, ServeOptions& options) {
  addInteractiveCommandOptions(cmd, options.interactive);
  cmd.add_option("--port", options.port, "TCP port to listen on (0: any free port)")->capture_default_str();
  cmd.add_option("--bind", options.bind, "Address to listen on")->capture_default_str();
  CLI::Option* token = cmd.add_option("--token", options.token,
                                      "Secret every request must show (default: a random one, printed in the address)");
  cmd.add_flag("--no-token", options.noToken,
               "Serve a loopback address without a token: then any user of this machine may watch and steer")
      ->excludes(token);
  cmd.add_option_function<std::string>(
         "--stream", [&options](const std::string& stream) { options.offerVideo = stream == "auto"; },
         "How frames travel: auto (an H.264 video stream to browsers whose WebCodecs decode it, JPEG stripes to the "
         "others) or jpeg (JPEG stripes to every browser)")
      ->check(CLI::IsMember({"auto", "jpeg"}))
      ->default_str("auto");
}

int runServeCommand(const ServeOptions& options) {
  checkInteractiveOptions(options.interactive);
  // It travels in addresses and cookies unescaped.
  const auto plain = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_'; };
  if (!std::all_of(options.token.begin(), options.token.end(), plain))
    throw std::runtime_error("--token: use letters, digits, '-' and '_' only");
#ifdef CANDELA_HAS_SERVE
  return runServe(options);
#else
  throw std::runtime_error(
      "this build has no web viewer: install libboost-dev, libturbojpeg0-dev and libx264-dev "
      "(scripts/install-dependencies.sh) and configure again");
#endif
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "candela: a physically based path tracer.\n"
      "  candela render                 render the built-in Cornell box to candela.png\n"
      "  candela render -o box.exr --spp 256\n"
      "  candela bench --spp 16         print one JSON line of timings\n"
      "  candela view                   open the interactive viewer\n"
      "  candela serve --port 8080      the interactive viewer in a web browser\n"

      "  candela bench --backend optix --width 1920 --height 1080 --spp 100 --warmup 20 --raw-trace"};
  app.require_subcommand(1);

  RenderJob renderJob;
  std::string output = "candela.png";
  DisplaySettings display;
  std::string toneMapper = "aces";
  CLI::App* render = app.add_subcommand("render", "Render a scene to an image file");
  addRenderOptions(*render, renderJob);
  render->add_option("-o,--output", output, "Output image: .png (tone mapped), .exr or .pfm (linear)")
      ->capture_default_str();
  render->add_option("--exposure", display.exposure, "Exposure in stops, for .png")->capture_default_str();
  AnimationRequest animation;
  addAnimationOptions(*render, animation);
  addToneMapperOption(*render, toneMapper, "Tone mapper for .png");
  addDenoiserOption(*render, renderJob.denoiser, kDenoiserChoices);
  addRenderControlOptions(*render, renderJob.control);
  // A checkpoint holds one image: a sequence's frames would overwrite it, and each would resume from it.
  for (const char* option : {"--checkpoint", "--resume"})
    render->get_option("--frames")->excludes(render->get_option(option));
  double rankTimeoutSeconds = 600.0;
  addDurationOption(*render, "--rank-timeout", rankTimeoutSeconds,
                    "Under mpirun: how long a rank waits for another (default: 10m); then rank 0 renders a silent "
                    "rank's samples itself, other waits end the job");
  render->add_option("--atrous-passes", renderJob.atrous.passes, "Passes of the a-trous denoiser")
      ->check(CLI::Range(1, kMaxAtrousPasses))
      ->capture_default_str();
  CameraPathSource cameraPath;
  addCameraPathOptions(*render, cameraPath);
  render
      ->add_option_function<std::string>(
          "--aov", [&renderJob](const std::string& list) { renderJob.aovs = parseAovList(list); },
          "Also write AOVs, comma-separated: albedo, normal, depth. In an .exr they are layers of the file; with "
          ".png or .pfm they go beside it as <name>.<aov>.png/.pfm")
      ->check(CLI::Validator(
          [](std::string& list) {
            try {
              parseAovList(list);
            } catch (const std::invalid_argument& e) {
              return std::string(e.what());
            }
            return std::string();
          },
          "", ""));

  RenderJob benchJob;
  benchJob.samplesPerPixel = 16;
  benchJob.steadyTimedFrames = true;
  CLI::App* bench = app.add_subcommand("bench", "Time a render and print the numbers as one JSON object");
  addRenderOptions(*bench, benchJob);
  bench->add_option("--warmup", benchJob.warmupFrames, "Untimed launches before the timed ones")->capture_default_str();
  bench->add_flag("--raw-trace", benchJob.rawTrace,
                  "Also time tracing the same rays with no shading, the traversal ceiling (optix backend)");

  unsigned threads = 0;
  for (CLI::App* cmd : {render, bench})
    cmd->add_option("--threads", threads, "CPU backend: render with this many threads (default: all)")
        ->check(CLI::Range(1u, 4096u));

  ViewerOptions viewOptions;
  CLI::App* view = app.add_subcommand("view", "Open a window that refines the image while you move the camera");
  addViewOptions(*view, viewOptions);

  ServeOptions serveOptions;
  CLI::App* serve = app.add_subcommand("serve", "Serve the interactive viewer to web browsers (prints the address)");
  addServeOptions(*serve, serveOptions);

  std::string inspectSpec;
  CLI::App* inspect = app.add_subcommand("load", "Load a scene and print its size and loading time as one JSON object");
  inspect->add_option("scene", inspectSpec, "Scene file or built-in scene")->required();
  SceneLoadOptions inspectOptions;
  addSceneInputOptions(*inspect, inspectOptions.cache, inspectOptions.outsidePaths);
  addTextureLimitOptions(*inspect, inspectOptions.textureLimits);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "candela: %s (see candela --help)\n", e.what());
    return 2;
  }

  for (auto [cmd, job] : {std::pair{render, &renderJob}, std::pair{bench, &benchJob}}) {
    job->given.width = cmd->count("--width") > 0;
    job->given.height = cmd->count("--height") > 0;
    job->given.samplesPerPixel = cmd->count("--spp") > 0;
    job->given.maxDepth = cmd->count("--max-depth") > 0;
  }

  std::optional<tbb::global_control> threadLimit;
  if (threads > 0) threadLimit.emplace(tbb::global_control::max_allowed_parallelism, threads);
  try {
    if (*inspect) return runLoad(inspectSpec, inspectOptions);
    if (*render) {
      display.toneMapper = parseToneMapper(toneMapper);
      if (cameraPath.given() || renderJob.denoiser == DenoiserChoice::Temporal)
        return runCameraPath(renderJob, cameraPath, output, display);
      if (animation.requested()) return runAnimation(renderJob, animation, output, display, rankTimeoutSeconds);
      if (!animation.clip.empty()) throw std::runtime_error("--animation needs --time or --frames");
      return runRender(renderJob, output, display, rankTimeoutSeconds);
    }
    if (*view) return runView(viewOptions);
    if (*serve) return runServeCommand(serveOptions);
    return runBench(benchJob);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "candela: not enough memory for the %s command\n",
                 app.get_subcommands().front()->get_name().c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "candela: %s\n", printableText(e.what()).c_str());
    return 1;
  }
}
