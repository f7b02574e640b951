#include "app/interactive/viewer_files.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "app/interactive/post_filter.h"
#include "core/file_extension.h"
#include "io/atomic_file.h"
#include "io/images/image_io.h"

namespace candela {

namespace {

nlohmann::ordered_json vec(Vec3 v) { return nlohmann::ordered_json::array({v.x, v.y, v.z}); }

void writeJson(const std::string& path, const nlohmann::ordered_json& json) {
  const std::string text = json.dump(2) + "\n";
  writeFileAtomically(path, text.data(), text.size());
}

}  // namespace

void saveScreenshot(const std::string& path, const Image& accumulated, const Image& emission,
                    const PostSettings& post) {
  writeImage(path, postFiltered(accumulated, emission, post), post.display);
}

namespace {

// The "models" of the scene file at `path`, their files made absolute.
nlohmann::ordered_json modelsOfSceneFile(const std::string& path) {
  std::ifstream in(path);
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(in, nullptr, /*allow_exceptions=*/false);
  nlohmann::ordered_json models = doc.is_object() && doc.contains("models") ? doc["models"] : nlohmann::ordered_json();
  if (!models.is_array()) return nlohmann::ordered_json();
  const std::filesystem::path base = std::filesystem::absolute(path).parent_path();
  for (auto& model : models)
    if (model.is_object() && model.contains("file") && model["file"].is_string())
      model["file"] = (base / model["file"].get<std::string>()).lexically_normal().string();
  return models;
}

}  // namespace

ViewFile makeViewFile(const std::string& sceneSpec, const Scene& scene, const CameraDescription& camera,
                      const RenderSettings& settings, const ViewerControls& controls) {
  nlohmann::ordered_json json;
  const std::string ext = lowerCaseExtension(sceneSpec);
  const bool isFile = std::filesystem::is_regular_file(sceneSpec);
  if (isFile && (ext == ".obj" || ext == ".gltf" || ext == ".glb"))
    json["models"] = nlohmann::ordered_json::array({{{"file", std::filesystem::absolute(sceneSpec).string()}}});
  else if (isFile && ext == ".json")
    json["models"] = modelsOfSceneFile(sceneSpec);

  json["camera"] = {{"position", vec(camera.eye)},
                    {"target", vec(camera.target)},
                    {"up", vec(camera.up)},
                    {"fov_degrees", camera.verticalFovDegrees},
                    {"aperture_radius", camera.apertureRadius},
                    {"focus_distance", camera.focusDistance}};
  const Environment& env = scene.environment;
  nlohmann::ordered_json environment;
  if (env.hasMap() && std::filesystem::is_regular_file(env.map.name))
    environment["map"] = std::filesystem::absolute(env.map.name).string();
  else if (!env.hasMap())
    environment["radiance"] = vec(env.radiance);
  environment["intensity"] = env.intensity;
  environment["rotation_degrees"] = env.rotationDegrees;
  environment["visible"] = env.visibleToCamera;
  json["environment"] = environment;
  json["render"] = {{"width", settings.width}, {"height", settings.height}, {"max_depth", controls.maxDepth}};
  return {json.dump(2) + "\n",
          json.contains("models") ? "" : "a built-in scene has no file to name, so the view file lists no models"};
}

std::string writeViewFile(const std::string& path, const std::string& sceneSpec, const Scene& scene,
                          const CameraDescription& camera, const RenderSettings& settings,
                          const ViewerControls& controls) {
  ViewFile file = makeViewFile(sceneSpec, scene, camera, settings, controls);
  std::ofstream out(path);
  out << file.text;
  if (!out) throw std::runtime_error("cannot write '" + path + "': the file could not be created or written");
  return file.note;
}

void writeStateFile(const std::string& path, const ViewerState& s) {
  nlohmann::ordered_json json = {
      {"frame", s.frame},
      {"restarts", s.restarts},
      {"accumulated_samples", s.accumulatedSamples},
      {"image_width", s.imageWidth},
      {"image_height", s.imageHeight},
      {"preview", s.preview},
      {"scene", s.scene},
      {"backend", s.backend},
      {"camera",
       {{"position", vec(s.cameraPosition)},
        {"forward", vec(s.cameraForward)},
        {"target", vec(s.cameraTarget)},
        {"distance", s.cameraDistance}}},
      {"denoiser", s.denoiser},
      {"message", s.message},
      {"message_is_error", s.messageIsError},
      {"open_scene_field", {s.openSceneField.x, s.openSceneField.y}},
      {"open_scene_text", s.openSceneText},
      {"open_scene_field_active", s.openSceneFieldActive},
  };
  writeJson(path, json);
}

}  // namespace candela
