// pbrt-v4's `subsurface` and `diffusetransmission` materials as the loader reads them: each form of subsurface
// parameters becomes a dielectric boundary around the medium of a random walk, hostile parameters are refused
// with one line, and a loaded subsurface scene renders.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/load_diagnostics.h"
#include "scene/scene_repair.h"
#include "scene/subsurface_albedo.h"
#include "support/pbrt_text.h"
#include "support/render_statistics.h"

namespace candela::test {
namespace {

using pbrt::loadError;

Scene loadText(const std::string& text, LoadWarnings& warnings) { return pbrt::loadText(text, &warnings); }

// A scene of one sphere of the material `material` (a Material directive's type and parameters).
std::string sphereOf(const std::string& material) {
  return "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 45\n"
         "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\nWorldBegin\n"
         "LightSource \"infinite\" \"rgb L\" [1 1 1]\nMaterial " +
         material + "\nShape \"sphere\" \"float radius\" 1\n";
}

// Whether any warning mentions `text`.
bool warned(const LoadWarnings& warnings, const std::string& text) {
  for (const std::string& m : warnings.messages)
    if (m.find(text) != std::string::npos) return true;
  return false;
}

void expectNear(Vec3 a, Vec3 b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// The sphere's boundary and the medium inside it.
struct Subsurface {
  Material boundary;
  Medium interior;
};

Subsurface loadSubsurface(const std::string& parameters, LoadWarnings& warnings) {
  const Scene scene = loadText(sphereOf("\"subsurface\" " + parameters), warnings);
  EXPECT_FALSE(warned(warnings, "diffuse")) << (warnings.messages.empty() ? "" : warnings.messages[0]);
  EXPECT_EQ(scene.media.size(), 1u);
  EXPECT_EQ(scene.instances.size(), 1u);
  if (scene.media.size() != 1 || scene.instances.size() != 1) return {};
  EXPECT_EQ(scene.instances[0].media.inside, 0u);
  EXPECT_EQ(scene.instances[0].media.outside, kNoMedium);
  EXPECT_EQ(scene.media[0].subsurface, 1u);
  const uint32_t material = scene.meshes[scene.instances[0].meshId].triangleMaterials[0];
  return {scene.materials[material], scene.media[0]};
}

TEST(PbrtSubsurface, EachFormBecomesADielectricAroundAMedium) {
  LoadWarnings warnings;
  // pbrt's defaults: whole milk per millimetre, inside smooth glass of index 1.33.
  Subsurface s = loadSubsurface("", warnings);
  EXPECT_EQ(s.boundary.type, MaterialType::Glass);
  EXPECT_FLOAT_EQ(s.boundary.ior, 1.33f);
  expectNear(s.interior.sigmaA, {0.0011f, 0.0024f, 0.014f}, 1e-7f);
  expectNear(s.interior.sigmaS, {2.55f, 3.21f, 3.77f}, 1e-6f);

  // A measured preset, scaled; its g is 0 whatever the file says, with a warning.
  s = loadSubsurface("\"string name\" \"Ketchup\" \"float scale\" 10 \"float g\" 0.5 \"float eta\" 1.4", warnings);
  expectNear(s.interior.sigmaA, {0.61f, 9.7f, 14.5f}, 1e-5f);
  expectNear(s.interior.sigmaS, {1.8f, 0.7f, 0.3f}, 1e-5f);
  EXPECT_EQ(s.interior.g, 0.0f);
  EXPECT_FLOAT_EQ(s.boundary.ior, 1.4f);
  EXPECT_TRUE(warned(warnings, "'g' is ignored with a named medium"));

  // The coefficients themselves, scaled, with g and a rough boundary.
  s = loadSubsurface(
      "\"rgb sigma_a\" [0.1 0.2 0.3] \"rgb sigma_s\" [1 2 3] \"float scale\" 2 \"float g\" 0.4 "
      "\"float roughness\" 0.1",
      warnings);
  expectNear(s.interior.sigmaA, {0.2f, 0.4f, 0.6f}, 1e-6f);
  expectNear(s.interior.sigmaS, {2, 4, 6}, 1e-6f);
  EXPECT_FLOAT_EQ(s.interior.g, 0.4f);
  EXPECT_EQ(s.boundary.type, MaterialType::Disney);
  EXPECT_EQ(s.boundary.specTrans, 1.0f);
  EXPECT_GT(s.boundary.roughness, 0.0f);

  // Reflectance and mean free path (times scale): sigma_t = 1 / mfp, the albedo inverted.
  s = loadSubsurface("\"rgb reflectance\" [0.8 0.5 0.2] \"rgb mfp\" [1 0.5 0.25] \"float scale\" 2", warnings);
  const Medium expected = subsurfaceMediumFromReflectance({0.8f, 0.5f, 0.2f}, {2.0f, 1.0f, 0.5f}, 0.0f);
  expectNear(s.interior.sigmaA, expected.sigmaA, 1e-6f);
  expectNear(s.interior.sigmaS, expected.sigmaS, 1e-6f);
  expectNear(mediumSigmaT(s.interior), {0.5f, 1.0f, 2.0f}, 1e-5f);
  EXPECT_FALSE(warned(warnings, "not supported"));
}

// One medium per material, inside every shape of it, and none for materials no shape uses; a mix with a
// subsurface material says what it leaves out.
TEST(PbrtSubsurface, OneMediumPerMaterialInsideItsShapes) {
  LoadWarnings warnings;
  const Scene scene = loadText(
      "WorldBegin\n"
      "MakeNamedMaterial \"skin\" \"string type\" \"subsurface\" \"string name\" \"Skin1\"\n"
      "MakeNamedMaterial \"unused\" \"string type\" \"subsurface\"\n"
      "NamedMaterial \"skin\"\nShape \"sphere\"\n"
      "AttributeBegin\nTranslate 3 0 0\nShape \"sphere\"\nAttributeEnd\n"
      "AttributeBegin\nMaterial \"diffuse\"\nTranslate 6 0 0\nShape \"sphere\"\nAttributeEnd\n",
      warnings);
  ASSERT_EQ(scene.media.size(), 1u);
  ASSERT_EQ(scene.instances.size(), 3u);
  EXPECT_EQ(scene.instances[0].media.inside, 0u);
  EXPECT_EQ(scene.instances[1].media.inside, 0u);
  EXPECT_EQ(scene.instances[2].media.inside, kNoMedium);
  EXPECT_EQ(scene.instances[2].media.outside, kNoMedium);

  LoadWarnings mixWarnings;
  loadText(
      "WorldBegin\nMakeNamedMaterial \"skin\" \"string type\" \"subsurface\"\n"
      "MakeNamedMaterial \"paint\" \"string type\" \"diffuse\"\n"
      "Material \"mix\" \"string materials\" [\"skin\" \"paint\"]\nShape \"sphere\"\n",
      mixWarnings);
  EXPECT_TRUE(warned(mixWarnings, "without the medium inside"));
}

TEST(PbrtSubsurface, DiffuseTransmissionIsItsOwnModel) {
  LoadWarnings warnings;
  Scene scene = loadText(sphereOf("\"diffusetransmission\" \"rgb reflectance\" [0.2 0.3 0.4] "
                                  "\"rgb transmittance\" [0.5 0.6 0.7] \"float scale\" 1.5"),
                         warnings);
  EXPECT_FALSE(warned(warnings, "diffuse reflection")) << (warnings.messages.empty() ? "" : warnings.messages[0]);
  const Material& m = scene.materials[scene.meshes[0].triangleMaterials[0]];
  EXPECT_EQ(m.type, MaterialType::DiffuseTransmission);
  expectNear(m.baseColor, {0.3f, 0.45f, 0.6f}, 1e-6f);
  expectNear(m.transmittance, {0.75f, 0.9f, 1.0f}, 1e-6f);  // clamped to 1, as pbrt-v4 does

  scene = loadText(sphereOf("\"diffusetransmission\""), warnings);
  const Material& defaults = scene.materials[scene.meshes[0].triangleMaterials[0]];
  expectNear(defaults.baseColor, {0.25f, 0.25f, 0.25f}, 1e-7f);
  expectNear(defaults.transmittance, {0.25f, 0.25f, 0.25f}, 1e-7f);
  EXPECT_TRUE(scene.media.empty());
}

TEST(PbrtSubsurface, HostileParametersAreRefusedInOneLine) {
  const std::pair<std::string, std::string> cases[] = {
      {"\"rgb reflectance\" [0.5 0.5 0.5] \"rgb mfp\" [1 -1 1]", "'mfp' must be finite and not negative"},
      {"\"rgb reflectance\" [0.5 0.5 0.5] \"rgb mfp\" [1 0 1]", "'mfp' must be positive"},
      {"\"rgb sigma_a\" [1 1 1] \"rgb sigma_s\" [1 -2 1]", "'sigma_s' must be finite and not negative"},
      {"\"rgb sigma_a\" [1 1 1]", "'sigma_a' and 'sigma_s' must be given together"},
      {"\"string name\" \"Jelly\"", "no measured medium is named 'Jelly'"},
      {"\"float g\" 1", "'g' must lie between -1 and 1"},
      {"\"float scale\" 0", "'scale' must be finite and positive"},
      {"\"float eta\" -1", "'eta' must be finite and positive"},
      {"\"rgb sigma_a\" [1 1 1] \"rgb sigma_s\" [10 10 10] \"float scale\" 3e38", "its coefficients overflow"},
  };
  for (const auto& [parameters, message] : cases) {
    const std::string error = loadError(sphereOf("\"subsurface\" " + parameters));
    EXPECT_NE(error.find("test.pbrt:6: subsurface: " + message), std::string::npos) << parameters << ": " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
  // Not-a-number never reaches the material: the parser refuses it.
  std::string error = loadError(sphereOf("\"subsurface\" \"rgb reflectance\" [0.5 nan 0.5]"));
  EXPECT_NE(error.find("test.pbrt:6: 'nan' is not a number"), std::string::npos) << error;
  error = loadError(sphereOf("\"diffusetransmission\" \"float scale\" -1"));
  EXPECT_NE(error.find("'scale' must be finite and not negative"), std::string::npos) << error;
}

// A pbrt subsurface sphere of reflectance 1 under a uniform light, after the repairs every loaded scene goes
// through: the scene takes the media path, and its walk, losing next to nothing, returns the light it takes in
// (the image mean is 1 within the sphere's smooth normals' small departure from energy conservation).
TEST(PbrtSubsurface, WhiteSubsurfaceSphereRendersNearOne) {
  LoadWarnings warnings;
  Scene scene = loadText(sphereOf("\"subsurface\" \"rgb reflectance\" [1 1 1] \"rgb mfp\" [0.5 0.5 0.5]"), warnings);
  repairScene(scene, "test.pbrt", warnings);
  ASSERT_EQ(scene.media.size(), 1u);
  const PixelStatistics stats = renderOnCpu(scene, 16, 16, 8, 16);
  EXPECT_EQ(stats.invalidSamples, 0u);
  const ImageMean mean = imageMean(stats);
  EXPECT_NEAR(mean.mean, 1.0, 0.03) << mean.mean << " +- " << mean.standardError;
}

}  // namespace
}  // namespace candela::test
