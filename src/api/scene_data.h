#pragma once
#include "candela/scene.h"
#include "scene/scene.h"

namespace candela::api {

// What an api::Scene shares between its copies: the library's scene, loaded or built and repaired.
struct Scene::Data {
  candela::Scene scene;
};

}  // namespace candela::api
