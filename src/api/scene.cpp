#include "candela/scene.h"

#include "api/error_translation.h"
#include "api/scene_data.h"
#include "app/scene_loading.h"

namespace candela::api {

Scene::Scene(std::shared_ptr<const Data> data) : data_(std::move(data)) {}

Scene Scene::load(const std::string& spec, const LoadOptions& options) {
  return withErrorsTranslated("load", [&] {
    SceneLoadOptions load;
    load.environmentPath = options.environment;
    load.camera = options.camera;
    load.cache.enabled = options.cache;
    load.outsidePaths = options.allowOutsidePaths ? OutsidePaths::Allowed : OutsidePaths::Refused;
    return Scene(std::make_shared<const Data>(Data{loadScene(spec, load)}));
  });
}

std::string Scene::name() const { return data_->scene.name; }

size_t Scene::triangleCount() const { return data_->scene.triangleCount(); }

}  // namespace candela::api
