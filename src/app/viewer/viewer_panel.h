#pragma once
#include <string>
#include <utility>
#include <vector>

#include "app/interactive/scene_summary.h"
#include "app/interactive/viewer_controls.h"

namespace candela {

// What the panel reports; filled by the viewer each frame.
struct PanelStatus {
  std::string backend;
  std::string device;
  std::string imageTransfer;  // how the image reaches the screen (ImageTransfer::description)
  std::string starting;       // while the GPU programs compile and the CPU renders meanwhile (meanwhileNote)
  double framesPerSecond = 0.0;
  double msPerFrame = 0.0;
  uint32_t accumulatedSamples = 0;
  uint32_t imageWidth = 0;
  uint32_t imageHeight = 0;
  bool preview = false;
  std::string sceneName;
  SceneSummary scene;
  std::vector<std::string> animationClips;               // the scene's animations; none: no animation section
  std::vector<std::pair<float, float>> animationRanges;  // each one's first and last key time
  Vec3 cameraPosition;
  Vec3 cameraDirection;
  std::string message;  // the outcome of the last action
  bool messageIsError = false;
};

// What the user asked for this frame.
struct PanelRequests {
  bool applyEnvironment = false;  // an environment slider changed
  bool applyMaterials = false;    // the shading model or an override changed
  bool saveScreenshot = false;
  bool saveSceneFile = false;
  bool openScene = false;  // the Open button, or Enter in the scene field
  Vec2 openSceneField;     // the centre of the scene field in window coordinates, for scripts that drive the window
  bool openSceneFieldActive = false;  // the scene field has the keyboard
};

// The docked panel at the right edge of the window: status, render settings, post-processing and actions.
PanelRequests drawPanel(const PanelStatus& status, ViewerControls& controls, float x, float width, float height);

}  // namespace candela
