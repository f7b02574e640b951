#pragma once
#include <tiny_gltf.h>

#include <functional>
#include <optional>
#include <string>

#include "io/load_diagnostics.h"
#include "scene/scene.h"

namespace candela {

// KHR_texture_transform as a 2x3 matrix: uv' = (m[0] u + m[1] v + m[2], m[3] u + m[4] v + m[5]).
struct UvTransform {
  float m[6] = {1, 0, 0, 0, 1, 0};
  bool operator==(const UvTransform& o) const;
  Vec2 apply(Vec2 uv) const { return {m[0] * uv.x + m[1] * uv.y + m[2], m[3] * uv.x + m[4] * uv.y + m[5]}; }
};

struct GltfMaterial {
  Material material;
  // The transform of the material's textures, when it has one (all its textures must agree); the loader bakes it
  // into the texture coordinates of the primitives that use the material.
  std::optional<UvTransform> uvTransform;
  // The TEXCOORD set the material's textures read (all must agree, else 0 with a warning); the loader gives
  // the primitives that use the material that set as their texture coordinates.
  int texCoord = 0;
};

// Returns a texture id for glTF textures[index] (its image, sampler wrap mode and colour encoding), or kNoTexture.
using GltfTextureResolver = std::function<int32_t(int index, bool srgb)>;
// The mean texel of glTF textures[index] (linear RGBA; sRGB colours decoded where `srgb`), or nothing where its
// image cannot be read.
using GltfTextureMean = std::function<std::optional<Vec4>(int index, bool srgb)>;

// Maps glTF materials[index]:
//   metallic-roughness (the core model)                                  -> Pbr
//   with KHR_materials_transmission, _ior, _clearcoat, _sheen, _specular or _anisotropy -> Disney
// (anisotropy: the strength stretches the lobe along the tangent as glTF's does, up to Disney's widest stretch;
// its rotation and texture are ignored with a warning)
// KHR_materials_iridescence puts a thin film over the specular lobe of either model, with its textures.
// emissiveFactor times KHR_materials_emissive_strength is the emitted radiance; alphaMode, alphaCutoff and
// doubleSided are kept. The base colour, metallic-roughness, normal and emissive textures are used; occlusion
// maps are left out on purpose (a path tracer computes occlusion), and the other extension textures
// (transmission, clearcoat, sheen, specular) have no slot: each of those gives a warning. A texture transform is
// returned for baking when all textures of the material share it, and ignored with a warning otherwise; likewise the
// TEXCOORD set. KHR_materials_unlit becomes a black surface emitting the base colour.
// KHR_materials_pbrSpecularGlossiness becomes Pbr (gltf_specular_glossiness.h): the diffuse texture is the base
// colour texture, scaled so that its mean converts as the factors do; the specular-glossiness texture cannot be
// converted texel by texel and is reduced to its mean (`textureMean`), with a warning.
GltfMaterial materialFromGltf(const tinygltf::Model& model, int index, const std::string& file,
                              const GltfTextureResolver& texture, const GltfTextureMean& textureMean,
                              LoadWarnings& warnings);

}  // namespace candela
