#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "app/interactive/animation_clock.h"
#include "app/interactive/post_settings.h"
#include "scene/material_overrides.h"

namespace candela {

// Everything the panel edits.
struct ViewerControls {
  uint32_t maxDepth = 8;
  uint32_t samplesPerFrame = 1;
  bool accumulate = true;
  float environmentScale = 1.0f;     // times the scene's own intensity
  float environmentRotation = 0.0f;  // degrees added to the scene's own rotation
  MaterialOverrides materials;
  std::vector<float> overrideSliders;  // one per overrideParameters() entry: its value while it is switched off
  PostSettings post;
  AnimationControls animation;

  std::string screenshotBase = "candela-view";      // the panel saves <base>.png and <base>.exr
  std::string sceneFilePath = "candela-view.json";  // camera and settings
  std::string openSpec;                             // a built-in scene name or a scene file
};

}  // namespace candela
