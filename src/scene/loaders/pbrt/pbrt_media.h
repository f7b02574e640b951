#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "kernel/media/medium.h"
#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// pbrt-v4's named media: MakeNamedMedium defines them, MediumInterface and the camera refer to them by name, and
// pbrt resolves the names once the whole scene is read, so a name may be used before its definition. Each name
// gets a slot when first defined or used; `finish` turns the slots into the scene's media and says where each
// slot went: `homogeneous`, `uniformgrid`, `rgbgrid`, `cloud` and `nanovdb` media (pbrt_grid_media.h).
class PbrtMedia {
 public:
  explicit PbrtMedia(PbrtContext& context) : context_(context) {}

  // MakeNamedMedium `name` with its parameters (`type` among them), under the transform `worldFromMedium`.
  void define(const std::string& name, const PbrtParameters& params, const glm::mat4& worldFromMedium);
  // The slot of medium `name`, used at file:line; kNoMedium for "" (vacuum).
  uint32_t slot(const std::string& name, const std::string& file, size_t line);
  // Moves the media into the scene; returns, per slot, the index in Scene::media. Throws
  // LoadError naming the first use of a medium never defined.
  std::vector<uint32_t> finish(Scene& scene);

 private:
  struct Slot {
    std::string name;
    std::string file;  // where it was first used, for the error if it is never defined
    size_t line = 0;
    bool defined = false;
    Medium medium;
  };
  uint32_t slotOf(const std::string& name);

  PbrtContext& context_;
  std::vector<Slot> slots_;
  std::map<std::string, uint32_t> byName_;
};

}  // namespace candela
