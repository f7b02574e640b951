#include "app/serve/web_assets.h"

namespace candela {

const WebAsset* findWebAsset(std::string_view target) {
  std::string_view path = target.substr(0, target.find('?'));
  if (path == "/") path = "/index.html";
  for (const WebAsset& asset : webAssets())
    if (asset.path == path) return &asset;
  return nullptr;
}

}  // namespace candela
