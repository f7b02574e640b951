#pragma once
#include <string>

#include "backends/backend.h"
#include "scene/material_overrides.h"

namespace candela {

struct RenderJob {
  std::string sceneSpec = "cornell-box";
  std::string environmentPath;  // replaces the scene's environment when set
  RenderSettings settings;
  uint32_t samplesPerPixel = 64;
  std::string backend = "auto";
  MaterialOverrides materialOverrides;
};

struct RenderOutcome {
  Image image;
  FrameStats stats;
  double seconds = 0.0;  // rendering only: scene loading and acceleration-structure builds excluded
  std::string backendName;
  std::string deviceName;
  std::string sceneName;
};

// Loads the scene, builds the backend and accumulates the requested samples, one launch per sample per pixel.
// Throws std::runtime_error on failure.
RenderOutcome runRenderJob(const RenderJob& job, bool showProgress);

}  // namespace candela
