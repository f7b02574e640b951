#pragma once
#include <cstdint>
#include <string>

#include "app/viewer/post_settings.h"

namespace candela {

// Everything the panel edits.
struct ViewerControls {
  uint32_t maxDepth = 8;
  uint32_t samplesPerFrame = 1;
  bool accumulate = true;
  float environmentIntensity = 1.0f;
  PostSettings post;

  std::string screenshotBase = "candela-view";      // the panel saves <base>.png and <base>.exr
  std::string sceneFilePath = "candela-view.json";  // camera and settings
  std::string openSpec;                             // a built-in scene name or a scene file
};

}  // namespace candela
