#include "app/scene_loading.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <new>
#include <stdexcept>

#include "app/progress.h"
#include "core/bounds.h"
#include "core/file_extension.h"
#include "io/available_memory.h"
#include "io/images/image_decoding.h"
#include "io/load_budget.h"
#include "io/load_diagnostics.h"
#include "scene/builtin_scenes.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/loaders/obj/obj_loader.h"
#include "scene/loaders/pbrt/pbrt_loader.h"
#include "scene/loaders/scene_file.h"
#include "scene/scene_repair.h"

namespace candela {

namespace {

// A .pbrt scene shares nothing with other models: no scene file names one.
Scene loadModelFile(const std::string& path, OutsidePaths outside, LoadWarnings& warnings, SharedModelAssets* shared) {
  const std::string ext = lowerCaseExtension(path);
  if (ext == ".obj") return loadObj(path, warnings, outside, shared);
  if (ext == ".pbrt") return loadPbrt(path, warnings, outside);
  return loadGltf(path, warnings, outside, shared);
}

// The scene cache holds only what loads under the default path rule and texture limits: other loads neither
// read it nor write it, so that neither gets what was loaded for the other.
SceneCacheSettings cacheFor(const SceneLoadOptions& options) {
  SceneCacheSettings cache = options.cache;
  const TextureLimits defaults;
  cache.enabled &= options.outsidePaths == OutsidePaths::Refused && options.textureLimits.maxSize == defaults.maxSize &&
                   options.textureLimits.maxBytes == defaults.maxBytes;
  return cache;
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

// A model or scene file as loaded, its vertex attributes repaired (repairVertexAttributes): what the scene cache
// stores.
template <class Load>
Scene loadRepairingAttributes(const std::string& path, LoadWarnings& warnings, Load load) {
  Scene scene = load();
  repairVertexAttributes(scene, path, warnings);
  return scene;
}

Scene loadFile(const std::string& path, const SceneLoadOptions& options, LoadWarnings& warnings) {
  std::string ext = lowerCaseExtension(path);
  if (ext == ".obj" || ext == ".gltf" || ext == ".glb" || ext == ".pbrt")
    return loadThroughSceneCache(path, cacheFor(options), warnings, [&](LoadWarnings& w) {
      return loadRepairingAttributes(path, w, [&] { return loadModelFile(path, options.outsidePaths, w, nullptr); });
    });
  // A scene file is cached as a whole (its key covers the JSON and every file its models were read from), and
  // on a miss its models load together, sharing libraries and textures: cached one by one, every model's cache
  // file would hold its own copy of each texture it uses, and a first load would decode a texture once per
  // model that uses it.
  if (ext == ".json")
    return loadThroughSceneCache(path, cacheFor(options), warnings, [&](LoadWarnings& w) {
      auto loadModel = [&](const std::string& model, LoadWarnings& mw, SharedModelAssets& shared) {
        return withMemoryReported(model, [&] { return loadModelFile(model, options.outsidePaths, mw, &shared); });
      };
      return loadRepairingAttributes(path, w, [&] { return loadSceneFile(path, loadModel, w, options.outsidePaths); });
    });
  std::string names;
  for (const std::string& n : builtinSceneNames()) names += (names.empty() ? "" : ", ") + n;
  if (!std::filesystem::exists(path))
    throw std::runtime_error("unknown scene '" + printableText(path) + "': not a file, nor a built-in scene (" + names +
                             ")");
  throw std::runtime_error(printableText(path) + ": unknown scene format '" + printableText(ext) +
                           "' (use .obj, .gltf, .glb, .pbrt or .json, or a built-in scene: " + names + ")");
}

// Takes the camera `choice` names (a name or an index into scene.cameras), or warns which one was taken when
// the file has several.
void chooseCamera(Scene& scene, const std::string& spec, const std::string& choice, LoadWarnings& warnings) {
  auto list = [&] {
    std::string names;
    for (size_t i = 0; i < scene.cameras.size(); ++i)
      names += (i ? ", " : "") + std::to_string(i) + " '" + scene.cameras[i].name + "'";
    return names.empty() ? std::string("none") : names;
  };
  if (choice.empty()) {
    if (scene.cameras.size() > 1)
      warnings.add(spec, std::to_string(scene.cameras.size()) + " cameras; taking 0 '" + scene.cameras[0].name +
                             "' (choose with --camera NAME|INDEX: " + list() + ")");
    return;
  }
  for (size_t i = 0; i < scene.cameras.size(); ++i)
    if (scene.cameras[i].name == choice || std::to_string(i) == choice) {
      scene.camera = scene.cameras[i].description;
      scene.cameraIndex = int32_t(i);
      scene.cameraMissing = false;
      return;
    }
  throw std::runtime_error(spec + ": no camera '" + choice + "' (cameras: " + list() + ")");
}

}  // namespace

bool hasLightSource(const Scene& scene) {
  const Environment& env = scene.environment;
  if (env.intensity > 0.0f && (env.hasMap() || !isBlack(env.radiance))) return true;
  for (const PunctualLight& light : scene.punctualLights)
    if (!isBlack(light.intensity)) return true;
  for (const Medium& medium : scene.media)
    if (!isBlack(medium.emission)) return true;
  std::vector<bool> emissive(scene.materials.size());
  for (size_t m = 0; m < scene.materials.size(); ++m) emissive[m] = !isBlack(scene.materials[m].emission);
  std::vector<bool> instanced(scene.meshes.size());
  for (const Instance& inst : scene.instances) instanced[inst.meshId] = true;
  for (size_t i = 0; i < scene.meshes.size(); ++i)
    if (instanced[i])
      for (uint32_t m : scene.meshes[i].triangleMaterials)
        if (m < emissive.size() && emissive[m]) return true;
  return false;
}

void frameSceneBounds(Scene& scene) {
  // A mesh of one instance contributes its vertices (and its curves' control points); a mesh of many, the corners
  // of its box at each instance, so that a mesh instanced thousands of times is framed in time proportional to its
  // size and its instances.
  auto eachPoint = [](const Mesh& mesh, auto&& take) {
    for (Vec3 p : mesh.positions) take(p);
    for (const Vec4& v : mesh.curveVertices) take(Vec3{v.x, v.y, v.z});
  };
  std::vector<uint32_t> instances(scene.meshes.size());
  for (const Instance& inst : scene.instances) ++instances[inst.meshId];
  std::vector<Bounds3> meshBounds(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (instances[m] > 1) eachPoint(scene.meshes[m], [&](Vec3 p) { meshBounds[m].extend(p); });
  Bounds3 bounds;
  for (const Instance& inst : scene.instances) {
    if (instances[inst.meshId] == 1) {
      eachPoint(scene.meshes[inst.meshId], [&](Vec3 p) { bounds.extend(inst.objectToWorld.point(p)); });
      continue;
    }
    const Bounds3& box = meshBounds[inst.meshId];
    if (box.empty()) continue;
    for (int corner = 0; corner < 8; ++corner)
      bounds.extend(inst.objectToWorld.point(
          {corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y, corner & 4 ? box.hi.z : box.lo.z}));
  }
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
  scene.cameraIndex = -1;
  scene.cameraMissing = false;
}

namespace {

// A line on stderr every few seconds while a long load runs: how long, how much memory, and what it is making.
class LoadProgressLines {
 public:
  LoadProgressLines(const std::string& spec, bool print) : print_(print) {
    if (!print_) return;
    setLoadProgressListener([spec](const LoadProgress& p) {
      std::fprintf(stderr, "candela: loading %s: %s, about %s so far (%s: %s)\n", printableText(spec).c_str(),
                   formatSeconds(p.seconds).c_str(), memorySizeText(p.charged).c_str(), printableText(p.file).c_str(),
                   printableText(p.element).c_str());
    });
  }
  ~LoadProgressLines() {
    if (print_) setLoadProgressListener({});
  }
  LoadProgressLines(const LoadProgressLines&) = delete;
  LoadProgressLines& operator=(const LoadProgressLines&) = delete;

 private:
  bool print_;
};

}  // namespace

Scene loadScene(const std::string& spec, const SceneLoadOptions& options) {
  Scene scene;
  LoadWarnings warnings;
  setTextureLimits(options.textureLimits);
  beginLoadBudget();
  LoadProgressLines progress(spec, options.printWarnings);
  if (!makeBuiltinScene(spec, scene))
    scene = withMemoryReported(spec, [&] { return loadFile(spec, options, warnings); });
  fitSceneTextures(scene, options.textureLimits, warnings);
  if (!options.environmentPath.empty()) {
    Environment env;
    const std::string& map = options.environmentPath;
    env.map = withMemoryReported(map, [&] { return loadEnvironmentImage(map); });
    scene.environment = std::move(env);
  }
  chooseCamera(scene, spec, options.camera, warnings);  // first, so that the repair checks the camera taken
  repairScene(scene, spec, warnings);
  if (!hasLightSource(scene))
    warnings.add(spec,
                 "the scene has no light source (no emissive surface or medium, punctual light or environment): the "
                 "image will be black; light it with --env");
  if (options.printWarnings)
    for (const std::string& w : warnings.messages)
      std::fprintf(stderr, "candela: warning: %s\n", printableText(w).c_str());
  if (scene.cameraMissing) frameSceneBounds(scene);
  return scene;
}

}  // namespace candela
