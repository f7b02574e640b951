#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "scene/loaders/load_diagnostics.h"
#include "scene/loaders/path_confinement.h"
#include "scene/scene.h"

namespace candela {

// Collects the textures a file's materials refer to, each distinct (source, encoding, wrap) once, and decodes
// them all at the end, in parallel. Materials hold provisional indices until finish() rewrites them; a texture
// that is missing or unreadable gives a warning and leaves its materials untextured, and so does an image file
// outside the folder `rule` confines the model to (path_confinement.h).
class TextureTable {
 public:
  explicit TextureTable(PathRule rule) : rule_(std::move(rule)) {}

  // An image file, or an image already in memory (`bytes`) that `name` describes for messages.
  int32_t fromFile(const std::string& path, bool srgb, TextureWrap wrap = TextureWrap::Repeat);
  int32_t fromMemory(const std::string& key, const std::string& name, std::vector<uint8_t> bytes, bool srgb,
                     TextureWrap wrap = TextureWrap::Repeat);

  // Decodes everything requested, appends the textures to `scene` (and their files to scene.inputFiles) and
  // points the texture fields of scene.materials[firstMaterial...] at them.
  void finish(Scene& scene, size_t firstMaterial, LoadWarnings& warnings);

 private:
  struct Request {
    std::string name;
    std::string path;            // empty when the bytes are in memory
    std::string refusal;         // why `path` may not be read (path_confinement.h); empty when it may
    std::vector<uint8_t> bytes;
    bool srgb = false;
    TextureWrap wrap = TextureWrap::Repeat;
  };
  int32_t add(const std::string& key, Request request);

  PathRule rule_;
  std::map<std::tuple<std::string, bool, TextureWrap>, int32_t> index_;
  std::vector<Request> requests_;
};

}  // namespace candela
