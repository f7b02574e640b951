#include "app/scene_loading.h"

#include <stdexcept>

#include "scene/builtin_scenes.h"

namespace candela {

Scene loadScene(const std::string& spec) {
  Scene scene;
  if (makeBuiltinScene(spec, scene)) return scene;
  std::string names;
  for (const std::string& n : builtinSceneNames()) names += (names.empty() ? "" : ", ") + n;
  throw std::runtime_error("unknown scene '" + spec + "' (built-in scenes: " + names + ")");
}

}  // namespace candela
