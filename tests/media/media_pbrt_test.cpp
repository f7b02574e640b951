// pbrt-v4's media directives (MakeNamedMedium, MediumInterface, the camera's medium, the interface material) as
// the loader reads them, and a pbrt scene with a medium rendered against its closed-form answer.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/load_diagnostics.h"
#include "media/media_scenes.h"
#include "scene/scene_repair.h"
#include "support/pbrt_text.h"
#include "support/render_statistics.h"

namespace candela::test {
namespace {

using pbrt::loadError;
using pbrt::loadText;

// A slab of absorbing fog (scale 2, so sigma_a = 1 2 4) half a unit deep, bounded by an interface box.
std::string absorbingSlab() {
  return std::string(kOrthographicView) +
         "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.5 1 2] \"rgb sigma_s\" [0 0 0] "
         "\"float scale\" 2 \"float g\" 0.25 \"rgb Le\" [0 0 0]\n"
         "AttributeBegin\nMaterial \"interface\"\nMediumInterface \"fog\" \"\"\n" +
         pbrtBox(0.5f) + "AttributeEnd\n";
}

TEST(PbrtMedia, HomogeneousMediaAndInterfacesAreRead) {
  LoadWarnings warnings;
  const Scene scene = loadText(absorbingSlab(), &warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  ASSERT_EQ(scene.media.size(), 1u);
  EXPECT_FLOAT_EQ(scene.media[0].sigmaA.z, 4.0f);
  EXPECT_FLOAT_EQ(scene.media[0].sigmaS.x, 0.0f);
  EXPECT_FLOAT_EQ(scene.media[0].g, 0.25f);
  ASSERT_EQ(scene.instances.size(), 1u);
  EXPECT_EQ(scene.instances[0].media.inside, 0u);
  EXPECT_EQ(scene.instances[0].media.outside, kNoMedium);
  EXPECT_EQ(scene.cameraMedium, kNoMedium);
  EXPECT_EQ(scene.materials[scene.meshes[0].triangleMaterials[0]].interfaceOnly, 1u);
}

// The camera is in the outside medium current at the Camera directive; a name may be used before it is defined
// (pbrt resolves names at the end), and a name never defined is an error at its first use.
TEST(PbrtMedia, CameraMediumAndForwardNames) {
  LoadWarnings warnings;
  const Scene scene = loadText(
      "MediumInterface \"\" \"air\"\nCamera \"perspective\"\nWorldBegin\n"
      "MakeNamedMedium \"smoke\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.5 0.5 0.5]\n"
      "MakeNamedMedium \"air\" \"string type\" \"homogeneous\" \"rgb sigma_s\" [0.1 0.1 0.1]\n"
      "MediumInterface \"smoke\" \"air\"\nShape \"sphere\"\n",
      &warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  ASSERT_EQ(scene.media.size(), 2u);
  EXPECT_EQ(scene.cameraMedium, 0u);
  EXPECT_FLOAT_EQ(scene.media[0].sigmaA.x, 1.0f);  // pbrt's default
  EXPECT_FLOAT_EQ(scene.media[1].sigmaA.x, 0.5f);
  EXPECT_EQ(scene.instances[0].media.inside, 1u);
  EXPECT_EQ(scene.instances[0].media.outside, 0u);
  // A nanovdb medium names a file, which a scene read from memory may not.
  EXPECT_NE(loadError("WorldBegin\nMakeNamedMedium \"smoke\" \"string type\" \"nanovdb\" \"string filename\" "
                      "\"smoke.nvdb\"\n")
                .find("test.pbrt:2: 'smoke.nvdb': a scene read from memory cannot refer to files"),
            std::string::npos);

  EXPECT_NE(loadError("WorldBegin\nMediumInterface \"fog\"\nShape \"sphere\"\n")
                .find("test.pbrt:2: medium 'fog' is not defined"),
            std::string::npos);
  EXPECT_NE(loadError("WorldBegin\nMakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"float g\" 1\n")
                .find("test.pbrt:2: medium: 'g' must lie between -1 and 1"),
            std::string::npos);
  EXPECT_NE(loadError("WorldBegin\nMakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [1 -1 1]\n")
                .find("'sigma_a' must be finite and not negative"),
            std::string::npos);
  EXPECT_NE(
      loadError("WorldBegin\nMakeNamedMedium \"fog\" \"string type\" \"jelly\"\n").find("unknown medium type 'jelly'"),
      std::string::npos);
}

// The slab above renders as its closed form: exp(-sigma_a d) per channel in every pixel, after the repairs every
// loaded scene goes through (which renumber the instances, and must keep their media).
TEST(PbrtMedia, SlabSceneRendersItsTransmittance) {
  Scene scene = loadText(absorbingSlab());
  LoadWarnings warnings;
  repairScene(scene, "test.pbrt", warnings);
  constexpr uint32_t kBatches = 32;
  const PixelStatistics stats = renderOnCpu(scene, 16, kBatches, 8);
  const Vec3 expected{std::exp(-0.5f), std::exp(-1.0f), std::exp(-2.0f)};
  std::string worst;
  EXPECT_EQ(countRejectedPixels(stats, expected, kBatches, 0.01, worst), 0u) << worst;
  EXPECT_EQ(stats.invalidSamples, 0u);
}

}  // namespace
}  // namespace candela::test
