#pragma once
#include <cstdint>
#include <string>

#include "app/device_list.h"
#include "app/interactive/post_settings.h"
#include "core/path_sampler.h"
#include "kernel/render_settings.h"
#include "scene/cache/scene_cache.h"
#include "scene/loaders/path_confinement.h"

namespace candela {

struct ServeOptions {
  std::string sceneSpec = "cornell-box";
  std::string environmentPath;
  SceneCacheSettings sceneCache;
  OutsidePaths outsidePaths = OutsidePaths::Refused;
  std::string backend = "auto";
  DeviceRequest devices;  // the GPUs of the optix backend
  std::string bind = "127.0.0.1";
  uint16_t port = 8080;  // 0: any free port (the printed address names it)
  std::string token;     // required of every request when not empty; a random one is made for other addresses
  uint32_t width = 960;  // of the image until a browser says how large its view is
  uint32_t height = 720;
  uint32_t maxDepth = 8;
  uint32_t seed = 0;
  SamplerKind sampler = SamplerKind::Sobol;
  LightSamplerKind lightSampler = LightSamplerKind::Bvh;
  uint32_t samplesPerFrame = 1;
  PostSettings post;
  uint32_t frames = 0;  // stop after this many frames (for tests); 0: until interrupted
};

}  // namespace candela
