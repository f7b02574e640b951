// Texture lookups, generated tangents and the material overrides.
#include <gtest/gtest.h>

#include <stdexcept>

#include "kernel/bsdf/blinn_phong.h"
#include "kernel/textured_material.h"
#include "scene/flat_scene.h"
#include "scene/material_overrides.h"
#include "scene/mesh_builders.h"
#include "scene/tangents.h"

namespace candela {
namespace {

// A 2 x 2 grey 8-bit texture with texels 0, 51, 102, 255 (row 0 first).
struct SmallTexture {
  std::vector<uint8_t> bytes = {0, 51, 102, 255};
  TextureView view;
  TexelArrays arrays;
  explicit SmallTexture(TextureWrap wrap, bool srgb = false) {
    view.width = view.height = 2;
    view.channels = 1;
    view.wrapU = view.wrapV = wrap;
    view.srgb = srgb ? 1u : 0u;
    arrays = {&view, 1, bytes.data(), nullptr};
  }
  float at(float u, float v) const { return sampleTexture(arrays, 0, {u, v}).x; }
};

TEST(Texture, TexelCentresReturnTheTexels) {
  SmallTexture t(TextureWrap::Clamp);
  EXPECT_FLOAT_EQ(t.at(0.25f, 0.25f), 0.0f);
  EXPECT_FLOAT_EQ(t.at(0.75f, 0.25f), 0.2f);
  EXPECT_FLOAT_EQ(t.at(0.25f, 0.75f), 0.4f);
  EXPECT_FLOAT_EQ(t.at(0.75f, 0.75f), 1.0f);
}

TEST(Texture, BilinearBetweenCentres) {
  SmallTexture t(TextureWrap::Clamp);
  EXPECT_NEAR(t.at(0.5f, 0.5f), (0.0f + 0.2f + 0.4f + 1.0f) / 4, 1e-6f);
  EXPECT_NEAR(t.at(0.5f, 0.25f), 0.1f, 1e-6f);
}

TEST(Texture, WrapModes) {
  // Half a texel left of the left edge: repeat blends with the right column, clamp and mirror stay on the left.
  SmallTexture repeat(TextureWrap::Repeat), clamp(TextureWrap::Clamp), mirror(TextureWrap::Mirror);
  EXPECT_NEAR(repeat.at(0.0f, 0.25f), 0.1f, 1e-6f);
  EXPECT_NEAR(clamp.at(0.0f, 0.25f), 0.0f, 1e-6f);
  EXPECT_NEAR(mirror.at(0.0f, 0.25f), 0.0f, 1e-6f);
  // One period on: repeat is periodic; mirror reflects (u = 1.25 lands on the texel at u = 0.75).
  EXPECT_NEAR(repeat.at(1.25f, 0.25f), repeat.at(0.25f, 0.25f), 1e-6f);
  EXPECT_NEAR(mirror.at(1.25f, 0.25f), mirror.at(0.75f, 0.25f), 1e-6f);
  EXPECT_NEAR(mirror.at(-0.25f, 0.25f), mirror.at(0.25f, 0.25f), 1e-6f);
  EXPECT_NEAR(clamp.at(7.0f, 0.75f), 1.0f, 1e-6f);
  EXPECT_NEAR(repeat.at(-1e30f, 0.25f), repeat.at(-1e30f, 0.25f), 0.0f);  // no overflow, no NaN
}

TEST(Texture, WrapModesArePerAxis) {
  // Repeat across, clamp down: half a texel past the left edge blends with the right column, half a texel above
  // the top edge stays on the top row.
  SmallTexture t(TextureWrap::Repeat);
  t.view.wrapV = TextureWrap::Clamp;
  EXPECT_NEAR(t.at(0.0f, 0.25f), 0.1f, 1e-6f);
  EXPECT_NEAR(t.at(0.25f, 0.0f), 0.0f, 1e-6f);
  EXPECT_NEAR(t.at(0.25f, 1.25f), 0.4f, 1e-6f);  // clamped to the bottom row, not repeated to the top
  t.view.wrapU = TextureWrap::Clamp;
  t.view.wrapV = TextureWrap::Repeat;
  EXPECT_NEAR(t.at(0.25f, 0.0f), 0.2f, 1e-6f);
  EXPECT_NEAR(t.at(1.25f, 0.25f), 0.2f, 1e-6f);
}

TEST(Texture, SrgbDecodesColourButNotAlpha) {
  std::vector<uint8_t> bytes = {188, 188, 188, 188};
  TextureView view;
  view.width = view.height = 1;
  view.srgb = 1;
  TexelArrays arrays{&view, 1, bytes.data(), nullptr};
  Vec4 c = sampleTexture(arrays, 0, {0.5f, 0.5f});
  EXPECT_NEAR(c.x, 0.5029f, 1e-3f);  // sRGB 188/255 is linear 0.503
  EXPECT_NEAR(c.w, 188.0f / 255.0f, 1e-6f);
}

TEST(Texture, FloatTexturesAndChannelExpansion) {
  std::vector<float> floats = {2.5f, 0.25f};
  TextureView view;
  view.width = view.height = 1;
  view.channels = 2;
  view.format = TexelFormat::Float32;
  TexelArrays arrays{&view, 1, nullptr, floats.data()};
  Vec4 c = sampleTexture(arrays, 0, {0.3f, 0.6f});
  EXPECT_EQ(c.x, 2.5f);
  EXPECT_EQ(c.z, 2.5f);
  EXPECT_EQ(c.w, 0.25f);
}

TEST(Texture, MaterialFactorsMultiplyTexels) {
  Scene scene;
  Texture mr;
  mr.width = mr.height = 1;
  mr.channels = 3;
  mr.bytes = {0, 128, 255};  // glTF packing: G roughness, B metallic
  scene.textures.push_back(mr);
  Material m;
  m.metallicRoughnessTexture = 0;
  m.roughness = 0.5f;
  m.metallic = 0.8f;
  Scene withMesh = scene;
  withMesh.materials = {m};
  FlatScene built = FlatScene::build(withMesh);
  SurfaceInteraction at;
  at.uv = {0.5f, 0.5f};
  Material e = evaluateMaterial(built.hostView(), m, at);
  EXPECT_NEAR(e.roughness, 0.5f * 128.0f / 255.0f, 1e-6f);
  EXPECT_NEAR(e.metallic, 0.8f, 1e-6f);
}

// glTF COLOR_0: the interpolated vertex colour multiplies the base colour; meshes without colours stay white.
TEST(Texture, VertexColoursMultiplyTheBaseColour) {
  Scene scene;
  Mesh coloured;
  coloured.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  coloured.indices = {0, 1, 2};
  coloured.triangleMaterials = {0};
  coloured.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Mesh plain = coloured;
  plain.colors.clear();
  scene.meshes = {plain, coloured};
  scene.instances = {{0, Affine3x4{}}, {1, Affine3x4{}}};
  Material m;
  m.baseColor = {0.5f, 0.5f, 0.5f};
  scene.materials = {m};
  FlatScene built = FlatScene::build(scene);
  SceneView view = built.hostView();
  Hit hit;
  hit.b1 = 0.25f;
  hit.b2 = 0.5f;
  hit.instanceId = 1;
  Material e = evaluateMaterial(view, m, makeInteraction(view, hit, Ray{}));
  EXPECT_NEAR(e.baseColor.x, 0.5f * 0.25f, 1e-6f);
  EXPECT_NEAR(e.baseColor.y, 0.5f * 0.25f, 1e-6f);
  EXPECT_NEAR(e.baseColor.z, 0.5f * 0.5f, 1e-6f);
  hit.instanceId = 0;
  e = evaluateMaterial(view, m, makeInteraction(view, hit, Ray{}));
  EXPECT_FLOAT_EQ(e.baseColor.x, 0.5f);
  EXPECT_FLOAT_EQ(e.baseColor.z, 0.5f);
}

Mesh quadWithUvs(bool mirrored) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  // v runs down the image: the top of the quad (y = 1) is v = 0.
  mesh.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  if (mirrored)
    for (Vec2& uv : mesh.uvs) uv.x = 1 - uv.x;
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.triangleMaterials = {0, 0};
  return mesh;
}

TEST(Tangents, FollowUAndMarkMirroredMapping) {
  for (const Vec4& t : generateTangents(quadWithUvs(false))) {
    EXPECT_NEAR(t.x, 1.0f, 1e-6f);
    EXPECT_NEAR(t.y, 0.0f, 1e-6f);
    EXPECT_EQ(t.w, 1.0f);  // bitangent = cross(n, t) = +y: towards the top of the image
  }
  for (const Vec4& t : generateTangents(quadWithUvs(true))) {
    EXPECT_NEAR(t.x, -1.0f, 1e-6f);
    EXPECT_EQ(t.w, -1.0f);  // sign * cross(n, t) = +y still
  }
}

TEST(Tangents, PerpendicularToTheNormalsOfACurvedMesh) {
  Mesh sphere = makeUvSphere(1.0f, 16, 8, 0, false);
  for (size_t i = 0; i < sphere.positions.size(); ++i) {
    const Vec3& p = sphere.positions[i];
    sphere.uvs.push_back({std::atan2(p.z, p.x) / (2 * kPi) + 0.5f, std::acos(p.y) / kPi});
  }
  std::vector<Vec4> tangents = generateTangents(sphere);
  for (size_t i = 0; i < tangents.size(); ++i) {
    Vec3 t{tangents[i].x, tangents[i].y, tangents[i].z};
    EXPECT_NEAR(length(t), 1.0f, 1e-4f);
    EXPECT_NEAR(dot(t, sphere.normals[i]), 0.0f, 1e-4f);
  }
}

TEST(MaterialOverrides, RejectsUnknownNamesAndOutOfRangeValues) {
  MaterialOverrides o;
  EXPECT_THROW(parseOverride(o, "shininess=0.5"), std::invalid_argument);
  EXPECT_THROW(parseOverride(o, "roughness=1.5"), std::invalid_argument);
  EXPECT_THROW(parseOverride(o, "roughness=-0.1"), std::invalid_argument);
  EXPECT_THROW(parseOverride(o, "roughness=abc"), std::invalid_argument);
  EXPECT_THROW(parseOverride(o, "roughness=0.5x"), std::invalid_argument);
  EXPECT_THROW(parseOverride(o, "roughness"), std::invalid_argument);
  EXPECT_THROW(parseOverride(o, "roughness=nan"), std::invalid_argument);
  EXPECT_THROW(parseShadingModel("lambert"), std::invalid_argument);
  parseOverride(o, "clearcoatGloss=0.25");
  ASSERT_TRUE(o.clearcoatGloss.has_value());
  EXPECT_EQ(*o.clearcoatGloss, 0.25f);
}

TEST(MaterialOverrides, SwitchModelsAndReplaceParameters) {
  Material pbr;
  pbr.type = MaterialType::Pbr;
  pbr.baseColor = {0.8f, 0.4f, 0.2f};
  pbr.metallic = 0.5f;
  pbr.roughness = 0.3f;
  MaterialOverrides o;
  o.shading = ShadingModel::BlinnPhong;
  o.roughness = 0.5f;
  Material phong = applyOverrides(pbr, o);
  EXPECT_EQ(phong.type, MaterialType::BlinnPhong);
  EXPECT_NEAR(phong.shininess, roughnessToPhongExponent(0.5f), 1e-3f);
  EXPECT_NEAR(phong.baseColor.x, 0.4f, 1e-6f);
  EXPECT_NEAR(phong.specularColor.x, 0.5f * 0.04f + 0.5f * 0.8f, 1e-6f);
  // And back: the exponent maps to the roughness it came from.
  MaterialOverrides toDisney;
  toDisney.shading = ShadingModel::Disney;
  Material back = applyOverrides(phong, toDisney);
  EXPECT_EQ(back.type, MaterialType::Disney);
  EXPECT_NEAR(back.roughness, 0.5f, 1e-3f);
  // Delta materials keep their model.
  Material mirror;
  mirror.type = MaterialType::Mirror;
  EXPECT_EQ(applyOverrides(mirror, o).type, MaterialType::Mirror);
  // A mix stays one: the materials it mixes, in the same list, take the overrides.
  Material mix;
  mix.type = MaterialType::Mix;
  mix.mixedMaterials[1] = 3;
  std::vector<Material> materials = {mix, pbr};
  applyOverrides(materials, o);
  EXPECT_EQ(materials[0].type, MaterialType::Mix);
  EXPECT_EQ(materials[0].mixedMaterials[1], 3u);
  EXPECT_EQ(materials[1].type, MaterialType::BlinnPhong);
  // Every parameter the viewer can bind reaches the material.
  MaterialOverrides all;
  for (const OverrideParameter& p : overrideParameters()) setOverride(all, p.name, 0.625f);
  Material d = applyOverrides(Material{}, all);
  for (const OverrideParameter& p : overrideParameters()) EXPECT_EQ(d.*p.materialField, 0.625f) << p.name;
}

}  // namespace
}  // namespace candela
