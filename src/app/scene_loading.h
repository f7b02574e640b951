#pragma once
#include <string>

#include "scene/scene.h"

namespace candela {

// A built-in scene name or a scene file path. Throws std::runtime_error with one sentence on failure.
Scene loadScene(const std::string& spec);

}  // namespace candela
