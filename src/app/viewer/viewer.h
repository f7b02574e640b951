#pragma once
#include <cstdint>
#include <string>

#include "app/device_list.h"
#include "app/interactive/post_settings.h"
#include "core/path_sampler.h"
#include "kernel/render_settings.h"
#include "scene/cache/scene_cache.h"
#include "scene/loaders/path_confinement.h"
#include "scene/loaders/texture_limits.h"

namespace candela {

struct ViewerOptions {
  std::string sceneSpec = "cornell-box";
  std::string environmentPath;  // an .hdr or .exr map that lights the first scene instead of its own
  SceneCacheSettings sceneCache;
  OutsidePaths outsidePaths = OutsidePaths::Refused;  // whether models may refer to files outside their folders
  std::string camera;  // the name or index of the first scene's camera to take; empty: the first
  TextureLimits textureLimits;
  std::string backend = "auto";
  DeviceRequest devices;  // the GPUs of the optix backend; the first one shows the image
  bool interop = true;    // false: the image reaches the screen through the host copy even where interop works
  uint32_t width = 960;   // of the image; the panel sits beside it
  uint32_t height = 720;
  uint32_t maxDepth = 8;
  uint32_t seed = 0;
  SamplerKind sampler = SamplerKind::Sobol;
  LightSamplerKind lightSampler = LightSamplerKind::Bvh;
  uint32_t samplesPerFrame = 1;
  PostSettings post;
  uint32_t frames = 0;                                // render this many frames, then exit; 0: until the window closes
  std::string screenshot;                             // on exit: the accumulated image (.png, .exr or .pfm)
  std::string windowCapture;                          // on exit: the window's pixels, panel included (.png)
  std::string stateFile = "candela-view-state.json";  // F12 writes the viewer's state here
};

// Opens the window and runs until it closes or `frames` frames are done; returns the process exit code.
// Throws std::runtime_error with one sentence when there is no display, no OpenGL 3.3, or the scene or backend
// cannot be loaded at start.
int runViewer(const ViewerOptions& options);

}  // namespace candela
