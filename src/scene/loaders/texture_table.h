#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "io/load_diagnostics.h"
#include "io/path_confinement.h"
#include "scene/scene.h"

namespace candela {

// Collects the textures materials refer to, each distinct (source, encoding, wrap modes) once, and decodes them
// all at the end, in parallel. One table may serve all the models of a scene (shared_model_assets.h). Materials
// hold provisional indices until finish() rewrites them; a texture that is missing or unreadable gives a warning
// and leaves its materials untextured, and so does an image file its model may not read (path_confinement.h).
class TextureTable {
 public:
  // An image file (as confineModelPath resolved it for the model that names it: a refused one is a warning at
  // finish()), or an image already in memory (`bytes`) that `name` describes for messages. `key` names in-memory
  // bytes uniquely within the table (the file that embeds them and where).
  int32_t fromFile(const ResolvedPath& file, bool srgb, TextureWrap wrapU = TextureWrap::Repeat,
                   TextureWrap wrapV = TextureWrap::Repeat);
  int32_t fromMemory(const std::string& key, const std::string& name, std::vector<uint8_t> bytes, bool srgb,
                     TextureWrap wrapU = TextureWrap::Repeat, TextureWrap wrapV = TextureWrap::Repeat);

  // Decodes everything requested, appends the textures to `scene` (and their files to scene.inputFiles) and
  // points the texture fields of scene.materials[firstMaterial...] at them.
  void finish(Scene& scene, size_t firstMaterial, LoadWarnings& warnings);

 private:
  struct Request {
    std::string name;
    std::string path;     // empty when the bytes are in memory
    std::string refusal;  // why `path` may not be read (path_confinement.h); empty when it may
    std::vector<uint8_t> bytes;
    bool srgb = false;
    TextureWrap wrapU = TextureWrap::Repeat, wrapV = TextureWrap::Repeat;
  };
  int32_t add(const std::string& key, Request request);

  std::map<std::tuple<std::string, bool, TextureWrap, TextureWrap>, int32_t> index_;
  std::vector<Request> requests_;
};

}  // namespace candela
