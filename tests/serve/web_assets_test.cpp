#include <gtest/gtest.h>

#include "app/serve/web_assets.h"

namespace candela {
namespace {

TEST(WebAssets, ThePagesFilesAreEmbedded) {
  for (const char* path : {"/", "/index.html", "/app.js", "/style.css", "/app.js?token=x"}) {
    const WebAsset* asset = findWebAsset(path);
    ASSERT_NE(asset, nullptr) << path;
    EXPECT_FALSE(asset->body.empty());
  }
  EXPECT_NE(findWebAsset("/")->body.find("<canvas"), std::string_view::npos);
  EXPECT_EQ(findWebAsset("/app.js")->contentType.substr(0, 15), "text/javascript");
}

TEST(WebAssets, NothingElseIsFound) {
  for (const char* path : {"", "/../../etc/passwd", "/%2e%2e/etc/passwd", "/index.html/..", "//index.html",
                           "/web/index.html", "/INDEX.HTML", "index.html", "/index.html%00"})
    EXPECT_EQ(findWebAsset(path), nullptr) << path;
}

}  // namespace
}  // namespace candela
