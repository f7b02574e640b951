#include "app/viewer/viewer_files.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "image/filters/bilateral.h"
#include "image/image_io.h"

namespace candela {

namespace {

nlohmann::ordered_json vec(Vec3 v) { return nlohmann::ordered_json::array({v.x, v.y, v.z}); }

void writeJson(const std::string& path, const nlohmann::ordered_json& json) {
  std::ofstream out(path);
  out << json.dump(2) << "\n";
  if (!out) throw std::runtime_error("cannot write '" + path + "': the file could not be created or written");
}

}  // namespace

void saveScreenshot(const std::string& path, const Image& accumulated, const PostSettings& post) {
  if (post.bilateral)
    writeImage(path, bilateralFilter(accumulated, post.bilateralParams), post.display);
  else
    writeImage(path, accumulated, post.display);
}

void writeViewFile(const std::string& path, const std::string& sceneSpec, const CameraDescription& camera,
                   const RenderSettings& settings, const ViewerControls& controls) {
  const PostSettings& post = controls.post;
  nlohmann::ordered_json json = {
      {"scene", sceneSpec},
      {"camera",
       {{"position", vec(camera.eye)},
        {"target", vec(camera.target)},
        {"up", vec(camera.up)},
        {"vertical_fov_degrees", camera.verticalFovDegrees}}},
      {"render",
       {{"width", settings.width},
        {"height", settings.height},
        {"max_depth", controls.maxDepth},
        {"seed", settings.seed},
        {"samples_per_frame", controls.samplesPerFrame},
        {"accumulate", controls.accumulate}}},
      {"environment", {{"intensity", controls.environmentIntensity}}},
      {"display",
       {{"tone_mapper", post.display.toneMapper == ToneMapper::Clamp ? "clamp" : "aces"},
        {"exposure", post.display.exposure},
        {"bilateral",
         {{"enabled", post.bilateral},
          {"radius", post.bilateralParams.radius},
          {"spatial_sigma", post.bilateralParams.spatialSigma},
          {"range_sigma", post.bilateralParams.rangeSigma}}}}},
  };
  writeJson(path, json);
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
      {"message", s.message},
      {"message_is_error", s.messageIsError},
      {"open_scene_field", {s.openSceneField.x, s.openSceneField.y}},
  };
  const std::string temporary = path + ".partial";
  writeJson(temporary, json);
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw std::runtime_error("cannot write '" + path + "': " + error.message());
}

}  // namespace candela
