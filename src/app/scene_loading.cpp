#include "app/scene_loading.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <new>
#include <stdexcept>

#include "core/bounds.h"
#include "scene/builtin_scenes.h"
#include "scene/loaders/gltf_loader.h"
#include "scene/loaders/image_decoding.h"
#include "scene/loaders/load_diagnostics.h"
#include "scene/loaders/obj_loader.h"
#include "scene/loaders/pbrt_loader.h"
#include "scene/loaders/scene_file.h"
#include "scene/scene_repair.h"
#include "core/file_extension.h"

namespace candela {

namespace {

Scene loadModel(const std::string& path, const SceneLoadOptions& options, LoadWarnings& warnings) {
  SceneCacheSettings cache = options.cache;
  cache.enabled &= options.outsidePaths == OutsidePaths::Refused;
  return loadThroughSceneCache(path, cache, warnings, [&](LoadWarnings& w) {
    std::string ext = lowerCaseExtension(path);
    if (ext == ".obj") return loadObj(path, w, options.outsidePaths);
    if (ext == ".pbrt") return loadPbrt(path, w, options.outsidePaths);
    return loadGltf(path, w, options.outsidePaths);
  });
}

// A file whose content asks for more memory than there is (a model of more triangles than fit) is refused with
// a sentence naming it rather than std::bad_alloc's name.
template <class Load>
auto withMemoryReported(const std::string& file, Load load) {
  try {
    return load();
  } catch (const std::bad_alloc&) {
    throw std::runtime_error(printableText(file) + ": not enough memory to load it");
  }
}

Scene loadFile(const std::string& path, const SceneLoadOptions& options, LoadWarnings& warnings) {
  std::string ext = lowerCaseExtension(path);
  if (ext == ".obj" || ext == ".gltf" || ext == ".glb" || ext == ".pbrt")
    return withMemoryReported(path, [&] { return loadModel(path, options, warnings); });
  if (ext == ".json")
    return loadSceneFile(
        path,
        [&](const std::string& model, LoadWarnings& w) {
          return withMemoryReported(model, [&] { return loadModel(model, options, w); });
        },
        warnings, options.outsidePaths);
  std::string names;
  for (const std::string& n : builtinSceneNames()) names += (names.empty() ? "" : ", ") + n;
  if (!std::filesystem::exists(path))
    throw std::runtime_error("unknown scene '" + printableText(path) + "': not a file, nor a built-in scene (" + names + ")");
  throw std::runtime_error(printableText(path) + ": unknown scene format '" + printableText(ext) + "' (use .obj, .gltf, .glb, .pbrt or .json, or a built-in scene: " + names +
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
  if (!makeBuiltinScene(spec, scene))
    scene = withMemoryReported(spec, [&] { return loadFile(spec, options, warnings); });
  if (!options.environmentPath.empty()) {
    Environment env;
    const std::string& map = options.environmentPath;
    env.map = withMemoryReported(map, [&] { return loadEnvironmentImage(map); });
    scene.environment = std::move(env);
  }
  repairScene(scene, spec, warnings);
  for (const std::string& w : warnings.messages)
    std::fprintf(stderr, "candela: warning: %s\n", printableText(w).c_str());
  if (scene.cameraMissing) frameSceneBounds(scene);
  return scene;
}

}  // namespace candela
