#pragma once
#include <functional>
#include <string>

#include "io/load_diagnostics.h"
#include "io/path_confinement.h"
#include "scene/loaders/shared_model_assets.h"
#include "scene/scene.h"

namespace candela {

// Loads a JSON scene file (docs/scene-file.md describes the format): models (.obj, .gltf, .glb) with transforms
// and material overrides, a camera (thin lens included), an environment and render settings. Paths are relative
// to the scene file and must lead inside its folder unless `outside` allows others (path_confinement.h);
// absolute paths are taken as they are. `loadModel` loads one model file (the caller decides about caching, and
// about the rule for the model's own references); it may load every model with `shared` (material libraries
// parsed once, textures decoded once for the whole scene) or none. A file that several models name with the same
// material overrides is loaded once: the later models become instances of its meshes. Errors throw LoadError
// naming the file and the JSON path ("scene.json: models[1].transform.scale: expected a number or 3 numbers"),
// or the line and column of invalid JSON ("scene.json:3:7: invalid JSON: ...").
using ModelLoader = std::function<Scene(const std::string& path, LoadWarnings& warnings, SharedModelAssets& shared)>;
Scene loadSceneFile(const std::string& path, const ModelLoader& loadModel, LoadWarnings& warnings,
                    OutsidePaths outside = OutsidePaths::Refused);

// Appends `part` to `scene` under `transform`: meshes, materials and textures are renumbered; a texture `scene`
// already has (same source, encoding and wrap modes) is not added again; its cameras are added with their names
// after `cameraPrefix`; its animation joins the scene's (appendAnimation).
void appendScene(Scene& scene, Scene&& part, const Affine3x4& transform, const std::string& cameraPrefix);

}  // namespace candela
