#pragma once
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "kernel/media/medium.h"
#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"
#include "scene/loaders/pbrt/pbrt_textures.h"

namespace candela {

// A pbrt material as a candela material: its id in the scene's list (for `mix`, a Mix over the two it mixes).
struct PbrtMaterial {
  uint32_t id = 0;
};

// Turns pbrt's materials into candela's models (docs/pbrt-v4.md lists how), appending them to the scene.
class PbrtMaterials {
 public:
  PbrtMaterials(PbrtContext& context, PbrtTextures& textures) : context_(context), textures_(textures) {}

  PbrtMaterial make(const std::string& type, const PbrtParameters& params);
  void defineNamed(const std::string& name, const PbrtParameters& params);  // MakeNamedMaterial ("string type")
  // A named material, or (after a warning naming file:line) the default when no such material was made.
  PbrtMaterial named(const std::string& name, const std::string& file, size_t line);
  bool isNamed(const std::string& name) const { return named_.count(name) > 0; }
  PbrtMaterial fallback();  // pbrt's default: diffuse 0.5

  // The uv mapping of a material's base colour texture, to be applied to the coordinates of its meshes.
  std::pair<Vec2, Vec2> uvMapping(uint32_t materialId) const;

  // The medium inside a `subsurface` material (pbrt_subsurface.h), which the loader puts inside the shapes of the
  // material (their MediumInterface's inside); null for other materials.
  const Medium* interior(uint32_t materialId) const;
  // `variant` is a copy of material `base` with another emission or alpha: it has base's interior.
  void noteVariant(uint32_t base, uint32_t variant);

 private:
  uint32_t add(const Material& m, const std::string& name, const PbrtTexture* baseTexture = nullptr);
  Material translate(const std::string& type, const PbrtParameters& params, const PbrtTexture*& baseTexture);
  PbrtMaterial makeMix(const PbrtParameters& params);

  PbrtContext& context_;
  PbrtTextures& textures_;
  std::map<std::string, PbrtMaterial> named_;
  std::map<uint32_t, std::pair<Vec2, Vec2>> uvMappings_;
  std::map<uint32_t, Medium> interiors_;
  std::optional<Medium> pendingInterior_;   // translate's subsurface interior, for make to key by the material's id
  std::map<uint32_t, uint32_t> mixDepths_;  // per mix: the most mixes a chain from it passes (kMaxMixDepth bounds it)
  std::optional<uint32_t> fallback_;
  std::string pendingName_;
  PbrtTexture baseTexture_;
};

}  // namespace candela
