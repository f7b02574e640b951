#pragma once
#include <cstdint>
#include <string>

#include "app/device_list.h"
#include "app/interactive/post_settings.h"
#include "core/path_sampler.h"
#include "io/path_confinement.h"
#include "kernel/render_settings.h"
#include "scene/cache/scene_cache.h"
#include "scene/loaders/texture_limits.h"

namespace candela {

// The limits of the interactive options, on the command line of both front ends and in candela serve's messages.
constexpr uint32_t kMinImageSide = 64;
constexpr uint32_t kMaxImageSide = 16384;
constexpr uint32_t kMaxInteractiveDepth = 1024;
constexpr uint32_t kMaxSamplesPerFrame = 1024;

// What `candela view` and `candela serve` both start from: the scene, the backend, the image and how it is
// rendered and post-processed. Each front end adds its own (the window's, the network's).
struct InteractiveOptions {
  std::string sceneSpec = "cornell-box";
  std::string environmentPath;  // an .hdr or .exr map that lights the first scene instead of its own
  SceneCacheSettings sceneCache;
  OutsidePaths outsidePaths = OutsidePaths::Refused;  // whether models may refer to files outside their folders
  std::string camera;     // the name or index of the first scene's camera to take; empty: the first
  std::string animation;  // the name or index of the first scene's animation to play; empty: the first
  TextureLimits textureLimits;
  std::string backend = "auto";
  DeviceRequest devices;  // the GPUs of the optix backend; the first one shows the image
  uint32_t width = 960;   // of the image until the window is resized or a browser reports its view's size
  uint32_t height = 720;
  uint32_t maxDepth = 8;
  uint32_t seed = 0;
  SamplerKind sampler = SamplerKind::Sobol;
  LightSamplerKind lightSampler = LightSamplerKind::Bvh;
  RestirMode restir = RestirMode::Off;
  uint32_t samplesPerFrame = 1;
  PostSettings post;
  uint32_t frames = 0;     // render this many frames, then exit; 0: until closed or interrupted
  std::string screenshot;  // on exit: the accumulated image (.png, .exr or .pfm)
};

}  // namespace candela
