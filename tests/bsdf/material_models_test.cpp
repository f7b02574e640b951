// The list of models (CANDELA_MATERIAL_MODELS, kernel/material.h) drives everything that names them: the type
// tags, the Bsdf's construction and dispatch, the flags the kernel and the scene ask of a material, the names of
// scene files and --shading.
#include <gtest/gtest.h>

#include <iterator>
#include <set>
#include <string>

#include "core/rng.h"
#include "kernel/aovs.h"
#include "kernel/bsdf/bsdf.h"
#include "kernel/bsdf/material_models.h"
#include "kernel/bsdf/material_type_names.h"
#include "kernel/pass_through.h"
#include "scene/material_overrides.h"
#include "support/vector_expectations.h"

namespace candela::test {
namespace {

// The scene cache and device buffers store these values: the existing ones never move.
static_assert(uint32_t(MaterialType::Diffuse) == 0 && uint32_t(MaterialType::BlinnPhong) == 1 &&
              uint32_t(MaterialType::Pbr) == 2 && uint32_t(MaterialType::Disney) == 3 &&
              uint32_t(MaterialType::Mirror) == 4 && uint32_t(MaterialType::Glass) == 5);

// The list's models are numbered 0, 1, 2, ... in its order.
constexpr MaterialType kListed[] = {
#define LISTED_TYPE(type, Model, name, shadingName) MaterialType::type,
    CANDELA_MATERIAL_MODELS(LISTED_TYPE)
#undef LISTED_TYPE
};
static_assert(std::size(kListed) == kMaterialModelCount);
constexpr bool listedInOrder() {
  for (uint32_t i = 0; i < kMaterialModelCount; ++i)
    if (uint32_t(kListed[i]) != i) return false;
  return true;
}
static_assert(listedInOrder());

TEST(MaterialModels, EveryNameRoundTripsThroughItsType) {
  std::set<std::string> names;
  for (const MaterialModelNames& model : kMaterialModelNames) {
    ASSERT_NE(model.name, nullptr);
    EXPECT_TRUE(names.insert(model.name).second) << model.name << " names two models";
    EXPECT_EQ(materialTypeNamed(model.name), model.type) << model.name;
    EXPECT_STREQ(materialTypeName(model.type), model.name);
  }
  EXPECT_EQ(names.size(), size_t(kMaterialModelCount));
  EXPECT_EQ(materialTypeName(MaterialType::Mix), nullptr);
  EXPECT_EQ(materialTypeNamed("mix"), std::nullopt);
  EXPECT_EQ(materialTypeNamed("velvet"), std::nullopt);
  EXPECT_EQ(materialTypeNameList(), "diffuse, blinn-phong, pbr, disney, mirror, glass, diffuse-transmission, hair");
}

// Each model --shading offers is chosen by its shading name and switches a material to its type.
TEST(MaterialModels, EveryShadingNameSelectsItsModel) {
  int offered = 0;
  for (const MaterialModelNames& model : kMaterialModelNames) {
    if (!model.shadingName) continue;
    ++offered;
    MaterialOverrides overrides;
    overrides.shading = parseShadingModel(model.shadingName);
    EXPECT_NE(overrides.shading, ShadingModel::Own);
    EXPECT_STREQ(shadingModelName(overrides.shading), model.shadingName) << "the name the page and checkpoints use";
    Material m;
    m.type = MaterialType::Pbr;
    EXPECT_EQ(applyOverrides(m, overrides).type, model.type) << model.shadingName;
  }
  EXPECT_EQ(offered, 3);
  EXPECT_EQ(parseShadingModel("phong"), ShadingModel::BlinnPhong);
  EXPECT_EQ(parseShadingModel("pbr"), ShadingModel::Pbr);
  EXPECT_EQ(parseShadingModel("disney"), ShadingModel::Disney);
  EXPECT_STREQ(shadingModelName(ShadingModel::Own), "own");
  EXPECT_EQ(shadingModelNames().size(), size_t(ShadingModel::Disney) + 1);
  try {
    parseShadingModel("glass");
    ADD_FAILURE() << "glass is not a shading choice";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown shading model 'glass' (phong, pbr or disney)");
  }
}

// A material of `type` whose lobes include every kind its model has: transmission and anisotropy where it can.
Material materialOfType(MaterialType type) {
  Material m;
  m.type = type;
  m.baseColor = {0.7f, 0.5f, 0.3f};
  m.specularColor = {0.3f, 0.3f, 0.3f};
  m.metallic = 0.2f;
  m.roughness = 0.4f;
  m.specTrans = 0.5f;
  m.anisotropic = 0.5f;
  return m;
}

// The Bsdf built for each type is that type's model, built by fromMaterial, and reports its flags; so do the
// material-level questions the kernel and the scene ask before a Bsdf is built.
template <class Model>
void expectBsdfIsModel(MaterialType type) {
  SCOPED_TRACE(materialTypeName(type));
  const Material m = materialOfType(type);
  SurfaceInteraction si;
  si.geometricNormal = si.shadingNormal = {0, 0, 1};
  si.tangent = {1, 0, 0};
  si.uv = {0.3f, 0.7f};
  const Vec3 wo = normalize(Vec3{0.3f, -0.2f, 0.9f});
  const Bsdf bsdf(m, si, wo);  // the local frame is the world's
  const Model model = Model::fromMaterial(m, m.ior, si.uv);

  EXPECT_EQ(bsdf.isDelta(), Model::kDelta);
  EXPECT_EQ(bsdf.hasTransmission(), model.hasTransmission());
  EXPECT_EQ(isDeltaModel(type), Model::kDelta);
  EXPECT_EQ(isSpecularMaterial(m), Model::kDelta);
  EXPECT_EQ(isTransmissive(m), Model::transmits(m));
  EXPECT_EQ(isOrientedByTangent(m), Model::orientedByTangent(m));
  for (uint32_t i = 0; i < 64; ++i) {
    const float uChoice = randomUniform(i, 0, 0, 17);
    const Vec2 u{randomUniform(i, 0, 1, 17), randomUniform(i, 0, 2, 17)};
    const BsdfSample a = bsdf.sample(wo, uChoice, u), b = model.sample(wo, uChoice, u);
    ASSERT_EQ(a.valid, b.valid);
    if (!a.valid) continue;
    EXPECT_EQ(a.pdf, b.pdf);
    EXPECT_EQ(a.f.x, b.f.x);
    EXPECT_EQ(a.isDelta, b.isDelta);
    if (b.isDelta) continue;
    const BsdfEval e = bsdf.evalPdf(wo, a.wi), f = model.evalPdf(wo, b.wi);
    EXPECT_EQ(e.pdf, f.pdf);
    EXPECT_EQ(e.f.y, f.f.y);
  }
}

TEST(MaterialModels, EveryTypeBuildsItsModelWithItsFlags) {
#define EXPECT_BSDF_IS_MODEL(type, Model, name, shadingName) expectBsdfIsModel<Model>(MaterialType::type);
  CANDELA_MATERIAL_MODELS(EXPECT_BSDF_IS_MODEL)
#undef EXPECT_BSDF_IS_MODEL
}

// The flags of today's models, as the kernel relies on them. A hair fibre scatters all round, so a surface of it
// always lets light through.
TEST(MaterialModels, DeltaAndTransmittingModels) {
  for (uint32_t t = 0; t < kMaterialModelCount; ++t) {
    const MaterialType type = MaterialType(t);
    const bool mirrorOrGlass = type == MaterialType::Mirror || type == MaterialType::Glass;
    EXPECT_EQ(isDeltaModel(type), mirrorOrGlass) << materialTypeName(type);
    Material opaque = materialOfType(type);
    opaque.specTrans = 0.0f;
    EXPECT_EQ(isTransmissive(opaque), type == MaterialType::Glass || type == MaterialType::Hair)
        << materialTypeName(type);
    EXPECT_EQ(isTransmissive(materialOfType(type)),
              type == MaterialType::Glass || type == MaterialType::Disney || type == MaterialType::Hair)
        << materialTypeName(type);
  }
  EXPECT_FALSE(isDeltaModel(MaterialType::Mix));
}

// A mix is resolved before a Bsdf is built; one built for it anyway scatters as a diffuse surface.
TEST(MaterialModels, MixIsNoModel) {
  Material mix = materialOfType(MaterialType::Mix);
  SurfaceInteraction si;
  si.geometricNormal = si.shadingNormal = {0, 0, 1};
  const Vec3 wo{0, 0, 1}, wi = normalize(Vec3{0.5f, 0.0f, 1.0f});
  const Bsdf bsdf(mix, si, wo);
  EXPECT_FALSE(bsdf.isDelta());
  EXPECT_FALSE(bsdf.hasTransmission());
  EXPECT_EQ(bsdf.eval(wo, wi).x, mix.baseColor.x * kInvPi);
  EXPECT_FALSE(isTransmissive(mix));
  EXPECT_FALSE(isOrientedByTangent(mix));
}

// Each model gives the albedo guide its own reflectance: the sum of its lobes' colours where it has several, the
// colour hair's absorption gives; clamped to [0, 1].
TEST(MaterialModels, EachModelGivesTheAlbedoGuideItsReflectance) {
  for (uint32_t t = 0; t < kMaterialModelCount; ++t) {
    Material m = materialOfType(MaterialType(t));
    m.baseColor = {0.25f, 0.5f, 0.75f};
    m.specularColor = {0.5f, 0.125f, 0.5f};
    m.transmittance = {0.125f, 0.25f, 0.0f};
    const Vec3 albedo = materialAlbedo(m);
    SCOPED_TRACE(materialTypeName(m.type));
    switch (m.type) {
      case MaterialType::BlinnPhong:
        expectNear(albedo, Vec3{0.75f, 0.625f, 1.0f}, 0.0f);  // 0.75 + 0.5 clamped to 1
        break;
      case MaterialType::DiffuseTransmission: expectNear(albedo, Vec3{0.375f, 0.75f, 0.75f}, 0.0f); break;
      case MaterialType::Hair:
        expectNear(albedo, HairBsdf::reflectanceOfAbsorption(m.fibreAbsorption, m.azimuthalRoughness), 0.0f);
        break;
      default: expectNear(albedo, m.baseColor, 0.0f);
    }
  }
  Material bright = materialOfType(MaterialType::Pbr);
  bright.baseColor = {2.0f, -1.0f, 0.5f};
  expectNear(materialAlbedo(bright), {1.0f, 0.0f, 0.5f}, 0.0f);
}

// The GPU's lean kernel has the models the viewers switch between, diffuse, mirror, glass and a mix; the CPU's
// kernel, compiled in full, has every model.
TEST(MaterialModels, TheLeanKernelHasTheViewersModelsAndTheSimpleOnes) {
  for (uint32_t t = 0; t <= kMaterialModelCount; ++t) {
    const MaterialType type = MaterialType(t);
    const bool lean = type != MaterialType::DiffuseTransmission && type != MaterialType::Hair;
    EXPECT_EQ(isLeanKernelModel(type), lean) << t;
    EXPECT_TRUE(kernelHasModel(type)) << t;
  }
  Material film = materialOfType(MaterialType::Pbr);
  EXPECT_TRUE(leanKernelRenders(film));
  film.iridescence = 1.0f;
  EXPECT_FALSE(leanKernelRenders(film));
  EXPECT_FALSE(leanKernelRenders(materialOfType(MaterialType::Hair)));
}

}  // namespace
}  // namespace candela::test
