#pragma once
#include <string>

#include "scene/cache/scene_cache.h"
#include "scene/loaders/texture_limits.h"
#include "scene/scene.h"

namespace candela {

struct SceneLoadOptions {
  std::string environmentPath;  // an .hdr or .exr map that replaces the scene's environment; empty: keep it
  SceneCacheSettings cache = {};  // for the models (.obj, .gltf, .glb), also those a scene file names
  TextureLimits textureLimits = {};  // textures over them are decoded smaller, with a warning
};

// A built-in scene name or a scene file (.obj, .gltf, .glb, .json), chosen by extension. Warnings go to stderr,
// one line each. A scene without a camera gets one that frames its bounds. Throws std::runtime_error with one
// line naming the file on failure.
Scene loadScene(const std::string& spec, const SceneLoadOptions& options = {});

// Places the camera outside the scene's bounds, looking at their centre slightly from above, far enough back
// that the bounding sphere fits the vertical field of view.
void frameSceneBounds(Scene& scene);

}  // namespace candela
