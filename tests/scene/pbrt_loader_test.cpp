#include "scene/loaders/pbrt/pbrt_loader.h"

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

#include "app/render_job.h"
#include "app/scene_loading.h"
#include "io/available_memory.h"
#include "io/load_budget.h"
#include "io/load_diagnostics.h"
#include "scene/builtin_scenes.h"
#include "scene/loaders/pbrt/pbrt_lights.h"
#include "scene/loaders/pbrt/pbrt_spectra.h"
#include "scene/loaders/pbrt/pbrt_spectrum_files.h"
#include "scene/loaders/pbrt/pbrt_tokenizer.h"
#include "scene/loaders/texture_limits.h"
#include "scene/scene_test_files.h"
#include "support/pbrt_text.h"

namespace candela {
namespace {

using test::TempFolder;
using test::pbrt::loadError;
using test::pbrt::loadText;

void expectNear(Vec3 a, Vec3 b, float tolerance = 1e-4f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

Vec3 windingNormal(const Scene& scene, size_t instance, size_t triangle) {
  const Mesh& m = scene.meshes[scene.instances[instance].meshId];
  const Affine3x4& t = scene.instances[instance].objectToWorld;
  Vec3 a = m.positions[m.indices[3 * triangle]], b = m.positions[m.indices[3 * triangle + 1]];
  Vec3 c = m.positions[m.indices[3 * triangle + 2]];
  // The front as candela's lights take it (kernel/lights.h): the world-space winding, turned under mirroring
  // instances.
  Vec3 n = cross(t.point(b) - t.point(a), t.point(c) - t.point(a));
  return t.determinant() < 0 ? -n : n;
}

constexpr const char* kTriangle = R"(Shape "trianglemesh" "point3 P" [0 0 0  1 0 0  0 1 0] "integer indices" [0 1 2]
)";

// The camera of these scenes mirrors (as pbrt scenes customarily do), so candela's world is pbrt's.
constexpr const char* kMirroredCamera = "Scale -1 1 1\nCamera \"perspective\"\nWorldBegin\n";

TEST(PbrtTokenizer, SplitsWordsStringsBracketsAndSkipsComments) {
  PbrtTokenizer tokens("t.pbrt", "Shape # a comment\n\"tri\\\"angle\" [1 -2.5e1]\n");
  EXPECT_EQ(tokens.next().text, "Shape");
  PbrtToken s = tokens.next();
  EXPECT_EQ(s.kind, PbrtToken::Kind::String);
  EXPECT_EQ(s.text, "tri\"angle");
  EXPECT_EQ(s.line, 2u);
  EXPECT_EQ(tokens.next().kind, PbrtToken::Kind::OpenBracket);
  EXPECT_EQ(tokens.next().text, "1");
  EXPECT_EQ(tokens.next().text, "-2.5e1");
  EXPECT_EQ(tokens.next().kind, PbrtToken::Kind::CloseBracket);
  EXPECT_EQ(tokens.next().kind, PbrtToken::Kind::End);
}

TEST(PbrtLoader, ErrorsNameFileAndLine) {
  EXPECT_EQ(loadError("WorldBegin\n\nShpe \"sphere\"\n"), "test.pbrt:3: unknown directive 'Shpe'");
  EXPECT_EQ(loadError("WorldBegin\nShape \"sphere\" \"float radius\" [1\n"), "test.pbrt:2: unclosed '[' of 'radius'");
  EXPECT_EQ(loadError("WorldBegin\nShape \"sphere\" \"float radius\" [x]\n"),
            "test.pbrt:2: 'x' is not a number (value of 'radius')");
  EXPECT_EQ(loadError("WorldBegin\nMaterial \"diffuse\n\""), "test.pbrt:2: line break inside a string");
  EXPECT_EQ(loadError("AttributeEnd\n"), "test.pbrt:1: AttributeEnd without a matching begin");
  EXPECT_EQ(loadError(
                "WorldBegin\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 3]"),
            "test.pbrt:2: 'indices' refers to vertex 3 of 3");
}

TEST(PbrtLoader, TransformsApplyInPbrtsOrder) {
  // Translate then Scale: a point is scaled first, then translated (each directive post-multiplies).
  Scene scene = loadText(std::string(kMirroredCamera) + "Translate 1 0 0\nScale 2 2 2\n" + kTriangle);
  ASSERT_EQ(scene.instances.size(), 1u);
  expectNear(scene.instances[0].objectToWorld.point({1, 0, 0}), {3, 0, 0});
  Scene rotated = loadText(std::string(kMirroredCamera) + "Rotate 90 0 0 1\nTranslate 1 0 0\n" + kTriangle);
  expectNear(rotated.instances[0].objectToWorld.point({0, 0, 0}), {0, 1, 0});
  Scene matrix =
      loadText(std::string(kMirroredCamera) + "Transform [1 0 0 0  0 1 0 0  0 0 1 0  5 6 7 1]\n" + kTriangle);
  expectNear(matrix.instances[0].objectToWorld.point({0, 0, 0}), {5, 6, 7});
  Scene attributes = loadText(std::string(kMirroredCamera) + "AttributeBegin\nTranslate 9 0 0\nAttributeEnd\n" +
                              "TransformBegin\nTranslate 9 0 0\nTransformEnd\n" + kTriangle);
  expectNear(attributes.instances[0].objectToWorld.point({0, 0, 0}), {0, 0, 0});
  Scene named = loadText(std::string(kMirroredCamera) + "Translate 4 0 0\nCoordinateSystem \"here\"\nIdentity\n" +
                         "CoordSysTransform \"here\"\n" + kTriangle);
  expectNear(named.instances[0].objectToWorld.point({0, 0, 0}), {4, 0, 0});
}

TEST(PbrtLoader, MotionKeepsTheStartTransform) {
  LoadWarnings warnings;
  Scene scene = loadText(std::string(kMirroredCamera) +
                             "TransformTimes 0 1\nActiveTransform EndTime\nTranslate 5 0 0\nActiveTransform All\n"
                             "Translate 0 1 0\n" +
                             kTriangle,
                         &warnings);
  expectNear(scene.instances[0].objectToWorld.point({0, 0, 0}), {0, 1, 0});
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("motion blur"), std::string::npos);
}

TEST(PbrtLoader, LeftHandedCameraMirrorsTheWorldSoTheImageIsNotMirrored) {
  // pbrt's LookAt puts world +x on the right of the image for a camera looking down +z with +y up.
  Scene scene = loadText(
      "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" 60\nWorldBegin\n"
      "Translate 1 0 5\n" +
      std::string(kTriangle));
  Vec3 p = scene.instances[0].objectToWorld.point({0, 0, 0});
  Vec3 forward = normalize(scene.camera.target - scene.camera.eye);
  Vec3 right = cross(forward, scene.camera.up);  // candela's image right (Camera::lookAt)
  EXPECT_GT(dot(p - scene.camera.eye, right), 0.5f);
  EXPECT_FLOAT_EQ(scene.camera.verticalFovDegrees, 60.0f);
  // The same scene after pbrt's customary `Scale -1 1 1`: +x is now on the left.
  Scene flipped = loadText(
      "Scale -1 1 1\nLookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
      "Translate 1 0 5\n" +
      std::string(kTriangle));
  Vec3 q = flipped.instances[0].objectToWorld.point({0, 0, 0});
  Vec3 f2 = normalize(flipped.camera.target - flipped.camera.eye);
  EXPECT_LT(dot(q - flipped.camera.eye, cross(f2, flipped.camera.up)), -0.5f);
}

TEST(PbrtLoader, FieldOfViewSpansTheShorterImageAxis) {
  Scene portrait = loadText(
      "Film \"rgb\" \"integer xresolution\" 100 \"integer yresolution\" 200\n"
      "Camera \"perspective\" \"float fov\" 90\nWorldBegin\n");
  EXPECT_NEAR(portrait.camera.verticalFovDegrees, 2.0f * std::atan(2.0f) * 180.0f / kPi, 1e-3f);
  EXPECT_EQ(*portrait.renderHints.width, 100u);
  EXPECT_EQ(*portrait.renderHints.height, 200u);
}

TEST(PbrtLoader, SamplerAndIntegratorBecomeRenderHints) {
  Scene scene = loadText(
      "Sampler \"zsobol\" \"integer pixelsamples\" 256\nIntegrator \"volpath\" "
      "\"integer maxdepth\" 12\nCamera \"perspective\" \"float lensradius\" 0.1 "
      "\"float focaldistance\" 3\nWorldBegin\n");
  EXPECT_EQ(*scene.renderHints.samplesPerPixel, 256u);
  EXPECT_EQ(*scene.renderHints.maxDepth, 12u);
  EXPECT_FLOAT_EQ(scene.camera.apertureRadius, 0.1f);
  EXPECT_FLOAT_EQ(scene.camera.focusDistance, 3.0f);
}

TEST(PbrtLoader, ReverseOrientationTurnsTheFront) {
  Scene scene = loadText(std::string(kMirroredCamera) + kTriangle + "ReverseOrientation\n" + kTriangle);
  ASSERT_EQ(scene.instances.size(), 2u);
  EXPECT_GT(windingNormal(scene, 0, 0).z, 0.0f);
  EXPECT_LT(windingNormal(scene, 1, 0).z, 0.0f);
  // Under the default (unmirrored) camera the world is mirrored; the front must still be pbrt's front.
  Scene mirrored = loadText(std::string("WorldBegin\n") + kTriangle);
  EXPECT_GT(windingNormal(mirrored, 0, 0).z, 0.0f);
  // With normals the front follows the normals.
  Scene withNormals =
      loadText(std::string(kMirroredCamera) +
               "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"normal N\" [0 0 -1 0 0 -1 0 0 -1]");
  EXPECT_LT(windingNormal(withNormals, 0, 0).z, 0.0f);
}

TEST(PbrtLoader, ObjectInstancesShareTheirMeshes) {
  Scene scene = loadText(std::string(kMirroredCamera) + "ObjectBegin \"thing\"\nTranslate 0 0 1\n" + kTriangle +
                         "ObjectEnd\nObjectInstance \"thing\"\nTranslate 5 0 0\nObjectInstance \"thing\"\n");
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.instances.size(), 2u);
  expectNear(scene.instances[0].objectToWorld.point({0, 0, 0}), {0, 0, 1});
  expectNear(scene.instances[1].objectToWorld.point({0, 0, 0}), {5, 0, 1});
}

TEST(PbrtLoader, MaterialsMapOntoCandelasModels) {
  Scene scene =
      loadText(std::string(kMirroredCamera) + "Material \"diffuse\" \"rgb reflectance\" [0.1 0.2 0.3]\n" + kTriangle +
               "Material \"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\"\n" + kTriangle +
               "Material \"conductor\" \"float roughness\" 0.01\n" + kTriangle +
               "Material \"dielectric\" \"spectrum eta\" \"glass-BK7\"\n" + kTriangle +
               "Material \"coateddiffuse\" \"rgb reflectance\" [0.5 0.5 0.5] \"float roughness\" 0\n" + kTriangle +
               "Material \"interface\"\n" + kTriangle);
  auto materialOf = [&](size_t i) { return scene.materials[scene.meshes[i].triangleMaterials[0]]; };
  EXPECT_EQ(materialOf(0).type, MaterialType::Diffuse);
  expectNear(materialOf(0).baseColor, {0.1f, 0.2f, 0.3f});
  EXPECT_EQ(materialOf(1).type, MaterialType::Mirror);
  Vec3 gold = materialOf(1).specularColor;
  EXPECT_GT(gold.x, gold.z + 0.4f);  // gold reflects red far more than blue
  EXPECT_EQ(materialOf(2).type, MaterialType::Pbr);
  EXPECT_FLOAT_EQ(materialOf(2).metallic, 1.0f);
  EXPECT_NEAR(materialOf(2).roughness, std::pow(0.01f, 0.25f), 1e-5f);  // remapped: alpha = sqrt(0.01)
  EXPECT_EQ(materialOf(3).type, MaterialType::Glass);
  EXPECT_NEAR(materialOf(3).ior, 1.5168f, 1e-4f);
  EXPECT_EQ(materialOf(4).type, MaterialType::Pbr);
  EXPECT_NEAR(materialOf(4).specular, 0.5f, 1e-4f);  // eta 1.5: F0 = 0.04
  EXPECT_EQ(materialOf(5).alphaMode, AlphaMode::Mask);
  EXPECT_EQ(materialOf(5).opacity, 0.0f);
}

TEST(PbrtLoader, PbrtV3MaterialsByTheirColours) {
  Scene scene = loadText(std::string(kMirroredCamera) + "Material \"matte\" \"color Kd\" [0.2 0.3 0.4]\n" + kTriangle +
                         "Material \"glass\" \"float index\" 1.33\n" + kTriangle +
                         "Material \"mirror\" \"rgb Kr\" [0.5 0.5 0.5]\n" + kTriangle);
  auto materialOf = [&](size_t i) { return scene.materials[scene.meshes[i].triangleMaterials[0]]; };
  EXPECT_EQ(materialOf(0).type, MaterialType::Diffuse);
  expectNear(materialOf(0).baseColor, {0.2f, 0.3f, 0.4f});
  EXPECT_EQ(materialOf(1).type, MaterialType::Glass);
  EXPECT_NEAR(materialOf(1).ior, 1.33f, 1e-5f);
  EXPECT_EQ(materialOf(2).type, MaterialType::Mirror);
  expectNear(materialOf(2).specularColor, {0.5f, 0.5f, 0.5f});
}

TEST(PbrtLoader, RenderSettingsAreBounded) {
  Scene scene = loadText(
      "Film \"rgb\" \"integer xresolution\" 100000 \"integer yresolution\" 0\n"
      "Integrator \"path\" \"integer maxdepth\" 100000\nWorldBegin\n");
  EXPECT_EQ(*scene.renderHints.width, 16384u);
  EXPECT_EQ(*scene.renderHints.height, 1u);
  EXPECT_EQ(*scene.renderHints.maxDepth, 1024u);
}

TEST(PbrtLoader, MoreMaterialConversions) {
  LoadWarnings warnings;
  Scene scene = loadText(
      std::string(kMirroredCamera) +
          "Material \"coatedconductor\" \"float conductor.roughness\" 0.01 \"float interface.roughness\" 0\n" +
          kTriangle + "Material \"thindielectric\" \"float eta\" 1.5\n" + kTriangle +
          "Material \"diffusetransmission\" \"rgb reflectance\" [0.3 0.3 0.3]\n" + kTriangle +
          "Material \"conductor\" \"float uroughness\" 0.04 \"float vroughness\" 0.0 \"bool remaproughness\" false\n" +
          kTriangle + "Material \"dielectric\" \"float roughness\" 0.3\n" + kTriangle,
      &warnings);
  auto materialOf = [&](size_t i) { return scene.materials[scene.meshes[i].triangleMaterials[0]]; };
  EXPECT_EQ(materialOf(0).type, MaterialType::Disney);
  EXPECT_FLOAT_EQ(materialOf(0).metallic, 1.0f);
  EXPECT_FLOAT_EQ(materialOf(0).clearcoat, 1.0f);
  EXPECT_FLOAT_EQ(materialOf(0).clearcoatGloss, 1.0f);
  EXPECT_NEAR(materialOf(0).roughness, std::pow(0.01f, 0.25f), 1e-5f);
  // A thin sheet: a mirror of reflectance 2R/(1+R) that rays pass otherwise.
  EXPECT_EQ(materialOf(1).type, MaterialType::Mirror);
  EXPECT_EQ(materialOf(1).alphaMode, AlphaMode::Blend);
  EXPECT_NEAR(materialOf(1).opacity, 2.0f * 0.04f / 1.04f, 1e-5f);
  EXPECT_EQ(materialOf(2).type, MaterialType::DiffuseTransmission);
  expectNear(materialOf(2).baseColor, {0.3f, 0.3f, 0.3f});
  expectNear(materialOf(2).transmittance, {0.25f, 0.25f, 0.25f});
  // Without remapping, the mean of u and v roughness is alpha itself: candela's roughness is its square root.
  EXPECT_EQ(materialOf(3).type, MaterialType::Pbr);
  EXPECT_NEAR(materialOf(3).roughness, std::sqrt(0.02f), 1e-5f);
  EXPECT_EQ(materialOf(4).type, MaterialType::Disney);
  EXPECT_FLOAT_EQ(materialOf(4).specTrans, 1.0f);
  std::string all;
  for (const std::string& w : warnings.messages) all += w + "\n";
  EXPECT_NE(all.find("thindielectric"), std::string::npos) << all;
  EXPECT_EQ(all.find("diffusetransmission"), std::string::npos) << all;
}

TEST(PbrtLoader, ConstantScaleMixAndCheckerboardTextures) {
  LoadWarnings warnings;
  Scene scene = loadText(std::string(kMirroredCamera) +
                             "Texture \"c\" \"spectrum\" \"constant\" \"rgb value\" [0.2 0.4 0.6]\n"
                             "Texture \"s\" \"spectrum\" \"scale\" \"texture tex\" \"c\" \"float scale\" 0.5\n"
                             "Texture \"m\" \"spectrum\" \"mix\" \"rgb tex1\" [1 1 1] \"rgb tex2\" [0 0 0] "
                             "\"float amount\" 0.25\n"
                             "Texture \"k\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [1 0 0] \"rgb tex2\" [0 0 1] "
                             "\"float uscale\" 4 \"float vscale\" 4\n"
                             "Material \"diffuse\" \"texture reflectance\" \"s\"\n" +
                             kTriangle + "Material \"diffuse\" \"texture reflectance\" \"m\"\n" + kTriangle +
                             "Material \"diffuse\" \"texture reflectance\" \"k\"\n"
                             "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"point2 uv\" [0 0 1 0 0 1]\n",
                         &warnings);
  auto colourOf = [&](size_t i) { return scene.materials[scene.meshes[i].triangleMaterials[0]].baseColor; };
  expectNear(colourOf(0), {0.1f, 0.2f, 0.3f});
  expectNear(colourOf(1), {0.75f, 0.75f, 0.75f});  // tex1 weighted 1 - amount
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();
  // The checkerboard is an image of one period: 2 x 2 checks; tex1 where floor(s) + floor(t) is even.
  const Material& checks = scene.materials[scene.meshes[2].triangleMaterials[0]];
  ASSERT_NE(checks.baseColorTexture, kNoTexture);
  const Texture& image = scene.textures[size_t(checks.baseColorTexture)];
  auto texel = [&](uint32_t x, uint32_t y) {
    const float* p = image.floats.data() + (size_t(y) * image.width + x) * 3;
    return Vec3{p[0], p[1], p[2]};
  };
  expectNear(texel(0, image.height - 1), {1, 0, 0});  // s, t in [0, 1): bottom left
  expectNear(texel(image.width - 1, image.height - 1), {0, 0, 1});
  expectNear(texel(0, 0), {0, 0, 1});
  // pbrt's (u, v) = (1, 0) is s = 4 (uscale 4), half periods: candela's u = 2.
  ASSERT_EQ(scene.meshes[2].uvs.size(), 3u);
  EXPECT_FLOAT_EQ(scene.meshes[2].uvs[1].x, 2.0f);
}

TEST(PbrtLoader, PngTexturesNormalMapsAndTheirEncoding) {
  TempFolder folder;
  const uint8_t pixels[4 * 3] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 128, 128, 255};
  ASSERT_TRUE(stbi_write_png(folder.file("albedo.png").c_str(), 2, 2, 3, pixels, 6));
  ASSERT_TRUE(stbi_write_png(folder.file("normals.png").c_str(), 2, 2, 3, pixels, 6));
  std::string path =
      folder.write("scene.pbrt",
                   std::string(kMirroredCamera) +
                       "Texture \"srgb\" \"spectrum\" \"imagemap\" \"string filename\" \"albedo.png\"\n"
                       "Texture \"linear\" \"spectrum\" \"imagemap\" \"string filename\" \"albedo.png\" "
                       "\"string encoding\" \"linear\"\n"
                       "Material \"diffuse\" \"texture reflectance\" \"srgb\" \"string normalmap\" \"normals.png\"\n" +
                       kTriangle + "Material \"diffuse\" \"texture reflectance\" \"linear\"\n" + kTriangle);
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();
  const Material& a = scene.materials[scene.meshes[0].triangleMaterials[0]];
  const Material& b = scene.materials[scene.meshes[1].triangleMaterials[0]];
  ASSERT_NE(a.baseColorTexture, kNoTexture);
  ASSERT_NE(b.baseColorTexture, kNoTexture);
  EXPECT_TRUE(scene.textures[size_t(a.baseColorTexture)].srgb);
  EXPECT_FALSE(scene.textures[size_t(b.baseColorTexture)].srgb);
  ASSERT_NE(a.normalTexture, kNoTexture);
  EXPECT_FALSE(scene.textures[size_t(a.normalTexture)].srgb);  // normal maps hold vectors, not colours
}

TEST(PbrtLoader, ImageTexturesAreDecodedWithinTheTextureSizeLimit) {
  TempFolder folder;
  std::vector<uint8_t> pixels(256 * 128 * 3, 200);
  ASSERT_TRUE(stbi_write_png(folder.file("large.png").c_str(), 256, 128, 3, pixels.data(), 256 * 3));
  const std::string path =
      folder.write("scene.pbrt", std::string(kMirroredCamera) +
                                     "Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \"large.png\"\n"
                                     "Material \"diffuse\" \"texture reflectance\" \"t\"\n" +
                                     kTriangle);
  const TextureLimits defaults = textureLimits();
  setTextureLimits({64, defaults.maxBytes});
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  setTextureLimits(defaults);
  const Material& m = scene.materials[scene.meshes[0].triangleMaterials[0]];
  ASSERT_NE(m.baseColorTexture, kNoTexture);
  const Texture& t = scene.textures[size_t(m.baseColorTexture)];
  EXPECT_EQ(t.width, 64u);
  EXPECT_EQ(t.height, 32u);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("large.png: texture of 256x128 pixels downscaled to 64x32"), std::string::npos)
      << warnings.messages[0];
}

TEST(PbrtLoader, CameraFeaturesNotRenderedAreNamed) {
  LoadWarnings warnings;
  loadText(
      "ConcatTransform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]\nCamera \"realistic\" \"float screenwindow\" "
      "[-1 1 -1 1]\nPixelFilter \"gaussian\"\nWorldBegin\n",
      &warnings);
  std::string all;
  for (const std::string& w : warnings.messages) all += w + "\n";
  EXPECT_NE(all.find("'realistic'"), std::string::npos) << all;
  EXPECT_NE(all.find("screen window is not of the image's aspect ratio"), std::string::npos) << all;
  EXPECT_NE(all.find("pixel filter"), std::string::npos) << all;
}

TEST(PbrtLoader, OrthographicCamerasSpanTheirScreenWindowInCameraUnits) {
  LoadWarnings warnings;
  Scene scene = loadText(
      "Film \"rgb\" \"integer xresolution\" 200 \"integer yresolution\" 100\n"
      "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"orthographic\" \"float lensradius\" 0.1 \"float focaldistance\" 3\n"
      "WorldBegin\n",
      &warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();
  EXPECT_EQ(scene.camera.projection, Projection::Orthographic);
  EXPECT_FLOAT_EQ(scene.camera.orthographicHalfHeight, 1.0f);  // the shorter axis spans [-1, 1]
  EXPECT_FLOAT_EQ(scene.camera.imageShift.x, 0.0f);
  EXPECT_FLOAT_EQ(scene.camera.apertureRadius, 0.1f);
  EXPECT_FLOAT_EQ(scene.camera.focusDistance, 3.0f);
  // Rays leave the image rectangle in parallel: the top-left corner's ray starts 2 left of and 1 above the eye
  // (through the lens's centre).
  CameraDescription pinhole = scene.camera;
  pinhole.apertureRadius = 0.0f;
  const Camera c = pinhole.toCamera(2.0f);
  const Ray corner = c.generateRay(0, 0, 200, 100), centre = c.generateRay(100, 50, 200, 100);
  expectNear(corner.direction, centre.direction);
  const Vec3 right = normalize(cross(centre.direction, scene.camera.up));
  EXPECT_NEAR(dot(corner.origin - centre.origin, right), -2.0f, 1e-4f);
  EXPECT_NEAR(dot(corner.origin - centre.origin, scene.camera.up), 1.0f, 1e-4f);

  // An off-centre window [0 2 0 1] in a camera transform that scales by 2: half as large in the world, shifted.
  Scene shifted = loadText(
      "Film \"rgb\" \"integer xresolution\" 200 \"integer yresolution\" 100\nScale 2 2 2\n"
      "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"orthographic\" \"float screenwindow\" [0 2 0 1]\nWorldBegin\n");
  EXPECT_FLOAT_EQ(shifted.camera.orthographicHalfHeight, 0.25f);
  EXPECT_FLOAT_EQ(shifted.camera.imageShift.x, 2.0f);
  EXPECT_FLOAT_EQ(shifted.camera.imageShift.y, 1.0f);
}

TEST(PbrtLoader, PerspectiveScreenWindowsScaleAndShiftTheImage) {
  Scene scene = loadText(
      "Film \"rgb\" \"integer xresolution\" 200 \"integer yresolution\" 100\n"
      "Camera \"perspective\" \"float fov\" 90 \"float screenwindow\" [-0.5 1.5 -0.25 0.75]\nWorldBegin\n");
  // Screen coordinate 1 is tan(45 degrees) = 1 away from the axis at distance 1: the window is 1 high.
  EXPECT_NEAR(scene.camera.verticalFovDegrees, 2.0f * std::atan(0.5f) * 180.0f / kPi, 1e-3f);
  EXPECT_FLOAT_EQ(scene.camera.imageShift.x, 1.0f);
  EXPECT_FLOAT_EQ(scene.camera.imageShift.y, 0.5f);
  EXPECT_NE(loadError("Camera \"perspective\" \"float screenwindow\" [1 -1 -1 1]\nWorldBegin\n")
                .find("test.pbrt:1: Camera 'screenwindow' (or 'frameaspectratio'): the window is empty"),
            std::string::npos);
}

TEST(PbrtLoader, ConcatTransformMultipliesTheCurrentTransform) {
  Scene scene = loadText(std::string(kMirroredCamera) +
                         "Translate 1 0 0\nConcatTransform [2 0 0 0 0 2 0 0 0 0 2 0 0 0 3 1]\n" + kTriangle);
  expectNear(scene.instances[0].objectToWorld.point({1, 0, 0}), {3, 0, 3});
}

TEST(PbrtLoader, NamedMaterialsMayBeMadeAfterTheirUse) {
  LoadWarnings warnings;
  Scene scene =
      loadText(std::string(kMirroredCamera) + "NamedMaterial \"later\"\n" + kTriangle + "NamedMaterial \"never\"\n" +
                   kTriangle + "MakeNamedMaterial \"later\" \"string type\" \"diffuse\" \"rgb reflectance\" [1 0 0]\n",
               &warnings);
  expectNear(scene.materials[scene.meshes[0].triangleMaterials[0]].baseColor, {1, 0, 0});
  expectNear(scene.materials[scene.meshes[1].triangleMaterials[0]].baseColor, {0.5f, 0.5f, 0.5f});
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("'never' is not defined"), std::string::npos) << warnings.messages[0];
}

TEST(PbrtLoader, NamedAndMixedMaterials) {
  std::string text = std::string(kMirroredCamera) +
                     "MakeNamedMaterial \"red\" \"string type\" \"diffuse\" \"rgb reflectance\" [1 0 0]\n"
                     "MakeNamedMaterial \"blue\" \"string type\" \"diffuse\" \"rgb reflectance\" [0 0 1]\n"
                     "MakeNamedMaterial \"mixed\" \"string type\" \"mix\" \"string materials\" [\"red\" \"blue\"] "
                     "\"float amount\" 0.25\n"
                     "NamedMaterial \"mixed\"\nShape \"sphere\"\n";
  Scene scene = loadText(text);
  ASSERT_EQ(scene.meshes.size(), 1u);
  // Every triangle takes the mix, which chooses per shading point (kernel/textured_material.h).
  const std::vector<uint32_t>& ids = scene.meshes[0].triangleMaterials;
  EXPECT_TRUE(std::all_of(ids.begin(), ids.end(), [&](uint32_t id) { return id == ids[0]; }));
  const Material& mix = scene.materials[ids[0]];
  ASSERT_EQ(mix.type, MaterialType::Mix);
  EXPECT_EQ(scene.materialNames[ids[0]], "mixed");
  EXPECT_EQ(scene.materialNames[mix.mixedMaterials[0]], "red");
  EXPECT_EQ(scene.materialNames[mix.mixedMaterials[1]], "blue");
  EXPECT_FLOAT_EQ(mix.mixAmount, 0.25f);  // the second material's probability, as in pbrt-v4
  EXPECT_EQ(mix.mixAmountTexture, kNoTexture);
}

TEST(PbrtLoader, MixAmountTexturesAreHonoured) {
  LoadWarnings warnings;
  const std::string triangle =
      "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"point2 uv\" [0 0 1 0 0 1] "
      "\"integer indices\" [0 1 2]\n";
  Scene scene = loadText(std::string(kMirroredCamera) +
                             "Texture \"amount\" \"float\" \"checkerboard\" \"float tex1\" 0.2 \"float tex2\" 0.8 "
                             "\"float uscale\" 4\n"
                             "Texture \"scaled\" \"float\" \"scale\" \"texture tex\" \"amount\" \"float scale\" 0.5\n"
                             "MakeNamedMaterial \"a\" \"string type\" \"diffuse\"\n"
                             "MakeNamedMaterial \"b\" \"string type\" \"conductor\"\n"
                             "MakeNamedMaterial \"m\" \"string type\" \"mix\" \"string materials\" [\"a\" \"b\"] "
                             "\"texture amount\" \"amount\"\n"
                             "MakeNamedMaterial \"half\" \"string type\" \"mix\" \"string materials\" [\"a\" \"b\"] "
                             "\"texture amount\" \"scaled\"\n"
                             "NamedMaterial \"m\"\n" +
                             triangle + "NamedMaterial \"half\"\n" + triangle,
                         &warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  const Material& mix = scene.materials[scene.meshes[0].triangleMaterials[0]];
  ASSERT_EQ(mix.type, MaterialType::Mix);
  ASSERT_NE(mix.mixAmountTexture, kNoTexture);  // the checkerboard's image of 0.2 and 0.8
  EXPECT_FLOAT_EQ(mix.mixAmount, 1.0f);
  // The amount texture's mapping reaches the mesh: a period of the checkerboard's image (two checks) is 1/2 of
  // u wide at uscale 4, so u = 1 becomes 2 periods.
  EXPECT_NEAR(scene.meshes[0].uvs[1].x, 2.0f, 1e-5f);
  const Material& half = scene.materials[scene.meshes[1].triangleMaterials[0]];
  EXPECT_EQ(half.mixAmountTexture, mix.mixAmountTexture);
  EXPECT_FLOAT_EQ(half.mixAmount, 0.5f);  // the scale texture's factor times the same image
}

TEST(PbrtLoader, MixesOfMixesNestUpToTheBound) {
  auto chain = [](uint32_t mixes) {
    std::string text = std::string(kMirroredCamera) + "MakeNamedMaterial \"m0\" \"string type\" \"diffuse\"\n";
    for (uint32_t i = 1; i <= mixes; ++i)
      text += "MakeNamedMaterial \"m" + std::to_string(i) + "\" \"string type\" \"mix\" \"string materials\" [\"m" +
              std::to_string(i - 1) + "\" \"m0\"]\n";
    return text + "NamedMaterial \"m" + std::to_string(mixes) + "\"\n" + kTriangle;
  };
  Scene scene = loadText(chain(kMaxMixDepth));
  const Material& outer = scene.materials[scene.meshes[0].triangleMaterials[0]];
  EXPECT_EQ(outer.type, MaterialType::Mix);
  EXPECT_EQ(scene.materials[outer.mixedMaterials[0]].type, MaterialType::Mix);
  EXPECT_EQ(scene.materials[outer.mixedMaterials[1]].type, MaterialType::Diffuse);
  EXPECT_NE(loadError(chain(kMaxMixDepth + 1))
                .find("test.pbrt:" + std::to_string(kMaxMixDepth + 5) + ": mix materials nest more than 8 deep"),
            std::string::npos)
      << loadError(chain(kMaxMixDepth + 1));
}

// pbrt-v4's area lights and alpha belong to the shape: a mix keeps them, the materials it mixes are untouched.
TEST(PbrtLoader, MixedShapesKeepTheirEmissionAndAlpha) {
  LoadWarnings warnings;
  Scene scene = loadText(std::string(kMirroredCamera) +
                             "MakeNamedMaterial \"a\" \"string type\" \"diffuse\"\n"
                             "MakeNamedMaterial \"gap\" \"string type\" \"interface\"\n"
                             "MakeNamedMaterial \"m\" \"string type\" \"mix\" \"string materials\" [\"a\" \"gap\"]\n"
                             "NamedMaterial \"m\"\nAreaLightSource \"diffuse\" \"rgb L\" [1 2 3]\n"
                             "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2] "
                             "\"float alpha\" 0.5\n",
                         &warnings);
  const Material& mix = scene.materials[scene.meshes[0].triangleMaterials[0]];
  ASSERT_EQ(mix.type, MaterialType::Mix);
  expectNear(mix.emission, {1, 2, 3});
  EXPECT_EQ(mix.alphaMode, AlphaMode::Blend);
  EXPECT_FLOAT_EQ(mix.opacity, 0.5f);
  EXPECT_TRUE(isBlack(scene.materials[mix.mixedMaterials[0]].emission));
  // An 'interface' in a mix cannot let light through per point: said so.
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("'gap' lets light through"), std::string::npos) << warnings.messages[0];
}

TEST(PbrtLoader, AreaLightsEmitFromTheirShapes) {
  Scene scene = loadText(std::string(kMirroredCamera) +
                         "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 2 3] \"float scale\" 2\n" +
                         kTriangle + "AttributeEnd\n" + kTriangle);
  expectNear(scene.materials[scene.meshes[0].triangleMaterials[0]].emission, {2, 4, 6});
  EXPECT_TRUE(isBlack(scene.materials[scene.meshes[1].triangleMaterials[0]].emission));
  // Two-sided lights emit from both faces: each triangle is there twice, once per winding.
  Scene twoSided =
      loadText(std::string(kMirroredCamera) + "AreaLightSource \"diffuse\" \"bool twosided\" true\n" + kTriangle);
  EXPECT_EQ(twoSided.meshes[0].triangleCount(), 2u);
  // `power` sets the radiance: phi = pi * area * L for a one-sided emitter of luminance L.
  Scene power = loadText(std::string(kMirroredCamera) + "AreaLightSource \"diffuse\" \"float power\" 10\n" + kTriangle);
  float L = luminance(power.materials[power.meshes[0].triangleMaterials[0]].emission);
  EXPECT_NEAR(kPi * 0.5f * L, 10.0f, 1e-3f);
  // As in pbrt-v4, each triangle of a mesh is a light of that power, and an RGB L keeps its magnitude.
  Scene perTriangle = loadText(std::string(kMirroredCamera) +
                               "AreaLightSource \"diffuse\" \"rgb L\" [2 2 2] \"float power\" 10\n"
                               "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 0 0 1 2 0 1 0 1 1] "
                               "\"integer indices\" [0 1 2 3 4 5]\n");
  const Mesh& pair = perTriangle.meshes[0];
  EXPECT_NEAR(perTriangle.materials[pair.triangleMaterials[0]].emission.x, 2.0f * 10.0f / (kPi * 0.5f), 1e-3f);
  EXPECT_NEAR(perTriangle.materials[pair.triangleMaterials[1]].emission.x, 2.0f * 10.0f / (kPi * 1.0f), 1e-3f);
  // Blackbody emitters are normalised to luminance 1 (times scale), as pbrt-v4 normalises them.
  Scene blackbody = loadText(std::string(kMirroredCamera) +
                             "AreaLightSource \"diffuse\" \"blackbody L\" [3000] \"float scale\" 5\n" + kTriangle);
  Vec3 e = blackbody.materials[blackbody.meshes[0].triangleMaterials[0]].emission;
  EXPECT_NEAR(luminance(e), 5.0f, 0.05f);
  EXPECT_GT(e.x, e.z);  // 3000 K is warm
}

TEST(PbrtLoader, AreaLightsOfInfiniteSizeEmitNoNaN) {
  // An infinite triangle area gives power / area = 0 and an infinite L times 0: not a number.
  Scene scene = loadText(std::string(kMirroredCamera) +
                         "Scale 1e30 1e30 1e30\nAreaLightSource \"diffuse\" \"rgb L\" [1e38 1 1] \"float scale\" 1e10 "
                         "\"float power\" 1\n" +
                         kTriangle + kTriangle);
  for (const Material& m : scene.materials) EXPECT_FALSE(std::isnan(m.emission.x));
}

TEST(PbrtLoader, InfiniteLightsBecomeTheEnvironment) {
  Scene scene = loadText("WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.5 0.25 1] \"float scale\" 2\n");
  expectNear(scene.environment.radiance, {1, 0.5f, 2});
  EXPECT_FALSE(scene.environment.hasMap());
}

// Point, spot and distant lights become punctual lights, placed by the transform in force (x = 0 throughout, so
// the world mirror leaves them as written).
TEST(PbrtLoader, PointSpotAndDistantLightsBecomePunctualLights) {
  Scene scene = loadText(
      "WorldBegin\nAttributeBegin\nTranslate 0 1 0\nLightSource \"point\" \"rgb I\" [1 2 3] \"float scale\" 2\n"
      "AttributeEnd\nLightSource \"spot\" \"point3 from\" [0 4 0] \"point3 to\" [0 0 0] \"float coneangle\" 40 "
      "\"float conedelta\" 10\nLightSource \"distant\" \"point3 from\" [0 1 0] \"point3 to\" [0 0 0] "
      "\"rgb L\" [3 3 3]\n");
  ASSERT_EQ(scene.punctualLights.size(), 3u);
  const PunctualLight &point = scene.punctualLights[0], &spot = scene.punctualLights[1], &sun = scene.punctualLights[2];
  EXPECT_EQ(point.type, PunctualLightType::Point);
  expectNear(point.position, {0, 1, 0});
  expectNear(point.intensity, {2, 4, 6});
  EXPECT_EQ(spot.type, PunctualLightType::Spot);
  expectNear(spot.position, {0, 4, 0});
  expectNear(spot.direction, {0, -1, 0});
  EXPECT_NEAR(spot.cosOuter, std::cos(40.0f * kPi / 180.0f), 1e-6f);
  EXPECT_NEAR(spot.cosInner, std::cos(30.0f * kPi / 180.0f), 1e-6f);
  EXPECT_EQ(sun.type, PunctualLightType::Directional);
  expectNear(sun.direction, {0, -1, 0});
  expectNear(sun.intensity, {3, 3, 3});
}

// pbrt-v4's photometric normalisations of punctual lights: a point light's power spreads over 4 pi steradians, a
// spot's over 2 pi (1 - cos inner) plus half its falloff band; a distant light's illuminance multiplies L.
TEST(PbrtLoader, PunctualLightPowerAndIlluminanceSetTheirIntensity) {
  LoadWarnings warnings;
  Scene scene = loadText(
      "WorldBegin\nLightSource \"point\" \"rgb I\" [1 2 3] \"float power\" 100 \"float scale\" 2\n"
      "LightSource \"spot\" \"float power\" 10 \"float coneangle\" 60 \"float conedelta\" 60\n"
      "LightSource \"distant\" \"rgb L\" [1 1 2] \"float illuminance\" 5\n",
      &warnings);
  ASSERT_EQ(scene.punctualLights.size(), 3u);
  const float pointScale = 2.0f * 100.0f / (4.0f * kPi);
  expectNear(scene.punctualLights[0].intensity, Vec3{1, 2, 3} * pointScale, 1e-4f);
  // Inner cone 0 degrees, falloff to 60: 2 pi (0 + (1 - 0.5) / 2) = pi / 2 steradians.
  expectNear(scene.punctualLights[1].intensity, Vec3{1, 1, 1} * (10.0f / (kPi / 2.0f)), 1e-4f);
  expectNear(scene.punctualLights[2].intensity, {5, 5, 10});
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
}

// pbrt-v3's name of a spot's falloff band, as pbrt-v4-scenes' villa-lights-on gives it.
TEST(PbrtLoader, SpotFalloffTakesPbrtV3sConeDeltaAngle) {
  LoadWarnings warnings;
  Scene scene =
      loadText("WorldBegin\nLightSource \"spot\" \"float coneangle\" 50 \"float conedeltaangle\" 20\n", &warnings);
  ASSERT_EQ(scene.punctualLights.size(), 1u);
  EXPECT_NEAR(scene.punctualLights[0].cosInner, std::cos(30.0f * kPi / 180.0f), 1e-6f);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
}

// pbrt-v4's sensor scales the image by ISO / 100 times the exposure time (shutterclose - shutteropen): scenes such
// as pbrt-v4-scenes' contemporary-bathroom (ISO 600) would be far too dark without it. candela scales the lights.
TEST(PbrtLoader, FilmIsoAndShutterTimeScaleTheLights) {
  LoadWarnings warnings;
  Scene scene = loadText(
      "Film \"rgb\" \"float iso\" 400 \"string filename\" \"out.exr\" \"float maxcomponentvalue\" 10\n"
      "Scale -1 1 1\nCamera \"perspective\" \"float shutteropen\" 0 \"float shutterclose\" 0.5\nWorldBegin\n"
      "LightSource \"infinite\" \"rgb L\" [1 1 1]\nLightSource \"point\" \"rgb I\" [1 2 3]\n"
      "AreaLightSource \"diffuse\" \"rgb L\" [1 2 3]\n" +
          std::string(kTriangle),
      &warnings);
  expectNear(scene.materials[scene.meshes[0].triangleMaterials[0]].emission, {2, 4, 6});
  expectNear(scene.punctualLights[0].intensity, {2, 4, 6});
  expectNear(scene.environment.radiance * scene.environment.intensity, {2, 2, 2});
  // What the film asks for and candela does not do is named; the output file is candela's -o.
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_EQ(warnings.messages[0], "test.pbrt: film: parameter 'maxcomponentvalue' is not applied");
  // Without iso and shutter times the ratio is 1.
  Scene plain = loadText(std::string(kMirroredCamera) + "AreaLightSource \"diffuse\" \"rgb L\" [1 2 3]\n" + kTriangle);
  expectNear(plain.materials[plain.meshes[0].triangleMaterials[0]].emission, {1, 2, 3});
  EXPECT_NE(loadError("Camera \"perspective\" \"float shutteropen\" 1 \"float shutterclose\" 1\n")
                .find("test.pbrt:1: the camera's shutter times leave the shutter closed"),
            std::string::npos);
  EXPECT_NE(loadError("Film \"rgb\" \"float iso\" 0\n").find("test.pbrt:1: 'iso' must be positive"), std::string::npos);
}

// pbrt-v4 renders only the film's crop window (pbrt-v4-scenes' head and sanmiguel-courtyard set one): the image
// is its pixels, seen as the full frame's camera sees them. The top-right quarter of a 200 x 100 frame is a 100 x 50
// image of the screen window x in [0, 2], y in [0, 1].
TEST(PbrtLoader, FilmCropWindowsRenderTheirPartOfTheFrame) {
  LoadWarnings warnings;
  Scene cropped = loadText(
      "Film \"rgb\" \"integer xresolution\" 200 \"integer yresolution\" 100 \"float cropwindow\" [1 .5 0 .5]\n"
      "Scale -1 1 1\nCamera \"perspective\" \"float fov\" 60\nWorldBegin\n",
      &warnings);
  Scene windowed = loadText(
      "Film \"rgb\" \"integer xresolution\" 100 \"integer yresolution\" 50\n"
      "Scale -1 1 1\nCamera \"perspective\" \"float fov\" 60 \"float screenwindow\" [0 2 0 1]\nWorldBegin\n");
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  EXPECT_EQ(cropped.renderHints.width, 100u);
  EXPECT_EQ(cropped.renderHints.height, 50u);
  EXPECT_NEAR(cropped.camera.verticalFovDegrees, windowed.camera.verticalFovDegrees, 1e-4f);
  EXPECT_NEAR(cropped.camera.imageShift.x, windowed.camera.imageShift.x, 1e-5f);
  EXPECT_NEAR(cropped.camera.imageShift.y, windowed.camera.imageShift.y, 1e-5f);
  EXPECT_GT(cropped.camera.imageShift.x, 0.0f);
  EXPECT_GT(cropped.camera.imageShift.y, 0.0f);
  // pbrt-v4's pixel bounds: columns ceil(0.3 * 10) = 3 to ceil(0.8 * 10) = 8.
  Scene rounded = loadText(
      "Film \"rgb\" \"integer xresolution\" 10 \"integer yresolution\" 10 "
      "\"float cropwindow\" [.3 .8 .15 .7]\n");
  EXPECT_EQ(rounded.renderHints.width, 5u);
  EXPECT_EQ(rounded.renderHints.height, 5u);
  EXPECT_NE(loadError("Film \"rgb\" \"float cropwindow\" [.5 .5 0 1]\n")
                .find("test.pbrt:1: the film's 'cropwindow' holds no pixel"),
            std::string::npos);
}

// CoordSysTransform "camera" puts what follows in the camera's frame (pbrt-v4-scenes' killeroo-gold lights its
// scene with a distant light that way): a point light at its origin sits at the eye, a distant light shines along
// the view.
TEST(PbrtLoader, CoordSysTransformCameraPlacesLightsAtTheCamera) {
  Scene scene = loadText(
      "LookAt 3 1 0  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\nAttributeBegin\nCoordSysTransform \"camera\"\n"
      "LightSource \"point\"\nLightSource \"distant\"\nAttributeEnd\n");
  ASSERT_EQ(scene.punctualLights.size(), 2u);
  expectNear(scene.punctualLights[0].position, scene.camera.eye);
  expectNear(scene.punctualLights[1].direction, normalize(scene.camera.target - scene.camera.eye));
  EXPECT_NE(loadError("Scale 0 1 1\nCamera \"perspective\"\n")
                .find("test.pbrt:2: Camera: the CTM at the Camera directive is not invertible"),
            std::string::npos);
}

TEST(PbrtLoader, UnsupportedFeaturesWarnOncePerFeature) {
  LoadWarnings warnings;
  Scene scene =
      loadText(std::string(kMirroredCamera) +
                   "Shape \"hyperboloid\" \"point3 p1\" [0 0 0]\nShape \"hyperboloid\" \"point3 p1\" "
                   "[1 1 1]\nLightSource \"goniometric\" \"rgb I\" [1 1 1]\n"
                   "MakeNamedMedium \"smoke\" \"string type\" \"homogeneous\" \"string preset\" \"Skin1\"\n"
                   "MakeNamedMedium \"cloud\" \"string type\" \"homogeneous\" \"string preset\" \"Wholemilk\"\n" +
                   kTriangle,
               &warnings);
  EXPECT_EQ(scene.meshes.size(), 1u);
  int shapeWarnings = 0, lightWarnings = 0, mediaWarnings = 0;
  for (const std::string& w : warnings.messages) {
    shapeWarnings += w.find("'hyperboloid'") != std::string::npos;
    lightWarnings += w.find("'goniometric'") != std::string::npos;
    mediaWarnings += w.find("medium presets") != std::string::npos;
  }
  EXPECT_EQ(shapeWarnings, 1);
  EXPECT_EQ(lightWarnings, 1);
  EXPECT_EQ(mediaWarnings, 1);
}

TEST(PbrtLoader, ParametersNotAppliedAreNamed) {
  LoadWarnings warnings;
  loadText(std::string(kMirroredCamera) + "Material \"coateddiffuse\" \"float thickness\" 0.1\n" + kTriangle +
               "Material \"coateddiffuse\" \"float thickness\" 0.2\n" + kTriangle,
           &warnings);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_EQ(warnings.messages[0], "test.pbrt: material 'coateddiffuse': parameter 'thickness' is not applied");
}

TEST(PbrtLoader, UnknownSpectraWarnAndTakeTheDefault) {
  LoadWarnings warnings;
  Scene scene = loadText(std::string(kMirroredCamera) +
                             "Material \"diffuse\" \"spectrum reflectance\" \"measured.spd\"\n" + kTriangle,
                         &warnings);
  expectNear(scene.materials[scene.meshes[0].triangleMaterials[0]].baseColor, {0.5f, 0.5f, 0.5f});
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("'measured.spd'"), std::string::npos) << warnings.messages[0];
}

// pbrt-v4 reads a spectrum that is not one of its names from a file of wavelength-value pairs (pbrt-v4-scenes'
// killeroo-gold: "spectrum k" [ "spds/Au.k.spd" ]).
TEST(PbrtLoader, SpectrumFilesAreRead) {
  TempFolder folder;
  folder.write("spds/grey.spd", "# a measured grey\n300 0.25   # nm, value\n900 0.25\n");
  folder.write("spds/bad.spd", "400 0.5\n500 half\n");
  std::string main =
      folder.write("main.pbrt", std::string(kMirroredCamera) +
                                    "Material \"diffuse\" \"spectrum reflectance\" \"spds/grey.spd\"\n" + kTriangle +
                                    "Material \"diffuse\" \"spectrum reflectance\" \"spds/missing.spd\"\n" + kTriangle +
                                    "Material \"diffuse\" \"spectrum reflectance\" \"spds/bad.spd\"\n" + kTriangle);
  LoadWarnings warnings;
  Scene scene = loadPbrt(main, warnings);
  expectNear(scene.materials[scene.meshes[0].triangleMaterials[0]].baseColor, {0.25f, 0.25f, 0.25f}, 1e-3f);
  // Files that cannot be read are named once each, and the default stands in.
  expectNear(scene.materials[scene.meshes[1].triangleMaterials[0]].baseColor, {0.5f, 0.5f, 0.5f});
  expectNear(scene.materials[scene.meshes[2].triangleMaterials[0]].baseColor, {0.5f, 0.5f, 0.5f});
  ASSERT_EQ(warnings.messages.size(), 2u);
  EXPECT_NE(warnings.messages[0].find("missing.spd: cannot open"), std::string::npos) << warnings.messages[0];
  EXPECT_NE(warnings.messages[1].find("bad.spd:2: 'half' is not a number"), std::string::npos) << warnings.messages[1];
  // The file is one of the scene's inputs (the scene cache notices when it changes).
  EXPECT_NE(std::find_if(scene.inputFiles.begin(), scene.inputFiles.end(),
                         [](const std::string& f) { return f.find("grey.spd") != std::string::npos; }),
            scene.inputFiles.end());
}

TEST(PbrtSpectrumFiles, PairsCommentsAndMalformedFiles) {
  EXPECT_EQ(parsePbrtSpectrumFile("a.spd", "# c\n400 1,500 2\r\n#\n600 3 700 4"),
            (std::vector<double>{400, 1, 500, 2, 600, 3, 700, 4}));
  auto error = [](const std::string& text) {
    try {
      parsePbrtSpectrumFile("a.spd", text);
    } catch (const LoadError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error("400 1 500"), "a.spd: a spectrum file needs wavelength-value pairs, found 3 numbers");
  EXPECT_EQ(error("# nothing\n"), "a.spd: a spectrum file needs wavelength-value pairs, found 0 numbers");
  EXPECT_EQ(error("400 1\n500 nan\n"), "a.spd:2: 'nan' is not a number");
}

TEST(PbrtLoader, ImageTexturesWithTheirUvMapping) {
  TempFolder folder;
  folder.write("grey.pfm", std::string("Pf\n2 1\n-1.0\n") + std::string("\0\0\0\x3f\0\0\x80\x3f", 8));
  std::string path =
      folder.write("scene.pbrt",
                   std::string(kMirroredCamera) +
                       "Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \"grey.pfm\" "
                       "\"float uscale\" 2 \"float vscale\" 4 \"float scale\" 0.5\n"
                       "Texture \"a\" \"float\" \"imagemap\" \"string filename\" \"grey.pfm\"\n"
                       "Material \"diffuse\" \"texture reflectance\" \"t\"\n"
                       "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"point2 uv\" [0 0 1 0 0 1] "
                       "\"texture alpha\" \"a\"\n");
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();
  ASSERT_EQ(scene.textures.size(), 1u);  // one image, read once
  EXPECT_EQ(scene.textures[0].width, 2u);
  EXPECT_FLOAT_EQ(scene.textures[0].floats[1], 1.0f);
  const Material& m = scene.materials[scene.meshes[0].triangleMaterials[0]];
  EXPECT_EQ(m.baseColorTexture, 0);
  expectNear(m.baseColor, {0.5f, 0.5f, 0.5f});
  EXPECT_EQ(m.opacityTexture, 0);
  EXPECT_EQ(m.alphaMode, AlphaMode::Blend);
  // pbrt's (u, v) = (1, 0) through uscale 2: u' = 2; v' = 0 is the bottom of the image, candela's v = 1.
  const Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.uvs.size(), 3u);
  EXPECT_FLOAT_EQ(mesh.uvs[1].x, 2.0f);
  EXPECT_FLOAT_EQ(mesh.uvs[1].y, 1.0f);
  EXPECT_FLOAT_EQ(mesh.uvs[2].y, 1.0f - 4.0f);
}

// A mix of images is an image of the mix, each input through its own uv mapping.
TEST(PbrtLoader, MixTexturesOfImagesBecomeAnImageOfTheMix) {
  TempFolder folder;
  folder.write("grey.pfm", std::string("Pf\n2 1\n-1.0\n") + std::string("\0\0\0\x3f\0\0\x80\x3f", 8));
  std::string path =
      folder.write("scene.pbrt",
                   std::string(kMirroredCamera) +
                       "Texture \"g\" \"spectrum\" \"imagemap\" \"string filename\" \"grey.pfm\" \"float uscale\" 2\n"
                       "Texture \"a\" \"float\" \"imagemap\" \"string filename\" \"grey.pfm\"\n"
                       "Texture \"m\" \"spectrum\" \"mix\" \"texture tex1\" \"g\" \"rgb tex2\" [0 0 0] "
                       "\"texture amount\" \"a\"\n"
                       "Material \"diffuse\" \"texture reflectance\" \"m\"\n"
                       "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"point2 uv\" [0 0 1 0 0 1]\n");
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();
  const Material& m = scene.materials[scene.meshes[0].triangleMaterials[0]];
  ASSERT_NE(m.baseColorTexture, kNoTexture);
  const Texture& mix = scene.textures[size_t(m.baseColorTexture)];
  // Four texels across: the first input repeats twice over u. At their centres, u = 1/8, 3/8, 5/8, 7/8: the
  // first input is 0.5, 1, 0.5, 1 and the amount 0.5, 0.5, 1, 1, so (1 - amount) x first is:
  ASSERT_EQ(mix.width, 4u);
  ASSERT_EQ(mix.height, 1u);
  const float expected[4] = {0.25f, 0.5f, 0.0f, 0.0f};
  for (uint32_t x = 0; x < 4; ++x) EXPECT_FLOAT_EQ(mix.floats[x * 3], expected[x]) << "texel " << x;
  // The mappings are in the image: the mesh keeps pbrt's (u, v), v flipped.
  EXPECT_FLOAT_EQ(scene.meshes[0].uvs[1].x, 1.0f);
}

// A mix of an image repeated without bound stays within the texture size limit.
TEST(PbrtLoader, MixTextureImagesKeepToTheTextureSizeLimit) {
  TempFolder folder;
  folder.write("grey.pfm", std::string("Pf\n2 1\n-1.0\n") + std::string("\0\0\0\x3f\0\0\x80\x3f", 8));
  std::string path =
      folder.write("scene.pbrt",
                   std::string(kMirroredCamera) +
                       "Texture \"g\" \"spectrum\" \"imagemap\" \"string filename\" \"grey.pfm\" "
                       "\"float uscale\" 1e30 \"float vscale\" -1e30\n"
                       "Texture \"m\" \"spectrum\" \"mix\" \"texture tex1\" \"g\" \"rgb tex2\" [0 0 0]\n"
                       "Material \"diffuse\" \"texture reflectance\" \"m\"\n"
                       "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"point2 uv\" [0 0 1 0 0 1]\n");
  setTextureLimits({64, 1u << 20});
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  setTextureLimits({});
  const Material& m = scene.materials[scene.meshes[0].triangleMaterials[0]];
  ASSERT_NE(m.baseColorTexture, kNoTexture);
  EXPECT_EQ(scene.textures[size_t(m.baseColorTexture)].width, 64u);
  EXPECT_EQ(scene.textures[size_t(m.baseColorTexture)].height, 64u);
}

// A number beyond a float's range is refused: as pbrt's float it would be infinite (a fuzzing input's sphere of
// radius 8.9e81 had bounds of not-a-number, which its tessellation then turned into an integer).
TEST(PbrtLoader, NumbersBeyondTheRangeOfAFloatAreRefused) {
  const std::string error = loadError(std::string(kMirroredCamera) + "Shape \"sphere\" \"float radius\" 8.9e81\n");
  EXPECT_EQ(error, "test.pbrt:4: '8.9e81' is beyond the range of a float (value of 'radius')");
  EXPECT_EQ(loadText(std::string(kMirroredCamera) + "Shape \"sphere\" \"float radius\" 3e38\n").meshes.size(), 1u);
}

// The same mix under two names is one image; a roughness made from a mix reads the mix's baked texels.
TEST(PbrtLoader, IdenticalMixTexturesShareOneImage) {
  TempFolder folder;
  folder.write("grey.pfm", std::string("Pf\n2 1\n-1.0\n") + std::string("\0\0\0\x3f\0\0\x80\x3f", 8));
  const std::string mix = "\"spectrum\" \"mix\" \"texture tex1\" \"g\" \"rgb tex2\" [0 0 0]\n";
  std::string path =
      folder.write("scene.pbrt",
                   std::string(kMirroredCamera) +
                       "Texture \"g\" \"spectrum\" \"imagemap\" \"string filename\" \"grey.pfm\"\n"
                       "Texture \"m1\" " +
                       mix + "Texture \"m2\" " + mix + "Material \"diffuse\" \"texture reflectance\" \"m1\"\n" +
                       kTriangle + "Material \"diffuse\" \"texture reflectance\" \"m2\"\n" + kTriangle +
                       "Material \"conductor\" \"texture roughness\" \"m2\" \"bool remaproughness\" false\n" +
                       kTriangle);
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  ASSERT_EQ(scene.meshes.size(), 3u);
  const Material& first = scene.materials[scene.meshes[0].triangleMaterials[0]];
  const Material& second = scene.materials[scene.meshes[1].triangleMaterials[0]];
  ASSERT_NE(first.baseColorTexture, kNoTexture);
  EXPECT_EQ(first.baseColorTexture, second.baseColorTexture);
  EXPECT_EQ(scene.textures.size(), 3u);  // the image, the mix and the roughness
  const Texture& baked = scene.textures[size_t(first.baseColorTexture)];
  ASSERT_EQ(baked.floats.size(), size_t(baked.width) * baked.height * 3);
  EXPECT_FLOAT_EQ(baked.floats[0], 0.25f);  // half of the first texel, 0.5
  const Material& rough = scene.materials[scene.meshes[2].triangleMaterials[0]];
  ASSERT_NE(rough.roughnessTexture, kNoTexture);
  const Texture& roughness = scene.textures[size_t(rough.roughnessTexture)];
  ASSERT_EQ(roughness.floats.size(), 2u);
  EXPECT_FLOAT_EQ(roughness.floats[0], std::sqrt(0.25f));  // candela's roughness is sqrt(alpha)
}

// A mix that would not fit the load's budget is refused in one line naming where it is defined, before it (or
// any other mix) is baked.
TEST(PbrtLoader, MixTexturesBeyondTheLoadBudgetAreRefusedNamingTheTexture) {
  const std::string text =
      std::string(kMirroredCamera) +
      "Texture \"c\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [1 1 1] \"float uscale\" 64 \"float vscale\" 64\n"
      "Texture \"m\" \"spectrum\" \"mix\" \"texture tex1\" \"c\" \"rgb tex2\" [0 0 0]\n"
      "Material \"diffuse\" \"texture reflectance\" \"m\"\n" +
      kTriangle;
  setProcessMemoryLimit(uint64_t(1) << 20);  // the budget of a process already past its limit: nothing
  beginLoadBudget();
  const std::string error = loadError(text);
  setProcessMemoryLimit(0);
  beginLoadBudget();
  EXPECT_NE(error.find("test.pbrt:5: mix texture 'm' baked at 2048x2048 texels needs about 48 MiB"), std::string::npos)
      << error;
}

// A roughness made from a mix is charged as the mix is, when a material first names it, and refused in one line
// naming where, before the mix is baked (a bake of 4096x4096 texels is 192 MiB).
TEST(PbrtLoader, RoughnessOfAMixBeyondTheLoadBudgetIsRefusedNamingTheTexture) {
  const std::string text =
      std::string(kMirroredCamera) +
      "Texture \"c\" \"float\" \"checkerboard\" \"float tex1\" 1 \"float uscale\" 64 \"float vscale\" 64\n"
      "Texture \"m\" \"float\" \"mix\" \"texture tex1\" \"c\" \"float tex2\" 0\n"
      "Material \"conductor\" \"texture roughness\" \"m\"\n" +
      kTriangle;
  beginLoadBudget();
  // Room for the mix's 48 MiB and not for its roughness's 16 MiB more.
  const uint64_t room = uint64_t(56) << 20;
  const uint64_t taken = loadMemoryLeft() - room;
  chargeLoadMemory(taken, "test", "the rest of the scene");
  const std::string error = loadError(text);
  releaseLoadMemory(taken);
  beginLoadBudget();
  EXPECT_NE(error.find("test.pbrt:6: the roughness of texture 'm' at 2048x2048 texels needs about 16 MiB"),
            std::string::npos)
      << error;
}

// A material that takes one colour of a mix (diffusetransmission's transmittance, hair, subsurface) reads the
// mix's mean from its inputs, as the baked image's mean, without baking it then.
TEST(PbrtLoader, MeanOfAMixTextureIsTheMeanOfItsBake) {
  TempFolder folder;
  folder.write("grey.pfm", std::string("Pf\n2 1\n-1.0\n") + std::string("\0\0\0\x3f\0\0\x80\x3f", 8));
  const std::string path =
      folder.write("scene.pbrt", std::string(kMirroredCamera) +
                                     "Texture \"g\" \"spectrum\" \"imagemap\" \"string filename\" \"grey.pfm\"\n"
                                     "Texture \"m\" \"spectrum\" \"mix\" \"texture tex1\" \"g\" \"rgb tex2\" [0 0 0]\n"
                                     "Material \"diffusetransmission\" \"texture transmittance\" \"m\"\n" +
                                     kTriangle);
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  const Material& m = scene.materials[scene.meshes[0].triangleMaterials[0]];
  // Half of the texels 0.5 and 1, in the mean.
  EXPECT_NEAR(m.transmittance.x, 0.375f, 1e-6f);
  EXPECT_NEAR(m.transmittance.z, 0.375f, 1e-6f);
}

TEST(PbrtLoader, RoughnessTexturesBecomeCandelasRoughness) {
  TempFolder folder;
  folder.write("grey.pfm", std::string("Pf\n2 1\n-1.0\n") + std::string("\0\0\0\x3f\0\0\x80\x3f", 8));
  std::string path = folder.write("scene.pbrt", std::string(kMirroredCamera) +
                                                    "Texture \"r\" \"float\" \"imagemap\" \"string filename\" "
                                                    "\"grey.pfm\" \"float scale\" 0.5\n"
                                                    "Material \"conductor\" \"texture roughness\" \"r\"\n" +
                                                    kTriangle);
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();
  const Material& m = scene.materials[scene.meshes[0].triangleMaterials[0]];
  EXPECT_EQ(m.type, MaterialType::Pbr);
  EXPECT_FLOAT_EQ(m.roughness, 1.0f);
  ASSERT_NE(m.roughnessTexture, kNoTexture);
  const Texture& r = scene.textures[size_t(m.roughnessTexture)];
  ASSERT_EQ(r.floats.size(), 2u);
  // pbrt's value 0.5 * texel, remapped: alpha = sqrt(value); candela's roughness = sqrt(alpha).
  EXPECT_NEAR(r.floats[0], std::pow(0.25f, 0.25f), 1e-5f);
  EXPECT_NEAR(r.floats[1], std::pow(0.5f, 0.25f), 1e-5f);
}

TEST(PbrtLoader, PfmTexturesAreDownscaledToTheSizeLimitWhileRead) {
  TempFolder folder;
  // 4 x 1 grey texels 1, 3, 5, 7, read at most 2 wide: the means of pairs.
  std::string texels;
  for (float v : {1.0f, 3.0f, 5.0f, 7.0f}) texels.append(reinterpret_cast<const char*>(&v), sizeof v);
  folder.write("wide.pfm", "Pf\n4 1\n-1.0\n" + texels);
  std::string path =
      folder.write("scene.pbrt", std::string(kMirroredCamera) +
                                     "Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" "
                                     "\"wide.pfm\"\nMaterial \"diffuse\" \"texture reflectance\" \"t\"\n" +
                                     kTriangle);
  const TextureLimits saved = textureLimits();
  setTextureLimits({2, saved.maxBytes});
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  setTextureLimits(saved);
  const Material& m = scene.materials[scene.meshes[0].triangleMaterials[0]];
  ASSERT_NE(m.baseColorTexture, kNoTexture);
  const Texture& t = scene.textures[size_t(m.baseColorTexture)];
  EXPECT_EQ(t.width, 2u);
  EXPECT_EQ(t.height, 1u);
  ASSERT_EQ(t.floats.size(), 2u);
  EXPECT_FLOAT_EQ(t.floats[0], 2.0f);
  EXPECT_FLOAT_EQ(t.floats[1], 6.0f);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("texture of 4x1 pixels downscaled to 2x1"), std::string::npos)
      << warnings.messages[0];
}

TEST(PbrtLoader, InvertedImageTextures) {
  TempFolder folder;
  folder.write("grey.pfm", std::string("Pf\n2 1\n-1.0\n") + std::string("\0\0\0\x3f\0\0\x80\x3f", 8));
  std::string path = folder.write("scene.pbrt", std::string(kMirroredCamera) +
                                                    "Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" "
                                                    "\"grey.pfm\" \"bool invert\" true\n"
                                                    "Material \"diffuse\" \"texture reflectance\" \"t\"\n" +
                                                    kTriangle);
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  const Material& m = scene.materials[scene.meshes[0].triangleMaterials[0]];
  ASSERT_NE(m.baseColorTexture, kNoTexture);
  const Texture& inverted = scene.textures[size_t(m.baseColorTexture)];
  ASSERT_EQ(inverted.floats.size(), 2u);
  EXPECT_FLOAT_EQ(inverted.floats[0], 0.5f);
  EXPECT_FLOAT_EQ(inverted.floats[1], 0.0f);
}

TEST(PbrtLoader, RepeatedShapesAndIncludesShareTheirMeshes) {
  TempFolder folder;
  folder.write("part.pbrt", "AttributeBegin\nTranslate 0 0 1\n" + std::string(kTriangle) + "AttributeEnd\n");
  std::string main = folder.write("main.pbrt", std::string(kMirroredCamera) +
                                                   "Include \"part.pbrt\"\nTranslate 5 0 0\nInclude \"part.pbrt\"\n"
                                                   "Shape \"sphere\" \"float radius\" 2\n"
                                                   "Translate 0 5 0\nShape \"sphere\" \"float radius\" 3\n");
  LoadWarnings warnings;
  Scene scene = loadPbrt(main, warnings);
  ASSERT_EQ(scene.meshes.size(), 2u);  // one triangle, one sphere
  ASSERT_EQ(scene.instances.size(), 4u);
  EXPECT_EQ(scene.instances[0].meshId, scene.instances[1].meshId);
  EXPECT_EQ(scene.instances[2].meshId, scene.instances[3].meshId);
  // The second Include is placed where reading it would put it: 5 along x (mirrored) and 1 along z.
  const Vec3 first = scene.instances[0].objectToWorld.point({0, 0, 0});
  const Vec3 second = scene.instances[1].objectToWorld.point({0, 0, 0});
  EXPECT_NEAR(std::fabs(second.x - first.x), 5.0f, 1e-5f);
  EXPECT_NEAR(second.z, 1.0f, 1e-5f);
  EXPECT_NEAR(length(scene.instances[3].objectToWorld.point({1, 0, 0}) -
                     scene.instances[3].objectToWorld.point({0, 0, 0})),
              3.0f, 1e-5f);
}

TEST(PbrtLoader, TexturesNoMaterialUsesAreNotDecoded) {
  TempFolder folder;
  std::string main =
      folder.write("main.pbrt", std::string(kMirroredCamera) +
                                    "Texture \"unused\" \"spectrum\" \"imagemap\" \"string filename\" "
                                    "\"nowhere.png\"\n"
                                    "Texture \"mixed\" \"spectrum\" \"mix\" \"texture tex1\" \"unused\"\n" +
                                    kTriangle);
  LoadWarnings warnings;
  Scene scene = loadPbrt(main, warnings);
  EXPECT_TRUE(scene.textures.empty());
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();
}

TEST(PbrtLoader, SceneCacheNoticesChangedIncludes) {
  TempFolder folder;
  folder.write("part.pbrt", kTriangle);
  std::string main = folder.write("main.pbrt", std::string(kMirroredCamera) + "Include \"part.pbrt\"\n");
  SceneLoadOptions options;
  options.cache = {true, folder.file("cache")};
  EXPECT_EQ(loadScene(main, options).triangleCount(), 1u);
  EXPECT_EQ(loadScene(main, options).triangleCount(), 1u);  // from the cache
  folder.write("part.pbrt", std::string(kTriangle) + kTriangle);
  EXPECT_EQ(loadScene(main, options).triangleCount(), 2u);
}

TEST(PbrtLoader, QuadricsAreTessellatedOnTheirSurface) {
  Scene scene = loadText(std::string(kMirroredCamera) +
                         "Shape \"sphere\" \"float radius\" 2\n"
                         "Shape \"disk\" \"float radius\" 1 \"float height\" 0.5\n"
                         "Shape \"cylinder\" \"float radius\" 1 \"float zmin\" 0 "
                         "\"float zmax\" 3\n");
  ASSERT_EQ(scene.meshes.size(), 3u);
  ASSERT_EQ(scene.instances[0].meshId, 0u);
  for (size_t i = 0; i < scene.meshes[0].positions.size(); ++i) {
    // A whole sphere is the one of radius 1, scaled by its instance.
    EXPECT_NEAR(length(scene.instances[0].objectToWorld.point(scene.meshes[0].positions[i])), 2.0f, 1e-4f);
    EXPECT_GT(dot(scene.meshes[0].normals[i], scene.meshes[0].positions[i]), 0.0f);  // outwards
  }
  for (Vec3 p : scene.meshes[1].positions) EXPECT_FLOAT_EQ(p.z, 0.5f);
  for (Vec3 p : scene.meshes[2].positions) EXPECT_NEAR(std::hypot(p.x, p.y), 1.0f, 1e-5f);
  // The sphere's front faces outwards.
  const Mesh& sphere = scene.meshes[0];
  for (size_t t = 0; t < sphere.triangleCount(); ++t) {
    Vec3 a = sphere.positions[sphere.indices[3 * t]], b = sphere.positions[sphere.indices[3 * t + 1]];
    Vec3 c = sphere.positions[sphere.indices[3 * t + 2]];
    Vec3 n = cross(b - a, c - a);
    if (length(n) > 1e-6f) {
      EXPECT_GT(dot(n, a + b + c), 0.0f);
    }
  }
}

TEST(PbrtLoader, BilinearMeshesAndLoopSubdivision) {
  Scene scene = loadText(std::string(kMirroredCamera) +
                         "Shape \"bilinearmesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 1 1 0]\n"
                         "Shape \"loopsubdiv\" \"integer levels\" 2 \"point3 P\" [0 0 0 1 0 0 0 1 0 0 0 1] "
                         "\"integer indices\" [0 2 1 0 1 3 0 3 2 1 2 3]\n");
  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.meshes[0].triangleCount(), 2u);
  EXPECT_GT(windingNormal(scene, 0, 0).z, 0.0f);  // cross(dp/du, dp/dv) = +z
  EXPECT_EQ(scene.meshes[1].triangleCount(), 4u * 16u);
  // Loop subdivision of a closed mesh shrinks it towards its centroid: every vertex inside the hull.
  for (Vec3 p : scene.meshes[1].positions) EXPECT_LT(p.x + p.y + p.z, 1.0f);
}

TEST(PbrtLoader, LoopSubdivisionEndsOnTheLimitSurface) {
  // With no levels, pbrt still moves the control points to the limit surface: a vertex of valence 3 keeps 2/5 of
  // itself and takes 1/5 of each neighbour.
  Scene scene = loadText(std::string(kMirroredCamera) +
                         "Shape \"loopsubdiv\" \"integer levels\" 0 \"point3 P\" [0 0 0 1 0 0 0 1 0 0 0 1] "
                         "\"integer indices\" [0 2 1 0 1 3 0 3 2 1 2 3]\n");
  ASSERT_EQ(scene.meshes.size(), 1u);
  expectNear(scene.meshes[0].positions[0], {0.2f, 0.2f, 0.2f});
  expectNear(scene.meshes[0].positions[1], {0.4f, 0.2f, 0.2f});
}

std::string plyHeader(const std::string& format, int vertices, int faces) {
  return "ply\nformat " + format + " 1.0\ncomment test\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nproperty float u\nproperty float v\n"
         "element face " +
         std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

// A unit quad: 4 vertices with texture coordinates and one face of 4 indices.
std::string binaryQuadPly(bool bigEndian) {
  std::string out = plyHeader(bigEndian ? "binary_big_endian" : "binary_little_endian", 4, 1);
  auto put = [&](const void* p, size_t n) {
    std::string bytes(static_cast<const char*>(p), n);
    if (bigEndian) std::reverse(bytes.begin(), bytes.end());
    out += bytes;
  };
  const float v[4][5] = {{0, 0, 0, 0, 0}, {1, 0, 0, 1, 0}, {1, 1, 0, 1, 1}, {0, 1, 0, 0, 1}};
  for (const auto& vertex : v)
    for (float f : vertex) put(&f, 4);
  out += char(4);
  for (int32_t i : {0, 1, 2, 3}) put(&i, 4);
  return out;
}

std::string gzip(const std::string& data) {
  z_stream s{};
  deflateInit2(&s, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY);
  std::string out(deflateBound(&s, uLong(data.size())) + 32, '\0');
  s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  s.avail_in = uInt(data.size());
  s.next_out = reinterpret_cast<Bytef*>(out.data());
  s.avail_out = uInt(out.size());
  deflate(&s, Z_FINISH);
  out.resize(s.total_out);
  deflateEnd(&s);
  return out;
}

TEST(PbrtLoader, PlyMeshesInEveryEncoding) {
  TempFolder folder;
  std::string ascii = plyHeader("ascii", 4, 1) + "0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 1\n4 0 1 2 3\n";
  folder.write("ascii.ply", ascii);
  folder.write("le.ply", binaryQuadPly(false));
  folder.write("be.ply", binaryQuadPly(true));
  folder.write("packed.ply.gz", gzip(binaryQuadPly(false)));
  for (const char* name : {"ascii.ply", "le.ply", "be.ply", "packed.ply.gz"}) {
    std::string scenePath = folder.write("scene.pbrt", std::string(kMirroredCamera) +
                                                           "Shape \"plymesh\" \"string filename\" \"" + name + "\"\n");
    LoadWarnings warnings;
    Scene scene = loadPbrt(scenePath, warnings);
    ASSERT_EQ(scene.meshes.size(), 1u) << name;
    const Mesh& m = scene.meshes[0];
    EXPECT_EQ(m.triangleCount(), 2u) << name;
    ASSERT_EQ(m.positions.size(), 4u) << name;
    expectNear(m.positions[2], {1, 1, 0});
    ASSERT_EQ(m.uvs.size(), 4u) << name;
    EXPECT_FLOAT_EQ(m.uvs[2].y, 0.0f) << name;  // pbrt's v = 1 is the top row: candela's v = 0
    EXPECT_GT(windingNormal(scene, 0, 0).z, 0.0f) << name;
    EXPECT_NE(std::find(scene.inputFiles.begin(), scene.inputFiles.end(), folder.file(name)), scene.inputFiles.end());
  }
}

TEST(PbrtLoader, PlyFacesOfMixedSizes) {
  // Lists of different lengths make tinyply read the faces twice, seeking back in between.
  TempFolder folder;
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  const float vertices[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
  ply.append(reinterpret_cast<const char*>(vertices), sizeof(vertices));
  const int32_t quad[4] = {0, 1, 2, 3}, triangle[3] = {1, 4, 2};
  ply += char(4);
  ply.append(reinterpret_cast<const char*>(quad), sizeof(quad));
  ply += char(3);
  ply.append(reinterpret_cast<const char*>(triangle), sizeof(triangle));
  folder.write("mixed.ply", ply);
  std::string path = folder.write("scene.pbrt", std::string(kMirroredCamera) +
                                                    "Shape \"plymesh\" \"string filename\" \"mixed.ply\"\n");
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
}

TEST(PbrtLoader, HostilePlyFilesAreRefused) {
  TempFolder folder;
  folder.write("huge.ply", plyHeader("binary_little_endian", 1000000000, 1) + std::string(64, '\0'));
  folder.write("badindex.ply", plyHeader("ascii", 3, 1) + "0 0 0 0 0\n1 0 0 0 0\n0 1 0 0 0\n3 0 1 7\n");
  folder.write("bomb.ply.gz", "not gzip at all");
  for (const char* name : {"huge.ply", "badindex.ply", "bomb.ply.gz"}) {
    std::string scenePath =
        folder.write("scene.pbrt", std::string("WorldBegin\nShape \"plymesh\" \"string filename\" \"") + name + "\"\n");
    LoadWarnings warnings;
    try {
      loadPbrt(scenePath, warnings);
      ADD_FAILURE() << name << " loaded";
    } catch (const LoadError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

TEST(PbrtLoader, IncludesAreConfinedAndBounded) {
  TempFolder folder;
  folder.write("parts/geometry.pbrt", kTriangle);
  std::string main = folder.write("main.pbrt", std::string(kMirroredCamera) +
                                                   "Include \"parts/geometry.pbrt\"\n"
                                                   "Import \"parts/geometry.pbrt\"\n");
  LoadWarnings warnings;
  Scene scene = loadPbrt(main, warnings);
  EXPECT_EQ(scene.instances.size(), 2u);
  EXPECT_EQ(scene.inputFiles.size(), 2u);  // the scene and the included file, once
  std::string self = folder.write("self.pbrt", "Include \"self.pbrt\"\n");
  try {
    loadPbrt(self, warnings);
    ADD_FAILURE() << "a file including itself loaded";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("deep"), std::string::npos) << e.what();
  }
  std::string outside = folder.write("out.pbrt", "Include \"../../etc/passwd\"\n");
  try {
    loadPbrt(outside, warnings);
    ADD_FAILURE() << "an include outside the scene's folder was read";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("out.pbrt:1:"), std::string::npos) << e.what();
  }
}

TEST(PbrtSpectra, ConversionsToRgb) {
  Vec3 d65ish = blackbodyRgb(6504.0f);
  EXPECT_NEAR(luminance(d65ish), 1.0f, 0.01f);
  EXPECT_NEAR(d65ish.x / d65ish.z, 1.0f, 0.15f);  // a blackbody near 6500 K is close to sRGB's white
  expectNear(sampledSpectrumRgb({400, 0.5, 700, 0.5}), {0.5f, 0.5f, 0.5f}, 1e-3f);
  Vec3 red = sampledSpectrumRgb({400, 0, 590, 0, 610, 1, 700, 1});
  EXPECT_GT(red.x, 5.0f * red.z);
  expectNear(*namedSpectrumRgb("stdillum-D65"), {1, 1, 1});
  EXPECT_FALSE(namedSpectrumRgb("no-such-spectrum"));
  expectNear(conductorReflectance({1.5f, 1.5f, 1.5f}, {0, 0, 0}), {0.04f, 0.04f, 0.04f});
}

TEST(PbrtLights, EqualAreaOctahedralMapping) {
  Vec2 up = equalAreaSphereToSquare({0, 0, 1});
  EXPECT_FLOAT_EQ(up.x, 0.5f);
  EXPECT_FLOAT_EQ(up.y, 0.5f);
  Vec2 x = equalAreaSphereToSquare({1, 0, 0});
  EXPECT_FLOAT_EQ(x.x, 1.0f);
  EXPECT_FLOAT_EQ(x.y, 0.5f);
  Vec2 down = equalAreaSphereToSquare({0, 0, -1});
  EXPECT_FLOAT_EQ(down.x, 1.0f);
  EXPECT_FLOAT_EQ(down.y, 1.0f);
}

// A square PFM whose centre (pbrt's +z in the octahedral layout) is red and whose corners (-z) are blue.
// A little-endian RGB PFM of width x height whose texel (row, column) is texel(row, column); PFM rows run from the
// bottom of the image.
template <class Texel>
std::string pfmImage(int width, int height, const Texel& texel) {
  std::string out = "PF\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      const Vec3 c = texel(row, column);
      const float rgb[3] = {c.x, c.y, c.z};
      out.append(reinterpret_cast<const char*>(rgb), sizeof(rgb));
    }
  return out;
}

Vec3 redOrBlue(bool red) { return red ? Vec3{1, 0, 0} : Vec3{0, 0, 1}; }

std::string octahedralPfm(int size) {
  return pfmImage(size, size, [&](int row, int column) {
    float u = (float(column) + 0.5f) / float(size) * 2 - 1, v = (float(row) + 0.5f) / float(size) * 2 - 1;
    return redOrBlue(std::fabs(u) + std::fabs(v) < 1.0f);
  });
}

TEST(PbrtLights, OctahedralMapsFollowTheMirroredWorld) {
  // A map whose pbrt +x half (u > 0.5 in the octahedral square) is red, under pbrt's default camera: the world
  // is mirrored, so pbrt's +x is candela's -x, where candela's map has u = 0.25.
  TempFolder folder;
  folder.write("sky.pfm", pfmImage(16, 16, [](int, int column) { return redOrBlue(column >= 8); }));
  std::string path =
      folder.write("scene.pbrt", "WorldBegin\nLightSource \"infinite\" \"string filename\" \"sky.pfm\"\n");
  LoadWarnings warnings;
  const Texture& map = loadPbrt(path, warnings).environment.map;
  ASSERT_EQ(map.width, 32u);
  const float* minusX = map.floats.data() + (size_t(map.height / 2) * map.width + map.width / 4) * 3;
  const float* plusX = map.floats.data() + (size_t(map.height / 2) * map.width + 3 * map.width / 4) * 3;
  EXPECT_GT(minusX[0], 0.9f);
  EXPECT_GT(plusX[2], 0.9f);
}

// pbrt-v4's `illuminance` of an infinite light: the lux it gives a surface facing the light's +z, pi L for a
// uniform L, and the integral of L cos(theta) over that hemisphere for a map.
TEST(PbrtLights, InfiniteLightIlluminanceSetsItsRadiance) {
  Scene constant = loadText("WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 2] \"float illuminance\" 10\n");
  expectNear(constant.environment.radiance, Vec3{1, 1, 2} * (10.0f / kPi));
  TempFolder folder;
  folder.write("sky.pfm", pfmImage(64, 32, [](int, int) { return Vec3{2, 2, 2}; }));
  std::string path = folder.write("scene.pbrt", std::string(kMirroredCamera) +
                                                    "LightSource \"infinite\" \"string filename\" \"sky.pfm\" "
                                                    "\"float illuminance\" 10 \"float scale\" 3\n");
  LoadWarnings warnings;
  const Texture& map = loadPbrt(path, warnings).environment.map;
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  ASSERT_FALSE(map.floats.empty());
  EXPECT_NEAR(map.floats[(size_t(5) * map.width + 7) * 3], 3.0f * 10.0f / kPi, 0.02f * 3.0f * 10.0f / kPi);
}

TEST(PbrtLights, PbrtV3EquirectangularMaps) {
  // pbrt-v3's layout: u = phi / 2pi about the light's +z, v = theta / pi from +z. A map whose top half is red
  // (the light's +z hemisphere), turned so that +z is world +y: red above, blue below.
  TempFolder folder;
  folder.write("sky.pfm", pfmImage(32, 16, [](int row, int) { return redOrBlue(row >= 8); }));
  std::string path = folder.write("scene.pbrt", std::string(kMirroredCamera) +
                                                    "Rotate -90 1 0 0\nLightSource \"infinite\" \"string filename\" "
                                                    "\"sky.pfm\"\n");
  LoadWarnings warnings;
  const Texture& map = loadPbrt(path, warnings).environment.map;
  ASSERT_EQ(map.height, 16u);
  EXPECT_GT(map.floats[(size_t(1) * map.width + 5) * 3], 0.9f);
  EXPECT_GT(map.floats[(size_t(map.height - 2) * map.width + 5) * 3 + 2], 0.9f);
}

TEST(PbrtLights, OctahedralMapsBecomeEquirectangularThroughTheLightTransform) {
  TempFolder folder;
  folder.write("sky.pfm", octahedralPfm(64));
  // Rotate -90 about x takes the light's +z to world +y: the red hemisphere must end up above.
  std::string path = folder.write("scene.pbrt", std::string(kMirroredCamera) +
                                                    "AttributeBegin\nRotate -90 1 0 0\nLightSource \"infinite\" "
                                                    "\"string filename\" \"sky.pfm\"\nAttributeEnd\n");
  LoadWarnings warnings;
  Scene scene = loadPbrt(path, warnings);
  ASSERT_TRUE(scene.environment.hasMap());
  const Texture& map = scene.environment.map;
  auto texel = [&](uint32_t row, uint32_t column) {
    const float* p = map.floats.data() + (size_t(row) * map.width + column) * map.channels;
    return Vec3{p[0], p[1], p[2]};
  };
  EXPECT_GT(texel(2, map.width / 2).x, 0.9f);               // near the zenith
  EXPECT_GT(texel(map.height - 3, map.width / 2).z, 0.9f);  // near the nadir
}

// The built-in Cornell box written out as a pbrt scene (in pbrt's customary mirrored camera frame) renders as
// the built-in one does.
std::string cornellBoxAsPbrt() {
  Scene box = makeCornellBox();
  std::ostringstream out;
  out.precision(9);
  Vec3 e = box.camera.eye, t = box.camera.target, u = box.camera.up;
  out << "Film \"rgb\" \"integer xresolution\" 48 \"integer yresolution\" 48\n";
  out << "Scale -1 1 1\nLookAt " << e.x << ' ' << e.y << ' ' << e.z << ' ' << t.x << ' ' << t.y << ' ' << t.z << ' '
      << u.x << ' ' << u.y << ' ' << u.z << "\n";
  out << "Camera \"perspective\" \"float fov\" " << box.camera.verticalFovDegrees << "\nWorldBegin\n";
  const Mesh& room = box.meshes[0];
  for (uint32_t id = 0; id < box.materials.size(); ++id) {
    const Material& m = box.materials[id];
    out << "AttributeBegin\nMaterial \"diffuse\" \"rgb reflectance\" [" << m.baseColor.x << ' ' << m.baseColor.y << ' '
        << m.baseColor.z << "]\n";
    if (!isBlack(m.emission))
      out << "AreaLightSource \"diffuse\" \"rgb L\" [" << m.emission.x << ' ' << m.emission.y << ' ' << m.emission.z
          << "]\n";
    out << "Shape \"trianglemesh\" \"point3 P\" [";
    uint32_t count = 0;
    for (size_t tri = 0; tri < room.triangleCount(); ++tri) {
      if (room.triangleMaterials[tri] != id) continue;
      for (int k = 0; k < 3; ++k) {
        Vec3 p = room.positions[room.indices[3 * tri + k]];
        out << p.x << ' ' << p.y << ' ' << p.z << ' ';
      }
      ++count;
    }
    out << "] \"integer indices\" [";
    for (uint32_t i = 0; i < 3 * count; ++i) out << i << ' ';
    out << "]\nAttributeEnd\n";
  }
  return out.str();
}

// A two-sided light is its triangles twice, one copy per winding, coincident: whichever the traversal reports
// first, a ray meets the copy that faces it, because each copy's back faces are culled. A camera looking up at a
// light panel sees its radiance whichever way the file winds it (the copy wound away from the camera came first
// in one of the two files, and was what the CPU backend's traversal reported before the culling).
TEST(PbrtLoader, TwoSidedLightsAreSeenFromEitherSideWhateverTheirWinding) {
  TempFolder folder;
  for (const char* indices : {"0 1 2 0 2 3", "0 2 1 0 3 2"}) {
    SCOPED_TRACE(indices);
    const std::string text =
        std::string(
            "LookAt 0 0 0  0 1 0  0 0 1\nCamera \"perspective\" \"float fov\" 20\n"
            "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\nWorldBegin\n"
            "AreaLightSource \"diffuse\" \"rgb L\" [4 2 1] \"bool twosided\" true\n"
            "Shape \"trianglemesh\" \"point3 P\" [-1 1 -1  1 1 -1  1 1 1  -1 1 1] \"integer indices\" [") +
        indices + "]\n";
    RenderJob job;
    job.settings.width = job.settings.height = 8;
    job.given.width = job.given.height = job.given.samplesPerPixel = true;
    job.samplesPerPixel = 4;
    job.backend = "cpu";
    const Scene scene = loadScene(folder.write("panel.pbrt", text), {});
    for (const Material& m : scene.materials) EXPECT_TRUE(isBlack(m.emission) || m.doubleSided == 0u);
    const RenderOutcome outcome = renderLoadedScene(job, scene, false);
    for (const Vec3& p : outcome.image.pixels) {
      EXPECT_NEAR(p.x, 4.0f, 1e-3f);
      EXPECT_NEAR(p.z, 1.0f, 1e-3f);
    }
  }
  // A one-sided light's back stays there for rays (dark, not culled).
  Scene oneSided = loadText(std::string(kMirroredCamera) + "AreaLightSource \"diffuse\"\n" + kTriangle);
  EXPECT_EQ(oneSided.materials[oneSided.meshes[0].triangleMaterials[0]].doubleSided, 1u);
}

TEST(PbrtLoader, CornellBoxRendersLikeTheBuiltInOne) {
  TempFolder folder;
  std::string path = folder.write("cornell.pbrt", cornellBoxAsPbrt());
  RenderJob job;
  job.settings.width = 48;
  job.settings.height = 48;
  job.given.width = job.given.height = job.given.samplesPerPixel = job.given.maxDepth = true;
  job.samplesPerPixel = 64;
  job.backend = "cpu";
  Scene fromPbrt = loadScene(path, {});
  EXPECT_EQ(*fromPbrt.renderHints.width, 48u);
  RenderOutcome pbrt = renderLoadedScene(job, fromPbrt, false);
  RenderOutcome builtin = renderLoadedScene(job, loadScene("cornell-box", {}), false);
  // Compare the means of the four quadrants: the red wall is on the left, the green one on the right.
  auto quadrant = [](const Image& image, int qx, int qy) {
    Vec3 sum{0, 0, 0};
    int n = 0;
    for (uint32_t y = 0; y < image.height; ++y)
      for (uint32_t x = 0; x < image.width; ++x)
        if (int(2 * x / image.width) == qx && int(2 * y / image.height) == qy) {
          sum += image.pixels[size_t(y) * image.width + x];
          ++n;
        }
    return sum / float(n);
  };
  for (int qy = 0; qy < 2; ++qy)
    for (int qx = 0; qx < 2; ++qx) {
      Vec3 a = quadrant(pbrt.image, qx, qy), b = quadrant(builtin.image, qx, qy);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 0.05f * b[c] + 0.002f) << "quadrant " << qx << ',' << qy;
    }
  EXPECT_GT(quadrant(pbrt.image, 0, 1).x, quadrant(pbrt.image, 1, 1).x);  // red wall on the left
}

}  // namespace
}  // namespace candela
