// pbrt-v4's `hair` material as the loader reads it: each form of its absorption, pbrt's defaults, hostile
// parameters refused in one line, and a patch of hair on a mesh that loads and renders.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <string>

#include "io/load_diagnostics.h"
#include "kernel/aovs.h"
#include "kernel/bsdf/hair.h"
#include "scene/scene_repair.h"
#include "support/pbrt_text.h"
#include "support/render_statistics.h"

namespace candela::test {
namespace {

using pbrt::loadError;

// A scene of one square patch of the material `material` (a Material directive's type and parameters), across
// the view, its fibres along u, under a uniform white light.
std::string patchOf(const std::string& material) {
  return "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
         "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\nWorldBegin\n"
         "LightSource \"infinite\" \"rgb L\" [1 1 1]\nMaterial " +
         material +
         "\nShape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point3 P\" [-1 -1 0 1 -1 0 1 1 0 -1 1 0] "
         "\"point2 uv\" [0 0 1 0 1 1 0 1]\n";
}

bool warned(const LoadWarnings& warnings, const std::string& text) {
  for (const std::string& m : warnings.messages)
    if (m.find(text) != std::string::npos) return true;
  return false;
}

Material loadHair(const std::string& parameters, LoadWarnings& warnings) {
  const Scene scene = pbrt::loadText(patchOf("\"hair\" " + parameters), &warnings);
  EXPECT_EQ(scene.meshes.size(), 1u);
  if (scene.meshes.empty()) return {};
  return scene.materials[scene.meshes[0].triangleMaterials[0]];
}

void expectNear(Vec3 a, Vec3 b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(PbrtHair, EachFormOfAbsorption) {
  LoadWarnings warnings;
  // pbrt-v4's defaults: brown hair (eumelanin 1.3), eta 1.55, both roughnesses 0.3, scales tilted 2 degrees.
  Material m = loadHair("", warnings);
  EXPECT_EQ(m.type, MaterialType::Hair);
  expectNear(m.fibreAbsorption, Vec3{0.419f, 0.697f, 1.37f} * 1.3f, 1e-5f);
  EXPECT_FLOAT_EQ(m.ior, 1.55f);
  EXPECT_FLOAT_EQ(m.roughness, 0.3f);
  EXPECT_FLOAT_EQ(m.azimuthalRoughness, 0.3f);
  EXPECT_FLOAT_EQ(m.scaleTilt, 2.0f);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();

  m = loadHair(
      "\"rgb sigma_a\" [0.1 0.2 0.3] \"float eta\" 1.6 \"float beta_m\" 0.2 \"float beta_n\" 0.5 "
      "\"float alpha\" 3",
      warnings);
  expectNear(m.fibreAbsorption, {0.1f, 0.2f, 0.3f}, 1e-6f);
  EXPECT_FLOAT_EQ(m.ior, 1.6f);
  EXPECT_FLOAT_EQ(m.roughness, 0.2f);
  EXPECT_FLOAT_EQ(m.azimuthalRoughness, 0.5f);
  EXPECT_FLOAT_EQ(m.scaleTilt, 3.0f);

  m = loadHair("\"float eumelanin\" 0.5 \"float pheomelanin\" 2", warnings);
  expectNear(m.fibreAbsorption, Vec3{0.419f, 0.697f, 1.37f} * 0.5f + Vec3{0.187f, 0.4f, 1.05f} * 2.0f, 1e-5f);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();

  // A colour becomes the absorption that gives it at the material's azimuthal roughness, both ways round.
  for (const char* name : {"reflectance", "color"}) {
    m = loadHair(std::string("\"rgb ") + name + "\" [0.2 0.4 0.6] \"float beta_n\" 0.4", warnings);
    const Vec3 expected = HairBsdf::absorptionOfReflectance({0.2f, 0.4f, 0.6f}, 0.4f);
    expectNear(m.fibreAbsorption, expected, 1e-5f);
    expectNear(HairBsdf::reflectanceOfAbsorption(m.fibreAbsorption, 0.4f), {0.2f, 0.4f, 0.6f}, 1e-5f);
    // The denoisers' albedo guide takes the colour back.
    expectNear(materialAlbedo(m), {0.2f, 0.4f, 0.6f}, 1e-5f);
    // pbrt-v4's fit at beta_n 0.4: (ln 0.2 / 5.74660)^2.
    EXPECT_NEAR(m.fibreAbsorption.x, std::pow(std::log(0.2) / 5.74660, 2.0), 1e-5);
  }
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages.front();

  // The first form given wins, as in pbrt-v4; the others are ignored with a warning.
  m = loadHair("\"rgb sigma_a\" [1 1 1] \"rgb reflectance\" [0.5 0.5 0.5] \"float eumelanin\" 3", warnings);
  expectNear(m.fibreAbsorption, {1, 1, 1}, 1e-6f);
  EXPECT_TRUE(warned(warnings, "'reflectance' is ignored since 'sigma_a' is given"));
  EXPECT_TRUE(warned(warnings, "'eumelanin/pheomelanin' is ignored since 'sigma_a' is given"));
  EXPECT_FALSE(warned(warnings, "not supported"));
}

// A named material of type hair is the same model.
TEST(PbrtHair, NamedHairMaterial) {
  const Scene scene = pbrt::loadText(
      "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
      "MakeNamedMaterial \"blonde\" \"string type\" \"hair\" \"float eumelanin\" 0.3\n"
      "NamedMaterial \"blonde\"\nShape \"trianglemesh\" \"integer indices\" [0 1 2] "
      "\"point3 P\" [0 0 0 1 0 0 0 1 0]\n");
  const Material& m = scene.materials[scene.meshes[0].triangleMaterials[0]];
  EXPECT_EQ(m.type, MaterialType::Hair);
  expectNear(m.fibreAbsorption, Vec3{0.419f, 0.697f, 1.37f} * 0.3f, 1e-5f);
}

// The offset across the fibre is pbrt-v4's -1 + 2v of the file's v, whichever way candela stores v.
TEST(PbrtHair, OffsetAcrossTheFibreIsPbrts) {
  const Scene scene = pbrt::loadText(patchOf("\"hair\""));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  const Material& m = scene.materials[mesh.triangleMaterials[0]];
  const float pbrtV[] = {0, 0, 1, 1};  // the patch's "point2 uv"
  ASSERT_EQ(mesh.uvs.size(), std::size(pbrtV));
  for (size_t i = 0; i < mesh.uvs.size(); ++i)
    EXPECT_FLOAT_EQ(HairBsdf::fromMaterial(m, 1.0f, mesh.uvs[i]).h, -1.0f + 2.0f * pbrtV[i]) << i;
  EXPECT_FLOAT_EQ(HairBsdf::fromMaterial(m, 1.0f, {0.3f, 0.25f}).h, 0.5f) << "candela's v 0.25 is pbrt's 0.75";
}

TEST(PbrtHair, HostileParametersAreRefusedInOneLine) {
  const std::pair<std::string, std::string> cases[] = {
      {"\"rgb sigma_a\" [1 -1 1]", "'sigma_a' must be finite and not negative"},
      {"\"rgb reflectance\" [0.5 -0.5 0.5]", "'reflectance' must be finite and not negative"},
      {"\"float eumelanin\" -1", "'eumelanin' and 'pheomelanin' must be finite and not negative"},
      {"\"float beta_m\" 0", "'beta_m' must lie in (0, 1]"},
      {"\"float beta_m\" 1.5", "'beta_m' must lie in (0, 1]"},
      {"\"float beta_n\" -0.2", "'beta_n' must lie in (0, 1]"},
      {"\"float eta\" 0", "'eta' must be finite and positive"},
      {"\"float eta\" -1.5", "'eta' must be finite and positive"},
      {"\"float eumelanin\" 3e38 \"float pheomelanin\" 3e38", "its melanin concentrations overflow"},
  };
  for (const auto& [parameters, message] : cases) {
    const std::string error = loadError(patchOf("\"hair\" " + parameters));
    EXPECT_NE(error.find("test.pbrt:6: hair: " + message), std::string::npos) << parameters << ": " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
  const std::string error = loadError(patchOf("\"hair\" \"rgb sigma_a\" [nan 1 1]"));
  EXPECT_NE(error.find("test.pbrt:6: 'nan' is not a number"), std::string::npos) << error;
}

// A patch of hair that absorbs nothing, in front of a uniform white light, after the repairs every loaded scene
// goes through: the fibre scatters all the light it meets (the white furnace, kernel tests in hair_bsdf_test), to
// either side of the patch, so the image is as bright as the light where the patch covers it too.
TEST(PbrtHair, WhiteHairPatchRendersNearOne) {
  LoadWarnings warnings;
  Scene scene = pbrt::loadText(patchOf("\"hair\" \"rgb sigma_a\" [0 0 0]"), &warnings);
  repairScene(scene, "test.pbrt", warnings);
  const PixelStatistics stats = renderOnCpu(scene, 16, 16, 8, 8);
  EXPECT_EQ(stats.invalidSamples, 0u);
  const ImageMean mean = imageMean(stats);
  EXPECT_NEAR(mean.mean, 1.0, 0.03) << mean.mean << " +- " << mean.standardError;
}

// Dark hair takes light away: the same patch with pbrt's brown default is darker than the light behind it.
TEST(PbrtHair, BrownHairPatchIsDarker) {
  LoadWarnings warnings;
  Scene scene = pbrt::loadText(patchOf("\"hair\""), &warnings);
  repairScene(scene, "test.pbrt", warnings);
  const PixelStatistics stats = renderOnCpu(scene, 16, 8, 8, 8);
  EXPECT_EQ(stats.invalidSamples, 0u);
  EXPECT_LT(imageMean(stats).mean, 0.8);
}

}  // namespace
}  // namespace candela::test
