#pragma once
#include <span>
#include <string_view>

namespace candela {

// The page's own files (src/app/serve/web), compiled into candela at build time (embed_web_assets.cmake). They
// are the only files the server hands out: no request reaches the file system.
struct WebAsset {
  std::string_view path;  // "/index.html"
  std::string_view contentType;
  std::string_view body;
};
std::span<const WebAsset> webAssets();

// The asset a request target names ("/" is "/index.html"; the query is ignored); nullptr for anything else.
const WebAsset* findWebAsset(std::string_view target);

}  // namespace candela
