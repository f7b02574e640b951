#pragma once
#include <string>

#include "app/interactive/viewer_controls.h"
#include "image/image.h"
#include "kernel/render_settings.h"
#include "scene/scene.h"

namespace candela {

// The files the viewer writes. Each throws std::runtime_error with a sentence naming the file on failure.

// The accumulated image (denoised where the a-trous denoiser is on) as the window shows it: through the CPU
// bilateral filter when it is on, which keeps `emission` (the part of the image the camera sees emitted) apart
// unless it is empty; a .png is tone mapped with the panel's settings, an .exr or .pfm stays linear.
void saveScreenshot(const std::string& path, const Image& accumulated, const Image& emission, const PostSettings& post);

// The view as a JSON scene file (docs/scene-file.md's format): "models" naming the scene's source when it is a
// model file (.obj, .gltf, .glb) or taken over from a scene file (paths made absolute), the camera, the
// environment as rendered and the render settings. A built-in scene has no file to name, so its view file has no
// "models" and does not load on its own. Returns a note for the user when that is so.
std::string writeViewFile(const std::string& path, const std::string& sceneSpec, const Scene& scene,
                          const CameraDescription& camera, const RenderSettings& settings,
                          const ViewerControls& controls);

// The same view file's text and note, for a viewer that hands the file to someone else (candela serve sends
// it to the browser).
struct ViewFile {
  std::string text;
  std::string note;  // empty, or why the file lists no models
};
ViewFile makeViewFile(const std::string& sceneSpec, const Scene& scene, const CameraDescription& camera,
                      const RenderSettings& settings, const ViewerControls& controls);

// A snapshot of what the viewer is doing, for scripts and tests; written to a temporary name and renamed, so a
// reader never sees half a file.
struct ViewerState {
  uint64_t frame = 0;
  uint64_t restarts = 0;
  uint32_t accumulatedSamples = 0;
  uint32_t imageWidth = 0;
  uint32_t imageHeight = 0;
  bool preview = false;
  std::string scene;
  std::string backend;
  Vec3 cameraPosition, cameraForward, cameraTarget;
  float cameraDistance = 0.0f;
  std::string denoiser;  // "none", "atrous" or "optix"
  std::string message;   // the panel's last message
  bool messageIsError = false;
  Vec2 openSceneField;
  std::string openSceneText;  // what the scene field holds
  bool openSceneFieldActive = false;
};
void writeStateFile(const std::string& path, const ViewerState& state);

}  // namespace candela
