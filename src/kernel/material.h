#pragma once
#include <cstdint>

#include "core/math.h"

namespace candela {

// The shading models, in one list, from which everything that names them is generated: MaterialType below, the
// Bsdf's union of models, its construction and dispatch (kernel/bsdf/bsdf.h), what a material's model says about
// it before a Bsdf is built (kernel/bsdf/material_models.h) and the names of scene files and --shading
// (kernel/bsdf/material_type_names.h).
//
// To add a model: write its header (fromMaterial, flags, eval/pdf/evalPdf/sample; see "A model" below), add a
// line here and include the header in kernel/bsdf/material_models.h, add its parameters to Material below if it
// has new ones. A format that should produce the model sets the type in the one function that maps its
// materials (materialFromMtl, materialFromGltf, PbrtMaterials::translate, the scene file's materialType).
//
// X(type, Model, name, shadingName): the MaterialType enumerator; the model's class; its name in scene files (a
// material override's "type"); its name for --shading and the viewers' shading choice, or nullptr where they do
// not offer it (scene/material_overrides.h). The order gives MaterialType's values, which the scene cache and
// device buffers store: a new model goes last (a cache is read only by the build that wrote it).
#define CANDELA_MATERIAL_MODELS(X)                                                 \
  X(Diffuse, LambertianBsdf, "diffuse", nullptr)                                   \
  X(BlinnPhong, BlinnPhongBsdf, "blinn-phong", "phong")                            \
  X(Pbr, PbrBsdf, "pbr", "pbr")                                                    \
  X(Disney, DisneyBsdf, "disney", "disney")                                        \
  X(Mirror, MirrorBsdf, "mirror", nullptr)                                         \
  X(Glass, SmoothDielectricBsdf, "glass", nullptr)                                 \
  X(DiffuseTransmission, DiffuseTransmissionBsdf, "diffuse-transmission", nullptr) \
  X(Hair, HairBsdf, "hair", nullptr)

// A model is plain data (the Bsdf keeps one in a union) working in the local shading frame, with
//   static constexpr bool kDelta;                   only delta lobes, which light sampling cannot reach
//   bool hasTransmission() const;                   whether it can scatter to the far side of the surface
//   static bool transmits(const Material&);         whether a surface of the material can let light through to
//                                                   its other side: rays then meet both sides (pass_through.h)
//   static bool orientedByTangent(const Material&); whether its lobes turn with the surface's tangent, which the
//                                                   scene then provides (anisotropy)
//   static constexpr bool kInLeanKernel;           whether the GPU's lean kernel has it (kernel/kernel_variant.h)
//   static Vec3 guideAlbedo(const Material&);       its reflectance for the denoisers' albedo guide: the colour its
//                                                   lobes scale light by at normal incidence
//   static Model fromMaterial(const Material&, float eta, Vec2 uv);  the model of a material with its textures
//                                                   applied, eta the relative index across the surface seen from
//                                                   wo, uv the surface's texture coordinates at the point (which
//                                                   hair takes its offset across the fibre from)
//   eval, pdf, evalPdf and sample, as LambertianBsdf's.

// The models of the list, then Mix; kernel code dispatches on this tag with a switch.
enum class MaterialType : uint32_t {
#define CANDELA_MATERIAL_TYPE_ENUMERATOR(type, Model, name, shadingName) type,
  CANDELA_MATERIAL_MODELS(CANDELA_MATERIAL_TYPE_ENUMERATOR)
#undef CANDELA_MATERIAL_TYPE_ENUMERATOR
  // Not a model: the scattering of one of two materials, chosen per shading point before a Bsdf is built
  // (chooseMixedMaterial in kernel/textured_material.h).
  Mix,
};

constexpr uint32_t kMaterialModelCount = uint32_t(MaterialType::Mix);

// How many mixes a chain of mixed materials may pass through before it reaches a material of another type:
// the kernel resolves a mix in a loop of at most this many steps, and scene validation rejects longer chains
// (and cycles).
constexpr uint32_t kMaxMixDepth = 8;

enum class AlphaMode : uint32_t { Opaque = 0, Mask, Blend };

constexpr int32_t kNoTexture = -1;

// The two materials of a mix (Material::mixedMaterials).
using MixedMaterials = uint32_t[2];

// Material's members, declared once: the struct below and the checks that scene validation (scene/scene.cpp) and the
// scene cache's (scene/cache/cached_scene_validation.cpp) make of them are generated from this list, so that a
// model's new parameter is one line here. The order is the struct's layout, which device buffers and the scene
// cache store (a change here changes the cache's layout: bump kCacheFormatVersion).
//
// X(Type, name, default, check), with `check`
//   Finite        a number or colour that must be finite
//   NonNegative   a colour that must be finite and at least 0 in every channel
//   TextureIndex  kNoTexture or the index of one of the scene's textures
//   ByHand        checked where it is used: the type, flags, the alpha mode and the mix's own members
#define CANDELA_MATERIAL_MEMBERS(X)                                                                               \
  X(MaterialType, type, MaterialType::Diffuse, ByHand)                                                            \
  X(Vec3, baseColor, (Vec3{0.8f, 0.8f, 0.8f}), Finite)                                                            \
  /* emitted radiance, W/(m^2 sr), already scaled by any strength factor */                                       \
  X(Vec3, emission, (Vec3{0.0f, 0.0f, 0.0f}), Finite)                                                             \
  /* Blinn-Phong and mirror */                                                                                    \
  X(Vec3, specularColor, (Vec3{0.04f, 0.04f, 0.04f}), Finite)                                                     \
  X(float, shininess, 32.0f, Finite)                                                                              \
  /* metallic-roughness and Disney */                                                                             \
  X(float, metallic, 0.0f, Finite)                                                                                \
  X(float, roughness, 0.5f, Finite)                                                                               \
  X(float, anisotropic, 0.0f, Finite)                                                                             \
  X(float, specular, 0.5f, Finite)                                                                                \
  X(float, specularTint, 0.0f, Finite)                                                                            \
  X(float, subsurface, 0.0f, Finite)                                                                              \
  X(float, sheen, 0.0f, Finite)                                                                                   \
  X(float, sheenTint, 0.5f, Finite)                                                                               \
  X(float, clearcoat, 0.0f, Finite)                                                                               \
  X(float, clearcoatGloss, 1.0f, Finite)                                                                          \
  X(float, specTrans, 0.0f, Finite)                                                                               \
  X(float, ior, 1.5f, Finite)                                                                                     \
  /* KHR_materials_iridescence: a thin dielectric film over the specular lobe (kernel/bsdf/thin_film.h), of       \
     strength `iridescence` (0: none), index iridescenceIor and a thickness in nanometres: iridescenceThickness   \
     without a thickness texture, else mix(iridescenceThicknessMinimum, iridescenceThickness, texel's G) */       \
  X(float, iridescence, 0.0f, Finite)                                                                             \
  X(float, iridescenceIor, 1.3f, Finite)                                                                          \
  X(float, iridescenceThickness, 400.0f, Finite)                                                                  \
  X(float, iridescenceThicknessMinimum, 100.0f, Finite)                                                           \
  /* inside a transmissive material: the absorption coefficient per unit of world length, per channel, by         \
     which light decays between entering and leaving a closed object (Beer-Lambert;                               \
     kernel/volume_absorption.h); zero: none, as for a thin-walled surface */                                     \
  X(Vec3, absorption, (Vec3{0.0f, 0.0f, 0.0f}), NonNegative)                                                      \
  /* diffuse transmission: the Lambertian transmittance to the far side (baseColor is the reflectance); zero,     \
     a diffuse reflector */                                                                                       \
  X(Vec3, transmittance, (Vec3{0.0f, 0.0f, 0.0f}), NonNegative)                                                   \
  /* hair (kernel/bsdf/hair.h), with `ior` the fibre's index and `roughness` its longitudinal roughness beta_m:   \
     the absorption inside the fibre per unit of its radius (pbrt-v4's sigma_a; by default pbrt's brown hair,     \
     eumelanin 1.3), the azimuthal roughness beta_n and the tilt of the cuticle's scales in degrees (alpha) */    \
  X(Vec3, fibreAbsorption, (Vec3{0.5447f, 0.9061f, 1.781f}), NonNegative)                                         \
  X(float, azimuthalRoughness, 0.3f, Finite)                                                                      \
  X(float, scaleTilt, 2.0f, Finite)                                                                               \
  /* pbrt's `interface` material: the surface only bounds participating media (the instances'                     \
     MediumInterface) and rays cross it unchanged. Its coverage is an alpha mask of opacity 0, so that the        \
     backends ask passesThrough about it: where a scene has no media it is a cut-out that lets every ray          \
     through; in a scene with media the integrator meets it and crosses it into the medium on the far side        \
     (kernel/pass_through.h) */                                                                                   \
  X(uint32_t, interfaceOnly, 0u, ByHand)                                                                          \
  /* coverage */                                                                                                  \
  X(AlphaMode, alphaMode, AlphaMode::Opaque, ByHand)                                                              \
  X(float, opacity, 1.0f, Finite)                                                                                 \
  X(float, alphaCutoff, 0.5f, Finite)                                                                             \
  X(uint32_t, doubleSided, 1u, ByHand)                                                                            \
  /* indices into the scene's textures, kNoTexture when absent */                                                 \
  X(int32_t, baseColorTexture, kNoTexture, TextureIndex)         /* sRGB; alpha channel multiplies opacity */     \
  X(int32_t, metallicRoughnessTexture, kNoTexture, TextureIndex) /* glTF packing: G = roughness, B = metallic */  \
  X(int32_t, roughnessTexture, kNoTexture, TextureIndex)         /* R */                                          \
  X(int32_t, metallicTexture, kNoTexture, TextureIndex)          /* R */                                          \
  X(int32_t, emissionTexture, kNoTexture, TextureIndex)          /* sRGB, multiplies emission */                  \
  X(int32_t, normalTexture, kNoTexture, TextureIndex)            /* tangent space */                              \
  X(int32_t, opacityTexture, kNoTexture, TextureIndex)           /* R */                                          \
  X(int32_t, iridescenceTexture, kNoTexture, TextureIndex)       /* R, multiplies iridescence */                  \
  /* G, between the minimum and maximum thickness */                                                              \
  X(int32_t, iridescenceThicknessTexture, kNoTexture, TextureIndex)                                               \
  /* mix: a shading point scatters as mixedMaterials[1] with probability mixAmount (times the R channel of        \
     mixAmountTexture), else as mixedMaterials[0], pbrt-v4's convention. Emission and coverage (alpha,            \
     culling) are the mix's own, as in pbrt, where both belong to the shape; the mixed materials' are not used */ \
  X(MixedMaterials, mixedMaterials, {}, ByHand)                                                                   \
  X(float, mixAmount, 0.5f, ByHand)                                                                               \
  X(int32_t, mixAmountTexture, kNoTexture, TextureIndex) /* R */

// Flat parameters that a device buffer can hold. Not every model reads every field.
struct Material {
#define CANDELA_MATERIAL_MEMBER(Type, name, value, check) Type name = value;
  CANDELA_MATERIAL_MEMBERS(CANDELA_MATERIAL_MEMBER)
#undef CANDELA_MATERIAL_MEMBER
};

}  // namespace candela
