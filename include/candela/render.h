#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "candela/image.h"
#include "candela/scene.h"

namespace candela::api {

// The settings of `candela render` of the same names. Unset sizes, samples and depth come from the scene file's
// render block, else from the command's defaults (512 x 512, 64 samples per pixel, depth 8).
struct RenderOptions {
  std::optional<uint32_t> width, height;
  std::optional<uint32_t> samplesPerPixel;  // --spp
  std::optional<uint32_t> maxDepth;         // --max-depth: bounces after the camera ray
  uint32_t seed = 0;                        // the same seed gives the same image, bit for bit
  std::string backend = "auto";             // auto, cpu or optix
  std::string denoiser = "none";            // none, atrous, bilateral or optix
  std::vector<std::string> aovs;            // any of albedo, normal, depth: returned beside the image
  std::string shading;                      // phong, pbr or disney for every material; empty: each material's own
  uint32_t threads = 0;                     // the CPU backend's threads; 0: all the cores
};

// Where a render stands, after each sample per pixel.
struct Progress {
  uint32_t samples = 0;          // samples per pixel rendered so far
  uint32_t samplesPerPixel = 0;  // asked for
  double seconds = 0.0;          // since the first sample started
  // The image of the samples so far (not denoised): a read of the film, so only worth it now and then.
  std::function<Image()> image;
};
// Called after each sample per pixel, on the thread that called render(); returning false ends the render there,
// with the samples rendered so far.
using ProgressCallback = std::function<bool(const Progress&)>;

struct RenderResult {
  Image image;                        // 3 channels, denoised where RenderOptions::denoiser says
  std::map<std::string, Image> aovs;  // albedo and normal: 3 channels; depth: 1
  uint32_t samplesPerPixel = 0;       // rendered: fewer than asked where the callback ended the render
  double seconds = 0.0;               // rendering and denoising, without the backend's start and scene set-up
  uint64_t rays = 0;                  // traced: camera, bounce and shadow rays
  uint64_t invalidSamples = 0;        // NaN, infinite or negative samples, dropped
  std::string backend, device;        // what rendered it ("cpu", the processor's name)
};

// Renders `scene` as `candela render` does. Throws Error.
RenderResult render(const Scene& scene, const RenderOptions& options = {}, const ProgressCallback& progress = {});

// The numbers `candela bench` prints. Timings cover rendering only, after `warmupFrames` untimed launches.
struct BenchResult {
  std::string scene, backend, device;
  uint32_t width = 0, height = 0, samplesPerPixel = 0, maxDepth = 0;
  double seconds = 0.0;
  double msamplesPerSecond = 0.0, mraysPerSecond = 0.0;
  uint64_t invalidSamples = 0;
  double medianMsPerFrame = 0.0;
  double backendStartSeconds = 0.0, firstFrameSeconds = 0.0;
};

// Times a render of `scene` (16 samples per pixel unless the options say otherwise, as `candela bench`). Throws
// Error.
BenchResult bench(const Scene& scene, const RenderOptions& options = {}, uint32_t warmupFrames = 0);

}  // namespace candela::api
