#include "app/scene_loading.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/bounds.h"
#include "scene/builtin_scenes.h"
#include "scene/loaders/gltf_loader.h"
#include "scene/loaders/image_decoding.h"
#include "scene/loaders/load_diagnostics.h"
#include "scene/loaders/obj_loader.h"
#include "scene/loaders/scene_file.h"
#include "core/file_extension.h"

namespace candela {

namespace {

Scene loadModel(const std::string& path, const SceneCacheSettings& cache, LoadWarnings& warnings) {
  return loadThroughSceneCache(path, cache, warnings, [&](LoadWarnings& w) {
    return lowerCaseExtension(path) == ".obj" ? loadObj(path, w) : loadGltf(path, w);
  });
}

Scene loadFile(const std::string& path, const SceneCacheSettings& cache, LoadWarnings& warnings) {
  std::string ext = lowerCaseExtension(path);
  if (ext == ".obj" || ext == ".gltf" || ext == ".glb") return loadModel(path, cache, warnings);
  if (ext == ".json")
    return loadSceneFile(
        path, [&](const std::string& model, LoadWarnings& w) { return loadModel(model, cache, w); }, warnings);
  std::string names;
  for (const std::string& n : builtinSceneNames()) names += (names.empty() ? "" : ", ") + n;
  if (!std::filesystem::exists(path))
    throw std::runtime_error("unknown scene '" + path + "': not a file, nor a built-in scene (" + names + ")");
  throw std::runtime_error(path + ": unknown scene format '" + ext + "' (use .obj, .gltf, .glb or .json, or a built-in scene: " + names +
                           ")");
}

}  // namespace

void frameSceneBounds(Scene& scene) {
  Bounds3 bounds;
  for (const Instance& inst : scene.instances)
    for (Vec3 p : scene.meshes[inst.meshId].positions) bounds.extend(inst.objectToWorld.point(p));
  if (!(bounds.lo.x <= bounds.hi.x)) return;  // nothing to frame
  Vec3 centre = bounds.centre();
  float radius = std::max(bounds.radius(), 1e-3f);
  CameraDescription& c = scene.camera;
  c.verticalFovDegrees = 40.0f;
  float distance = 1.1f * radius / std::sin(0.5f * c.verticalFovDegrees * kPi / 180.0f);
  c.target = centre;
  c.eye = centre + normalize(Vec3{0.0f, 0.3f, 1.0f}) * distance;
  c.up = {0, 1, 0};
  c.apertureRadius = 0.0f;
  c.focusDistance = 0.0f;
  scene.cameraMissing = false;
}

Scene loadScene(const std::string& spec, const SceneLoadOptions& options) {
  Scene scene;
  LoadWarnings warnings;
  setTextureLimits(options.textureLimits);
  // Cached models hold their textures as decoded under the default limits; other limits load afresh and leave
  // the cache alone, so that neither reads textures decoded for the other.
  SceneCacheSettings cache = options.cache;
  const TextureLimits defaults;
  if (options.textureLimits.maxSize != defaults.maxSize || options.textureLimits.maxBytes != defaults.maxBytes)
    cache.enabled = false;
  if (!makeBuiltinScene(spec, scene)) scene = loadFile(spec, cache, warnings);
  fitSceneTextures(scene, options.textureLimits, warnings);
  if (!options.environmentPath.empty()) {
    Environment env;
    env.map = loadEnvironmentImage(options.environmentPath);
    scene.environment = std::move(env);
  }
  for (const std::string& w : warnings.messages) std::fprintf(stderr, "candela: warning: %s\n", w.c_str());
  if (scene.cameraMissing) frameSceneBounds(scene);
  return scene;
}

}  // namespace candela
