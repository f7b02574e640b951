#pragma once
#include <string>

#include "backends/backend.h"
#include "scene/material_overrides.h"
#include "scene/scene.h"

namespace candela {

struct RenderJob {
  std::string sceneSpec = "cornell-box";
  std::string environmentPath;  // replaces the scene's environment when set
  // Which settings the command line gave; the others may come from the scene file's render hints.
  struct {
    bool width = false, height = false, samplesPerPixel = false, maxDepth = false;
  } given;
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
RenderOutcome renderLoadedScene(const RenderJob& job, const Scene& scene, bool showProgress);

}  // namespace candela
