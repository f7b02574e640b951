#pragma once
#include <string>

#include "io/path_confinement.h"
#include "scene/cache/scene_cache.h"
#include "scene/loaders/texture_limits.h"
#include "scene/scene.h"

namespace candela {

struct SceneLoadOptions {
  std::string environmentPath;    // an .hdr or .exr map that replaces the scene's environment; empty: keep it
  SceneCacheSettings cache = {};  // for models (.obj, .gltf, .glb, .pbrt) and scene files (as a whole)
  // Whether models and scene files may refer to files outside their folders (path_confinement.h). Models are
  // then loaded afresh: the scene cache holds only what loads under the default rule.
  OutsidePaths outsidePaths = OutsidePaths::Refused;
  std::string camera = {};           // the name or index (in Scene::cameras) of the camera to take; empty: the first
  TextureLimits textureLimits = {};  // textures over them are decoded smaller, with a warning
  bool printWarnings = true;         // false: only one of the processes of a distributed render prints them
};

// A built-in scene name or a scene file (.obj, .gltf, .glb, .pbrt, .json), chosen by extension, repaired
// (repairScene: unusable triangles and instances dropped, radiance clamped, the camera checked). Warnings go to
// stderr, one line each. A scene without a camera gets one that frames its bounds; of a file's several cameras
// the first is taken, with a warning that names it, unless options.camera names another. A scene with nothing
// that emits light is a warning. Throws std::runtime_error with one line naming the file on failure, running out
// of memory included.
Scene loadScene(const std::string& spec, const SceneLoadOptions& options = {});

// Whether anything in the scene emits: an emissive material, a punctual light, the environment or a medium.
bool hasLightSource(const Scene& scene);

// Places the camera outside the scene's bounds, looking at their centre slightly from above, far enough back
// that the bounding sphere fits the vertical field of view.
void frameSceneBounds(Scene& scene);

}  // namespace candela
