// Grid media rendered whole on the CPU backend, and read from pbrt-v4 scenes (uniformgrid, rgbgrid, cloud),
// against answers known another way: the homogeneous medium they must equal, the furnace, a slab's transmittance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "io/load_diagnostics.h"
#include "kernel/media/medium_grid.h"
#include "media/media_grids.h"
#include "media/media_render.h"
#include "media/media_scenes.h"
#include "scene/cache/scene_serialization.h"
#include "scene/loaders/pbrt/pbrt_spectra.h"
#include "support/pbrt_text.h"

namespace candela::test {
namespace {

constexpr uint32_t kBatches = kMediaBatches;
constexpr double kAlpha = 0.01;

PixelStatistics render(const Scene& scene, uint32_t size) { return renderMediaScene(scene, size, 5); }

// A slab of medium m as makeMediumSlab's, the medium a uniformgrid of density 1 whose box is twice the slab's:
// 2 samples per axis put the samples' centres on the slab's faces or beyond, so the lookup is 1 all through it.
Scene constantGridSlab(const Medium& m, float depth) {
  Scene scene = makeMediumSlab(m, depth);
  scene.media.clear();
  addDensityGrid(scene, m.sigmaA, m.sigmaS, 2, 2, 2, std::vector<float>(8, 1.0f), {-100, -100, -depth},
                 {100, 100, 2.0f * depth});
  return scene;
}

// A uniform grid of constant density renders as the homogeneous medium it equals: the same image mean within
// 4 standard errors of the difference, for a medium that scatters and absorbs each channel differently.
TEST(GridMediaRender, ConstantGridRendersAsTheHomogeneousMedium) {
  Medium m;
  m.sigmaA = {0.2f, 0.5f, 0.1f};
  m.sigmaS = {0.8f, 0.4f, 1.6f};
  m.g = 0.3f;
  const PixelStatistics homogeneous = render(makeMediumSlab(m, 1.0f), 32);
  Scene gridScene = constantGridSlab(m, 1.0f);
  gridScene.media[0].g = m.g;
  const PixelStatistics grid = render(gridScene, 32);
  EXPECT_EQ(grid.invalidSamples, 0u);
  const ImageMean a = imageMean(homogeneous), b = imageMean(grid);
  const double error = std::sqrt(a.standardError * a.standardError + b.standardError * b.standardError);
  EXPECT_LT(std::fabs(a.mean - b.mean), 4.0 * error) << a.mean << " vs " << b.mean << " +- " << error;
  // The test resolves a slab 20% thicker.
  const ImageMean thicker = imageMean(render(makeMediumSlab(m, 1.2f), 32));
  const double thickerError =
      std::sqrt(thicker.standardError * thicker.standardError + b.standardError * b.standardError);
  EXPECT_GT(std::fabs(thicker.mean - b.mean), 4.0 * thickerError);
}

// A furnace (media_scenes.h) filled with a grid of densities from 0.2 to 3 and albedo 1: the radiance is 1
// everywhere, whatever the density. Grey: every pixel; channels scattering differently: the image mean.
TEST(GridMediaRender, FurnaceOfAVaryingGridIsOneEverywhere) {
  const uint32_t n = 6;
  std::vector<float> density(n * n * n);
  for (uint32_t i = 0; i < density.size(); ++i) density[i] = 0.2f + 2.8f * bitsToUnitFloat(pcg4d({i, 3, 4, 5}).x);
  for (Vec3 sigmaS : {Vec3{2, 2, 2}, Vec3{1, 2, 4}}) {
    Scene scene = makeMediumFurnace(Medium{});
    scene.media.clear();
    addDensityGrid(scene, {0, 0, 0}, sigmaS, n, n, n, density, {-1.2f, -1.2f, -1.2f}, {1.2f, 1.2f, 1.2f});
    const PixelStatistics stats = render(scene, 8);
    EXPECT_EQ(stats.invalidSamples, 0u);
    const ImageMean mean = imageMean(stats);
    EXPECT_LT(std::fabs(mean.mean - 1.0), 4.0 * mean.standardError) << mean.mean << " +- " << mean.standardError;
    if (sigmaS.x == sigmaS.z) {
      std::string worst;
      EXPECT_EQ(countRejectedPixels(stats, {1, 1, 1}, kBatches, kAlpha, worst), 0u) << worst;
    }
  }
}

using pbrt::loadError;
using pbrt::loadText;

// A box [-50, 50] x [-50, 50] x [0, depth] as a pbrt trianglemesh bounding medium `name` as an interface.
std::string pbrtInterfaceBox(const std::string& name, float depth) {
  return "AttributeBegin\nMaterial \"interface\"\nMediumInterface \"" + name + "\" \"\"\n" + pbrtBox(depth) +
         "AttributeEnd\n";
}

std::string uniformGrid(const std::string& extra) {
  return "MakeNamedMedium \"smoke\" \"string type\" \"uniformgrid\" \"integer nx\" 2 \"integer ny\" 2 "
         "\"integer nz\" 2 \"float density\" [1 1 1 1 1 1 1 1] \"point3 p0\" [-100 -100 -0.5] "
         "\"point3 p1\" [100 100 1] \"rgb sigma_a\" [0.5 1 2] \"rgb sigma_s\" [0 0 0] \"float scale\" 2 " +
         extra + "\n";
}

// A uniformgrid slab of constant density half a unit deep (its samples' centres beyond the slab's faces), purely
// absorbing with sigma_a x scale = 1 2 4: every pixel is exp(-sigma_a x 0.5), and a slab 40% thicker is rejected
// (delta tracking's estimate in a purely absorbing medium is 0 or 1, noisier than the homogeneous medium's exact
// one).
TEST(PbrtGridMedia, UniformGridSlabTransmitsItsAbsorption) {
  const Scene scene = loadText(std::string(kOrthographicView) + uniformGrid("") + pbrtInterfaceBox("smoke", 0.5f));
  ASSERT_EQ(scene.media.size(), 1u);
  ASSERT_EQ(scene.mediumGrids.size(), 1u);
  EXPECT_EQ(scene.media[0].grid, 0u);
  EXPECT_EQ(scene.mediumGrids[0].kind, MediumGridKind::Density);
  EXPECT_EQ(scene.mediumGrids[0].nx, 2u);
  const PixelStatistics stats = render(scene, 16);
  auto transmittance = [](float d) { return Vec3{std::exp(-1.0f * d), std::exp(-2.0f * d), std::exp(-4.0f * d)}; };
  std::string worst;
  EXPECT_EQ(countRejectedPixels(stats, transmittance(0.5f), kBatches, kAlpha, worst), 0u) << worst;
  EXPECT_GT(countRejectedPixels(stats, transmittance(0.7f), kBatches, kAlpha, worst), 0u);
  EXPECT_EQ(stats.invalidSamples, 0u);
}

// The transform in effect at MakeNamedMedium places the grid: its inverse takes world points into the medium.
TEST(PbrtGridMedia, TheMediumTransformPlacesTheGrid) {
  const Scene scene = loadText(std::string(kOrthographicView) + "AttributeBegin\nTranslate 0 2 3\nScale 2 2 2\n" +
                               uniformGrid("") + "AttributeEnd\n" + pbrtInterfaceBox("smoke", 0.5f));
  const Affine3x4& m = scene.mediumGrids[0].mediumFromWorld;
  const Vec3 p = m.point({0, 2, 3});
  EXPECT_NEAR(p.x, 0.0f, 1e-6f);
  EXPECT_NEAR(p.y, 0.0f, 1e-6f);
  EXPECT_NEAR(p.z, 0.0f, 1e-6f);
  EXPECT_NEAR(m.point({0, 4, 3}).y, 1.0f, 1e-6f);
}

// A uniformgrid with a temperature grid emits as pbrt-v4's GridMedium: in the dark, a slab of constant density
// and temperature that only absorbs is Lescale x the blackbody of (t - offset) x scale x (1 - exp(-sigma_a d)) in
// every pixel and channel, the same test rejecting the scale left out.
TEST(PbrtGridMedia, TemperatureGridsEmitTheirBlackbody) {
  std::string dark = kOrthographicView;
  const std::string light = "LightSource \"infinite\" \"rgb L\" [1 1 1]\n";
  dark.replace(dark.find(light), light.size(), "");
  LoadWarnings warnings;
  const Scene scene = loadText(dark +
                                   uniformGrid("\"float temperature\" [8 8 8 8 8 8 8 8] \"float temperaturescale\" 400 "
                                               "\"float temperatureoffset\" 1 \"float Lescale\" [3 3 3 3 3 3 3 3]") +
                                   pbrtInterfaceBox("smoke", 0.5f),
                               &warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  ASSERT_EQ(scene.mediumGrids.size(), 1u);
  EXPECT_NE(scene.mediumGrids[0].temperature, kNoGridValues);
  const PixelStatistics stats = render(scene, 16);
  EXPECT_EQ(stats.invalidSamples, 0u);
  auto expected = [](double kelvin) {
    const Vec3 le = peakNormalisedBlackbodyRgb(kelvin) * 3.0f;
    return Vec3{le.x * (1.0f - std::exp(-1.0f * 0.5f)), le.y * (1.0f - std::exp(-2.0f * 0.5f)),
                le.z * (1.0f - std::exp(-4.0f * 0.5f))};
  };
  std::string worst;
  EXPECT_EQ(countRejectedPixels(stats, expected((8 - 1) * 400), kBatches, kAlpha, worst), 0u) << worst;
  EXPECT_GT(countRejectedPixels(stats, expected(8 * 400), kBatches, kAlpha, worst), 0u);

  // Colder than the cutoff: no emission, the density grid alone. `Le` beside a temperature grid, or a grid of
  // another size, is refused as pbrt-v4 refuses it.
  const Scene cold =
      loadText(dark + uniformGrid("\"float temperature\" [8 8 8 8 8 8 8 8]") + pbrtInterfaceBox("smoke", 0.5f));
  EXPECT_EQ(cold.mediumGrids[0].temperature, kNoGridValues);
  EXPECT_EQ(cold.media[0].emission.x, 0.0f);
  for (const auto& [extra, expectedError] :
       {std::pair<std::string, std::string>{"\"float temperature\" [8 8 8 8 8 8 8 8] \"rgb Le\" [1 1 1]",
                                            "'Le' and 'temperature' are both given"},
        {"\"float temperature\" [8 8 8]", "'temperature' has 3 values where nx*ny*nz = 8"},
        {"\"float temperature\" [800 8 8 8 8 8 8 8] \"float Lescale\" [1 1 1 1 1 1 1 -1]",
         "'Lescale' has a negative"}}) {
    std::string message = "(no error)";
    try {
      loadText(dark + uniformGrid(extra) + pbrtInterfaceBox("smoke", 0.5f));
    } catch (const LoadError& e) {
      message = e.what();
    }
    EXPECT_NE(message.find(expectedError), std::string::npos) << message;
  }
}

// As pbrt-v4, the temperature is interpolated first and its blackbody taken after: half-way between samples at
// 1000 K and 3000 K the medium glows as a blackbody of 2000 K (not as the mean of the two blackbodies, several
// times brighter), times the Lescale interpolated there; the table the kernel reads it from holds pbrt's blackbody
// within 1e-4 from the cutoff to the hottest temperature.
TEST(PbrtGridMedia, TemperatureIsInterpolatedBeforeItsBlackbody) {
  const Scene scene = loadText(std::string(kOrthographicView) +
                               "MakeNamedMedium \"fire\" \"string type\" \"uniformgrid\" \"integer nx\" 2 "
                               "\"float density\" [1 1] \"float temperature\" [1000 3000] \"float Lescale\" [1 3]\n" +
                               pbrtInterfaceBox("fire", 0.5f));
  ASSERT_EQ(scene.mediumGrids.size(), 1u);
  const MediumGrid& grid = scene.mediumGrids[0];
  ASSERT_NE(grid.temperature, kNoGridValues);
  const float* values = scene.mediumGridValues.data();
  for (float x : {0.25f, 0.5f, 0.6f, 0.75f}) {
    // Sample centres at x = 0.25 and 0.75 of the unit box.
    const float f = (x - 0.25f) / 0.5f;
    const Vec3 expected = peakNormalisedBlackbodyRgb(1000.0 + 2000.0 * f) * (1.0f + 2.0f * f);
    // The medium's x is the world's -x (pbrt's space is left-handed, candela's right-handed).
    const Vec3 le = gridMediumAt(scene.media[0], grid, values, {-x, 0.5f, 0.5f}).emission;
    EXPECT_NEAR(le.x, expected.x, 1e-4f * expected.x + 1e-7f) << x;
    EXPECT_NEAR(le.y, expected.y, 1e-4f * expected.y + 1e-7f) << x;
    EXPECT_NEAR(le.z, expected.z, 1e-4f * expected.z + 1e-9f) << x;
  }
  double worst = 0.0;
  for (double kelvin = 101.0; kelvin < 1.2e5; kelvin *= 1.0123) {
    const Vec3 exact = peakNormalisedBlackbodyRgb(std::min(kelvin, double(kBlackbodyHottestKelvin)));
    const Vec3 table = blackbodyEmission(values + grid.blackbody, float(kelvin));
    for (auto channel : {&Vec3::x, &Vec3::y, &Vec3::z})
      worst =
          std::max(worst, std::fabs(double(table.*channel - exact.*channel)) / std::max(double(exact.*channel), 1e-3));
  }
  EXPECT_LT(worst, 1e-4);
}

// rgbgrid and cloud media load with their parameters and render without an invalid sample; each attenuates the
// environment behind it somewhere.
TEST(PbrtGridMedia, RgbGridAndCloudLoadAndRender) {
  std::string rgb =
      "MakeNamedMedium \"tint\" \"string type\" \"rgbgrid\" \"integer nx\" 2 \"point3 p0\" [-2 -2 0] "
      "\"point3 p1\" [2 2 0.5] \"rgb sigma_a\" [1 0 0  0 2 0] \"rgb sigma_s\" [0.5 0.5 0.5  1 1 1] "
      "\"rgb Le\" [0 0 0  0.5 0.5 0.5] \"float Lescale\" 2 \"float scale\" 3\n";
  std::string cloud =
      "MakeNamedMedium \"tint\" \"string type\" \"cloud\" \"point3 p0\" [-1 -1 0] \"point3 p1\" "
      "[1 1 0.5] \"rgb sigma_a\" [0.5 0.5 0.5] \"rgb sigma_s\" [4 4 4] \"float density\" 2 "
      "\"float wispiness\" 0.5 \"float frequency\" 3 \"float g\" 0.5\n";
  for (const std::string& medium : {rgb, cloud}) {
    SCOPED_TRACE(medium);
    LoadWarnings warnings;
    const Scene scene = loadText(std::string(kOrthographicView) + medium + pbrtInterfaceBox("tint", 0.5f), &warnings);
    ASSERT_EQ(scene.mediumGrids.size(), 1u);
    const MediumGrid& grid = scene.mediumGrids[0];
    if (grid.kind == MediumGridKind::Rgb) {
      EXPECT_EQ(grid.nx, 2u);
      EXPECT_NE(grid.sigmaA, kNoGridValues);
      EXPECT_NE(grid.emission, kNoGridValues);
      EXPECT_FLOAT_EQ(scene.media[0].sigmaA.x, 3.0f);
      EXPECT_FLOAT_EQ(scene.media[0].emission.x, 2.0f);
    } else {
      EXPECT_EQ(grid.kind, MediumGridKind::Cloud);
      EXPECT_FLOAT_EQ(grid.frequency, 3.0f);
      EXPECT_FLOAT_EQ(scene.media[0].g, 0.5f);
    }
    for (const std::string& w : warnings.messages) EXPECT_EQ(w.find("medium"), std::string::npos) << w;
    const PixelStatistics stats = render(scene, 8);
    EXPECT_EQ(stats.invalidSamples, 0u);
    const ImageMean mean = imageMean(stats);
    EXPECT_LT(mean.mean, 0.95);
    EXPECT_GT(mean.mean, 0.0);
  }
}

// Grids that cannot be what they say are refused in one line naming the directive.
TEST(PbrtGridMedia, HostileGridsAreRefused) {
  auto grid = [](const std::string& sizes, const std::string& density) {
    return std::string(kOrthographicView) + "MakeNamedMedium \"g\" \"string type\" \"uniformgrid\" " + sizes +
           " \"float density\" [" + density + "]\n" + pbrtInterfaceBox("g", 0.5f);
  };
  const std::string eight = "1 1 1 1 1 1 1 1";
  const std::string two = "\"integer nx\" 2 \"integer ny\" 2 \"integer nz\" 2";
  EXPECT_NE(loadError(grid(two, "1 1 1 1 1 1 1")).find("7 values where nx*ny*nz = 8"), std::string::npos);
  EXPECT_NE(loadError(grid("\"integer nx\" -2", eight)).find("between 1 and 2^20"), std::string::npos);
  EXPECT_NE(loadError(grid("\"integer nx\" 1073741824 \"integer ny\" 1073741824", eight)).find("between 1 and 2^20"),
            std::string::npos);
  EXPECT_NE(loadError(grid(two, "1 1 1 1 1 1 1 -1")).find("negative or non-finite"), std::string::npos);
  // The parser refuses what no float holds before the grid sees it.
  EXPECT_NE(loadError(grid(two, "1 1 1 1 1 1 1 1e39")).find("beyond the range of a float"), std::string::npos);
  EXPECT_NE(loadError(grid(two, "1 1 1 nan 1 1 1 1")).find("'nan' is not a number"), std::string::npos);
  EXPECT_NE(loadError(grid(two + " \"point3 p0\" [0 0 0] \"point3 p1\" [1 0 1]", eight)).find("not empty"),
            std::string::npos);
  EXPECT_NE(loadError(grid(two, "")).find("needs \"density\""), std::string::npos);
  // So dense that tracking a ray through it would take some 1e30 steps.
  EXPECT_NE(loadError(grid(two, "1 1 1 1 1 1 1 1e30")).find("too dense to track"), std::string::npos);
  EXPECT_NE(loadError(std::string(kOrthographicView) + "MakeNamedMedium \"g\" \"string type\" \"rgbgrid\"\n")
                .find("needs 'sigma_a' or 'sigma_s'"),
            std::string::npos);
  EXPECT_EQ(loadError(grid(two, "1 1 1 1 1 1 1")), "test.pbrt:6: medium: 'density' has 7 values where nx*ny*nz = 8");
}

// A scene whose grid names samples it does not have (a damaged scene cache) fails validation.
TEST(PbrtGridMedia, AGridPastItsSamplesFailsValidation) {
  Scene scene = loadText(std::string(kOrthographicView) + uniformGrid("") + pbrtInterfaceBox("smoke", 0.5f));
  EXPECT_NO_THROW(validateScene(scene));
  scene.mediumGrids[0].nx = 1'000'000;
  EXPECT_THROW(validateScene(scene), std::runtime_error);
}

// The scene cache's layout carries grid media whole: grids, samples and majorant grids read back as written.
TEST(PbrtGridMedia, TheSceneCacheKeepsGrids) {
  const Scene scene = loadText(std::string(kOrthographicView) + uniformGrid("\"float Lescale\" [1 2 3 4 5 6 7 8]") +
                               pbrtInterfaceBox("smoke", 0.5f));
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  {
    BinaryWriter out(file);
    writeScene(out, scene);
    ASSERT_TRUE(out.ok());
  }
  const long size = std::ftell(file);
  std::rewind(file);
  Scene read;
  {
    BinaryReader in(file, uint64_t(size));
    ASSERT_TRUE(readScene(in, read));
  }
  std::fclose(file);
  ASSERT_EQ(read.mediumGrids.size(), 1u);
  EXPECT_EQ(std::memcmp(&read.mediumGrids[0], &scene.mediumGrids[0], sizeof(MediumGrid)), 0);
  EXPECT_EQ(read.mediumGridValues, scene.mediumGridValues);
  EXPECT_EQ(read.media[0].grid, 0u);
  EXPECT_NO_THROW(validateScene(read));
}

}  // namespace
}  // namespace candela::test
