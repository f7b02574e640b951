// pbrt-v4's `nanovdb` medium: .nvdb files written here (media/nanovdb_files.h) read into the dense grid of
// uniformgrid media, rendered against the homogeneous medium they equal, downsampled keeping their mean, emitting
// from their temperature grids as pbrt-v4's blackbody, and hostile files refused in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "app/scene_loading.h"
#include "io/load_diagnostics.h"
#include "media/media_render.h"
#include "media/media_scenes.h"
#include "media/nanovdb_files.h"
#include "scene/loaders/nanovdb/nanovdb_dense_grid.h"
#include "scene/loaders/nanovdb/nanovdb_file.h"
#include "scene/loaders/pbrt/pbrt_loader.h"
#include "scene/loaders/pbrt/pbrt_spectra.h"
#include "scene/loaders/pbrt/pbrt_temperature_emission.h"
#include "scene/scene_test_files.h"

namespace candela::test {
namespace {

// The slab of pbrtBox(depth) bounding medium "smoke", seen by kOrthographicView.
std::string slabScene(const std::string& medium, float depth) {
  return std::string(kOrthographicView) + medium + "\nAttributeBegin\nMaterial \"interface\"\n" +
         "MediumInterface \"smoke\" \"\"\n" + pbrtBox(depth) + "AttributeEnd\n";
}

std::string nanoVdbMedium(const std::string& file, const std::string& extra = "") {
  return "MakeNamedMedium \"smoke\" \"string type\" \"nanovdb\" \"string filename\" \"" + file + "\" " + extra;
}

// `scene` loaded from a folder that also holds `nvdb` as smoke.nvdb.
Scene loadWithFile(const TempFolder& folder, const std::string& scene, const std::string& nvdb,
                   LoadWarnings* warningsOut = nullptr) {
  folder.write("smoke.nvdb", nvdb);
  LoadWarnings warnings;
  Scene loaded = loadPbrt(folder.write("main.pbrt", scene), warnings);
  if (warningsOut) *warningsOut = warnings;
  return loaded;
}

// The message of the LoadError that loading a slab whose medium is `nvdb` throws, or "(no error)".
std::string loadError(const TempFolder& folder, const std::string& nvdb, const std::string& file = "smoke.nvdb") {
  try {
    loadWithFile(folder, slabScene(nanoVdbMedium(file), 0.5f), nvdb);
  } catch (const LoadError& e) {
    return e.what();
  }
  return "(no error)";
}

// 5 x 3 x 4 voxels of distinct values from index (-3, 2, 7), across leaves, under a map that scales each axis
// differently and moves the grid.
TestNanoVdbGrid varyingGrid() {
  TestNanoVdbGrid g;
  g.origin = {-3, 2, 7};
  g.size = {5, 3, 4};
  for (uint32_t k = 0; k < 4; ++k)
    for (uint32_t j = 0; j < 3; ++j)
      for (uint32_t i = 0; i < 5; ++i) g.values.push_back(0.01f * float(1 + i + 10 * j + 100 * k));
  g.voxelSize = {0.5, 2, 1};
  g.translation = {1, -3, 0.25};
  return g;
}

// A grid of density 1 whose voxels' cells fill [-100, 100]^2 x [-0.5, 1]: its samples' centres lie beyond the
// faces of a slab from z = 0 to 0.5, so the density is 1 all through the slab. Its leaves are uniform, so it is
// written as lower-node tiles.
TestNanoVdbGrid constantSlabGrid() {
  TestNanoVdbGrid g;
  g.size = {16, 8, 8};
  g.values.assign(16 * 8 * 8, 1.0f);
  g.voxelSize = {200.0 / 16, 200.0 / 8, 1.5 / 8};
  g.translation = {-100 + 0.5 * g.voxelSize[0], -100 + 0.5 * g.voxelSize[1], -0.5 + 0.5 * g.voxelSize[2]};
  return g;
}

// A nanovdb medium of constant density renders as the homogeneous medium of its coefficients: image means within
// 4 standard errors of their difference, a medium that scatters and absorbs each channel differently.
TEST(NanoVdbMedia, ConstantDensityRendersAsTheHomogeneousMedium) {
  TempFolder folder;
  const std::string coefficients =
      "\"rgb sigma_a\" [0.1 0.25 0.05] \"rgb sigma_s\" [0.4 0.2 0.8] \"float scale\" 2 \"float g\" 0.3";
  LoadWarnings warnings;
  const Scene grid = loadWithFile(folder, slabScene(nanoVdbMedium("smoke.nvdb", coefficients), 1.0f),
                                  nanoVdbFile({constantSlabGrid()}), &warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  ASSERT_EQ(grid.mediumGrids.size(), 1u);
  EXPECT_EQ(grid.mediumGrids[0].nx, 16u);
  EXPECT_FLOAT_EQ(grid.media[0].sigmaS.z, 1.6f);
  const Scene homogeneous =
      loadWithFile(folder, slabScene("MakeNamedMedium \"smoke\" \"string type\" \"homogeneous\" " + coefficients, 1.0f),
                   "");
  const PixelStatistics a = renderMediaScene(homogeneous, 16, 5), b = renderMediaScene(grid, 16, 5);
  EXPECT_EQ(b.invalidSamples, 0u);
  const ImageMean ma = imageMean(a), mb = imageMean(b);
  const double error = std::sqrt(ma.standardError * ma.standardError + mb.standardError * mb.standardError);
  EXPECT_LT(std::fabs(ma.mean - mb.mean), 4.0 * error) << ma.mean << " vs " << mb.mean << " +- " << error;
  // The test tells a density 20% higher apart.
  TestNanoVdbGrid denser = constantSlabGrid();
  denser.values.assign(denser.values.size(), 1.2f);
  const ImageMean mc = imageMean(renderMediaScene(
      loadWithFile(folder, slabScene(nanoVdbMedium("smoke.nvdb", coefficients), 1.0f), nanoVdbFile({denser})), 16, 5));
  const double denserError = std::sqrt(ma.standardError * ma.standardError + mc.standardError * mc.standardError);
  EXPECT_GT(std::fabs(ma.mean - mc.mean), 4.0 * denserError);
}

// Without downsampling, the dense grid's samples are the voxels' values, its box the voxels' cells in index space,
// and NanoVDB's map then the MakeNamedMedium transform take index space to the world; ZIP-compressed grids read
// the same.
TEST(NanoVdbMedia, SamplesAreTheVoxelValuesAtTheirCentres) {
  TempFolder folder;
  const TestNanoVdbGrid g = varyingGrid();
  for (bool zip : {false, true}) {
    const Scene scene = loadWithFile(
        folder, slabScene("AttributeBegin\nTranslate 10 0 0\n" + nanoVdbMedium("smoke.nvdb") + "\nAttributeEnd", 0.5f),
        nanoVdbFile({g}, zip));
    ASSERT_EQ(scene.mediumGrids.size(), 1u);
    const MediumGrid& grid = scene.mediumGrids[0];
    EXPECT_EQ(grid.kind, MediumGridKind::Density);
    ASSERT_EQ(grid.nx, 5u);
    ASSERT_EQ(grid.ny, 3u);
    ASSERT_EQ(grid.nz, 4u);
    for (size_t i = 0; i < g.values.size(); ++i)
      ASSERT_EQ(scene.mediumGridValues[grid.density + i], g.values[i]) << "sample " << i << (zip ? " (ZIP)" : "");
    EXPECT_EQ(grid.p0.x, -3.5f);
    EXPECT_EQ(grid.p0.y, 1.5f);
    EXPECT_EQ(grid.p1.z, 10.5f);
    // Voxel (-1, 3, 9)'s centre in the world: NanoVDB's map, then Translate 10 0 0, then the loader's mirroring
    // of pbrt's x axis.
    const Vec3 world{-float(0.5 * -1 + 1 + 10), float(2.0 * 3 - 3), float(9 + 0.25)};
    const Vec3 index = grid.mediumFromWorld.point(world);
    EXPECT_NEAR(index.x, -1.0f, 1e-5f);
    EXPECT_NEAR(index.y, 3.0f, 1e-5f);
    EXPECT_NEAR(index.z, 9.0f, 1e-5f);
  }
}

// Area-averaging down to fewer samples keeps the grid's mean (the cells are equal, each the mean of what it
// covers), and a grid over the bound a side is cut down to it with one warning.
TEST(NanoVdbMedia, DownsamplingKeepsTheMean) {
  TestNanoVdbGrid g;
  g.origin = {5, -9, 0};
  g.size = {10, 7, 5};
  double sum = 0.0;
  for (uint32_t i = 0; i < 10 * 7 * 5; ++i) {
    g.values.push_back(float((i * 37) % 101) / 7.0f);
    sum += g.values.back();
  }
  TempFolder folder;
  const std::string path = folder.write("grid.nvdb", nanoVdbFile({g}));
  const NanoVdbFile file(path);
  std::vector<float> values(3, 0.0f);  // samples already there stay
  const NanoVdbDenseGrid dense = appendNanoVdbDenseGrid(file.gridBytes(file.grids()[0]), path, "density", 4, values);
  EXPECT_TRUE(dense.downsampled);
  ASSERT_EQ(dense.nx, 4u);
  ASSERT_EQ(dense.ny, 4u);
  ASSERT_EQ(dense.nz, 4u);
  ASSERT_EQ(dense.offset, 3u);
  ASSERT_EQ(values.size(), 3u + 64u);
  double denseSum = 0.0;
  for (size_t i = 3; i < values.size(); ++i) denseSum += values[i];
  EXPECT_NEAR(denseSum / 64.0, sum / 350.0, 1e-5 * sum / 350.0);
  // One cell of the x axis holding whole voxels: 10 voxels into 4 cells, cell 0 is voxels 0, 1 and half of 2.
  double cell = 0.0;
  for (uint32_t k = 0; k < 5; ++k)
    for (uint32_t j = 0; j < 7; ++j)
      for (uint32_t i = 0; i < 3; ++i) {
        const double w = (i == 2 ? 0.5 : 1.0) *
                         (j < 1    ? 1.0
                          : j == 1 ? 0.75
                                   : 0.0) *
                         (k == 0   ? 1.0
                          : k == 1 ? 0.25
                                   : 0.0);
        cell += w * g.values[(k * 7 + j) * 10 + i];
      }
  EXPECT_NEAR(values[3], cell / (2.5 * 1.75 * 1.25), 1e-5);

  TestNanoVdbGrid wide;
  wide.size = {300, 2, 2};
  wide.values.assign(300 * 2 * 2, 0.5f);
  LoadWarnings warnings;
  const Scene scene =
      loadWithFile(folder, slabScene(nanoVdbMedium("smoke.nvdb"), 0.5f), nanoVdbFile({wide}), &warnings);
  EXPECT_EQ(scene.mediumGrids[0].nx, 256u);
  EXPECT_EQ(scene.mediumGrids[0].ny, 2u);
  EXPECT_FLOAT_EQ(scene.mediumGridValues[scene.mediumGrids[0].density + 100], 0.5f);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("300 x 2 x 2 voxels are area-averaged down to 256 x 2 x 2"), std::string::npos)
      << warnings.messages[0];
}

// The slab scene of slabScene in the dark: no light, so that what reaches the camera is the medium's emission.
std::string darkSlabScene(const std::string& medium, float depth) {
  std::string scene = slabScene(medium, depth);
  const std::string light = "LightSource \"infinite\" \"rgb L\" [1 1 1]\n";
  return scene.replace(scene.find(light), light.size(), "");
}

// constantSlabGrid's voxels, all at `temperature`, as the grid "temperature".
TestNanoVdbGrid constantTemperatureGrid(float temperature) {
  TestNanoVdbGrid g = constantSlabGrid();
  g.name = "temperature";
  g.values.assign(g.values.size(), temperature);
  return g;
}

// pbrt-v4's blackbody, 1 at its peak, against Planck's law integrated here against Wyman, Sloan and Shirley's fit
// of the CIE y curve (its luminance; its colour is a blackbody light's), and the table the
// loader reads it from within 1e-4 of it where it is not negligible; 0 at and below 100 K, finite and the blackbody
// of 1e5 K beyond that.
TEST(TemperatureEmission, IsPbrtsBlackbodyOnePeak) {
  // (Below about 1900 K the colour lies outside sRGB's gamut: its negative channels are clamped.)
  for (double kelvin : {2000.0, 3000.0, 5000.0, 6500.0, 10000.0, 30000.0}) {
    double y = 0.0, ySum = 0.0;
    const double peak = 2.8977721e6 / kelvin, c2 = 1.4387769e7;
    for (double lambda = 360.0; lambda <= 830.0; lambda += 1.0) {
      auto lobe = [&](double mu, double below, double above) {
        const double t = (lambda - mu) / (lambda < mu ? below : above);
        return std::exp(-0.5 * t * t);
      };
      const double match = 0.821 * lobe(568.8, 46.9, 40.5) + 0.286 * lobe(530.9, 16.3, 31.1);
      y += match * std::pow(peak / lambda, 5.0) * std::expm1(c2 / 2.8977721e6) / std::expm1(c2 / (lambda * kelvin));
      ySum += match;
    }
    const Vec3 rgb = peakNormalisedBlackbodyRgb(kelvin);
    EXPECT_NEAR(luminance(rgb), y / ySum, 2e-3 * y / ySum) << kelvin << " K";
    // The colour of a blackbody light (luminance 1) at the same temperature.
    const Vec3 light = blackbodyRgb(float(kelvin)) * luminance(rgb);
    EXPECT_NEAR(rgb.x, light.x, 2e-3f * light.x) << kelvin << " K";
    EXPECT_NEAR(rgb.z, light.z, 2e-3f * light.x) << kelvin << " K";
  }
  std::vector<float> table;
  for (uint32_t i = 0; i < kBlackbodyTableSize; ++i) {
    const Vec3 rgb = blackbodyTableEntry(i);
    table.insert(table.end(), {rgb.x, rgb.y, rgb.z});
  }
  EXPECT_GE(double(kBlackbodyCutoffKelvin) * std::exp2(double(kBlackbodyTableSize - 1) / kBlackbodyStepsPerOctave),
            double(kBlackbodyHottestKelvin));
  double worst = 0.0;
  for (double kelvin = 101.0; kelvin < 1.2e5; kelvin *= 1.0123) {
    const Vec3 exact = peakNormalisedBlackbodyRgb(std::min(kelvin, double(kBlackbodyHottestKelvin))),
               interpolated = blackbodyEmission(table.data(), float(kelvin));
    for (auto channel : {&Vec3::x, &Vec3::y, &Vec3::z}) {
      const double e = exact.*channel, t = interpolated.*channel;
      worst = std::max(worst, std::fabs(t - e) / std::max(e, 1e-3));
    }
  }
  EXPECT_LT(worst, 1e-4);
  for (float cold : {-5.0f, 0.0f, 50.0f, 100.0f, std::nanf("")}) {
    const Vec3 none = blackbodyEmission(table.data(), cold);
    EXPECT_EQ(none.x + none.y + none.z, 0.0f) << cold;
  }
  const Vec3 hottest = peakNormalisedBlackbodyRgb(kBlackbodyHottestKelvin);
  for (float hot : {2e5f, 1e30f, std::numeric_limits<float>::infinity()}) {
    const Vec3 capped = blackbodyEmission(table.data(), hot);
    EXPECT_TRUE(isFinite(capped));
    EXPECT_NEAR(capped.z, hottest.z, 1e-7f);
  }
  EXPECT_GT(hottest.z, hottest.x);
}

// A slab of constant density and temperature that only absorbs and emits, in the dark, is the emission-absorption
// solution in every pixel and channel: Lescale x the blackbody of (t - offset) x scale x (1 - exp(-sigma_a d)). The
// same test rejects the images of the offset, the scale or Lescale left out.
TEST(NanoVdbMedia, ConstantTemperatureEmitsItsBlackbody) {
  TempFolder folder;
  const Vec3 sigmaA{0.5f, 1.0f, 2.0f};
  const float depth = 0.5f;
  LoadWarnings warnings;
  const Scene scene =
      loadWithFile(folder,
                   darkSlabScene(nanoVdbMedium("smoke.nvdb",
                                               "\"rgb sigma_a\" [0.5 1 2] \"rgb sigma_s\" [0 0 0] \"float Lescale\" 2 "
                                               "\"float temperatureoffset\" 500 \"float temperaturescale\" 5"),
                                 depth),
                   nanoVdbFile({constantSlabGrid(), constantTemperatureGrid(1100.0f)}), &warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  ASSERT_EQ(scene.mediumGrids.size(), 1u);
  EXPECT_NE(scene.mediumGrids[0].temperature, kNoGridValues);
  EXPECT_TRUE(hasLightSource(scene));  // no warning that the image will be black
  const PixelStatistics stats = renderMediaScene(scene, 16, 9);
  EXPECT_EQ(stats.invalidSamples, 0u);
  auto expected = [&](float leScale, double kelvin) {
    const Vec3 le = peakNormalisedBlackbodyRgb(kelvin) * leScale;
    return Vec3{le.x * (1.0f - std::exp(-sigmaA.x * depth)), le.y * (1.0f - std::exp(-sigmaA.y * depth)),
                le.z * (1.0f - std::exp(-sigmaA.z * depth))};
  };
  std::string worst;
  EXPECT_EQ(countRejectedPixels(stats, expected(2.0f, (1100.0 - 500.0) * 5.0), kMediaBatches, 0.01, worst), 0u)
      << worst;
  EXPECT_GT(countRejectedPixels(stats, expected(2.0f, 1100.0 * 5.0), kMediaBatches, 0.01, worst), 0u);
  EXPECT_GT(countRejectedPixels(stats, expected(2.0f, 1100.0 - 500.0), kMediaBatches, 0.01, worst), 0u);
  EXPECT_GT(countRejectedPixels(stats, expected(1.0f, (1100.0 - 500.0) * 5.0), kMediaBatches, 0.01, worst), 0u);
}

// As pbrt-v4: at or below 100 K after offset and scale a medium emits nothing (and keeps its density grid alone),
// and `temperaturecutoff` is the offset where `temperatureoffset` is not given.
TEST(NanoVdbMedia, TemperaturesAtTheCutoffDoNotEmit) {
  TempFolder folder;
  const std::string file = nanoVdbFile({constantSlabGrid(), constantTemperatureGrid(1100.0f)});
  const struct {
    std::string parameters;
    bool emits;
  } cases[] = {
      {"\"float temperatureoffset\" 1000", false},
      {"\"float temperatureoffset\" 999", true},
      {"\"float temperaturecutoff\" 1000", false},
      {"\"float temperaturecutoff\" 1000 \"float temperatureoffset\" 0", true},
      {"\"float temperaturescale\" 0.09", false},
      {"\"float Lescale\" 0", false},
  };
  for (const auto& c : cases) {
    LoadWarnings warnings;
    const Scene scene =
        loadWithFile(folder, darkSlabScene(nanoVdbMedium("smoke.nvdb", c.parameters), 0.5f), file, &warnings);
    EXPECT_TRUE(warnings.messages.empty()) << c.parameters << ": " << warnings.messages[0];
    ASSERT_EQ(scene.mediumGrids.size(), 1u);
    EXPECT_EQ(scene.mediumGrids[0].temperature != kNoGridValues, c.emits) << c.parameters;
    EXPECT_EQ(hasLightSource(scene), c.emits) << c.parameters;
    if (c.emits) continue;
    EXPECT_EQ(scene.mediumGridValues.size(), 16u * 8 * 8 + 16 * 16 * 16) << "density and majorants alone";
    const ImageMean mean = imageMean(renderMediaScene(scene, 16, 3));
    EXPECT_EQ(mean.mean, 0.0) << c.parameters;
  }
}

// Emission is sigma_a x Le, as in pbrt-v4: a hot grid where the density is 0 stays dark. A file with a temperature
// grid but no density is refused, as pbrt-v4 refuses it.
TEST(NanoVdbMedia, TemperatureWithoutDensityDoesNotEmit) {
  TempFolder folder;
  TestNanoVdbGrid empty = constantSlabGrid();
  empty.values.assign(empty.values.size(), 0.0f);
  const Scene scene = loadWithFile(folder, darkSlabScene(nanoVdbMedium("smoke.nvdb"), 0.5f),
                                   nanoVdbFile({empty, constantTemperatureGrid(3000.0f)}));
  EXPECT_NE(scene.mediumGrids[0].temperature, kNoGridValues);
  EXPECT_EQ(imageMean(renderMediaScene(scene, 16, 3)).mean, 0.0);
  EXPECT_NE(loadError(folder, nanoVdbFile({constantTemperatureGrid(3000.0f)}))
                .find("has no grid named 'density' (its grids: 'temperature')"),
            std::string::npos);
}

// The temperature is read over the density's cells: where its own box is elsewhere, its voxels land on the
// density's samples of the same index, its background elsewhere; downsampled, it is averaged over the same cells.
TEST(NanoVdbMedia, TemperatureIsSampledOverTheDensitysCells) {
  TempFolder folder;
  TestNanoVdbGrid temperature = varyingGrid();  // 5 x 3 x 4 from (-3, 2, 7)
  temperature.name = "temperature";
  temperature.origin = {-1, 2, 7};
  temperature.size = {2, 1, 1};
  temperature.values = {2000.0f, 4000.0f};
  temperature.background = 500.0f;
  const Scene scene =
      loadWithFile(folder, slabScene(nanoVdbMedium("smoke.nvdb"), 0.5f), nanoVdbFile({varyingGrid(), temperature}));
  const MediumGrid& grid = scene.mediumGrids[0];
  ASSERT_NE(grid.temperature, kNoGridValues);
  ASSERT_EQ(grid.nx, 5u);
  const float* density = scene.mediumGridValues.data() + grid.density;
  const float* kelvins = scene.mediumGridValues.data() + grid.temperature;
  for (size_t i = 0; i < varyingGrid().values.size(); ++i) {
    ASSERT_EQ(density[i], varyingGrid().values[i]);
    // Sample i is voxel (-3 + x, 2 + y, 7 + z).
    const size_t x = i % 5, y = (i / 5) % 3, z = i / 15;
    const float kelvin = (y == 0 && z == 0 && x == 2) ? 2000.0f : (y == 0 && z == 0 && x == 3) ? 4000.0f : 500.0f;
    EXPECT_EQ(kelvins[i], kelvin) << i;
  }

  // Downsampled, it averages as a grid of the density's box with the same values would.
  const std::string path = folder.write("both.nvdb", nanoVdbFile({varyingGrid(), temperature}));
  const NanoVdbFile file(path);
  std::vector<float> densities, temperatures, reference;
  const NanoVdbDenseGrid dense = appendNanoVdbDenseGrid(file.gridBytes(file.grids()[0]), path, "density", 2, densities);
  const NanoVdbDenseGrid sampled = appendNanoVdbDenseGridLike(file.gridBytes(file.grids()[1]), path, "temperature",
                                                              dense, NanoVdbValues::Finite, temperatures);
  EXPECT_EQ(sampled.nx, dense.nx);
  EXPECT_EQ(sampled.indexMin[0], dense.indexMin[0]);
  // The same voxels as a grid over the density's whole box, background included, read on its own.
  TestNanoVdbGrid whole = varyingGrid();
  for (uint32_t i = 0; i < whole.values.size(); ++i) {
    const uint32_t x = i % 5, y = (i / 5) % 3, z = i / 15;
    whole.values[i] = (y == 0 && z == 0 && x == 2) ? 2000.0f : (y == 0 && z == 0 && x == 3) ? 4000.0f : 500.0f;
  }
  const std::string wholePath = folder.write("whole.nvdb", nanoVdbFile({whole}));
  const NanoVdbFile wholeFile(wholePath);
  appendNanoVdbDenseGrid(wholeFile.gridBytes(wholeFile.grids()[0]), wholePath, "density", 2, reference);
  ASSERT_EQ(temperatures.size(), reference.size());
  for (size_t i = 0; i < reference.size(); ++i) EXPECT_NEAR(temperatures[i], reference[i], 1e-3f) << i;
}

// Temperature grids that cannot be read as such refuse the file in one line; those that can but say odd things
// load as documented: negative temperatures are colder than the cutoff, huge ones glow as 1e5 K, a grid placed by
// another map than the density's or a missing grid named by the scene leave the medium dark with a warning, a
// missing grid of the default name leaves it dark silently (as pbrt-v4).
TEST(NanoVdbMedia, OddTemperatureGridsAreRefusedOrDocumented) {
  TempFolder folder;
  TestNanoVdbGrid vectors = constantTemperatureGrid(1000.0f);
  vectors.valueType = 6;
  TestNanoVdbGrid levelSet = constantTemperatureGrid(1000.0f);
  levelSet.gridClass = 1;
  TestNanoVdbGrid notANumber = constantTemperatureGrid(1000.0f);
  notANumber.values[5] = std::nanf("");
  const struct {
    std::string file, expected, parameters = "";
  } refused[] = {
      {nanoVdbFile({constantSlabGrid(), vectors}), "grid 'temperature' holds Vec3f values; only float temperatures"},
      {nanoVdbFile({constantSlabGrid(), levelSet}), "grid 'temperature' is a level set, not a fog volume"},
      {nanoVdbFile({constantSlabGrid(), notANumber}), "grid 'temperature' has a non-finite value (nan)"},
      {nanoVdbFile({constantSlabGrid()}), "'Lescale' must not be negative", "\"float Lescale\" -1"},
  };
  for (const auto& c : refused) {
    std::string message = "(no error)";
    try {
      loadWithFile(folder, slabScene(nanoVdbMedium("smoke.nvdb", c.parameters), 0.5f), c.file);
    } catch (const LoadError& e) {
      message = e.what();
    }
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.expected << ": " << message;
    EXPECT_NE(message.find("main.pbrt:"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }

  auto load = [&](const std::vector<TestNanoVdbGrid>& grids, const std::string& parameters, LoadWarnings& warnings) {
    return loadWithFile(folder, slabScene(nanoVdbMedium("smoke.nvdb", parameters), 0.5f), nanoVdbFile(grids),
                        &warnings);
  };
  LoadWarnings warnings;
  EXPECT_EQ(load({constantSlabGrid(), constantTemperatureGrid(-3000.0f)}, "", warnings).mediumGrids[0].kind,
            MediumGridKind::Density);
  const Scene negativeOffset =
      load({constantSlabGrid(), constantTemperatureGrid(-3000.0f)}, "\"float temperatureoffset\" -6000", warnings);
  const MediumGrid& lifted = negativeOffset.mediumGrids[0];
  ASSERT_NE(lifted.temperature, kNoGridValues);
  EXPECT_EQ(negativeOffset.mediumGridValues[lifted.temperature], -3000.0f);
  EXPECT_EQ(lifted.temperatureOffset, -6000.0f);
  const Scene huge =
      load({constantSlabGrid(), constantTemperatureGrid(3e38f)}, "\"float temperaturescale\" 1e38", warnings);
  const MediumGrid& hot = huge.mediumGrids[0];
  ASSERT_NE(hot.temperature, kNoGridValues);
  const float kelvin = (huge.mediumGridValues[hot.temperature] - hot.temperatureOffset) * hot.temperatureScale;
  EXPECT_EQ(blackbodyEmission(huge.mediumGridValues.data() + hot.blackbody, kelvin).z,
            blackbodyEmission(huge.mediumGridValues.data() + hot.blackbody, kBlackbodyHottestKelvin).z);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];

  // A map that differs in the last digits places the voxels where the density's does; one that moves them by
  // 1/50 of a voxel (at the box's far corner) does not.
  TestNanoVdbGrid close = constantTemperatureGrid(3000.0f);
  close.voxelSize[0] *= 1.0 + 1e-9;
  close.translation[2] += 1e-9;
  EXPECT_NE(load({constantSlabGrid(), close}, "", warnings).mediumGrids[0].temperature, kNoGridValues);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  TestNanoVdbGrid moved = constantTemperatureGrid(3000.0f);
  moved.voxelSize[0] *= 1.0 + 0.02 / 15;
  LoadWarnings movedWarnings;
  EXPECT_EQ(load({constantSlabGrid(), moved}, "", movedWarnings).mediumGrids[0].temperature, kNoGridValues);
  ASSERT_EQ(movedWarnings.messages.size(), 1u);
  EXPECT_NE(movedWarnings.messages[0].find("'density' and 'temperature' have different index-to-world maps"),
            std::string::npos)
      << movedWarnings.messages[0];

  LoadWarnings missing;
  EXPECT_EQ(load({constantSlabGrid()}, "", missing).mediumGrids[0].temperature, kNoGridValues);
  EXPECT_TRUE(missing.messages.empty()) << missing.messages[0];
  EXPECT_EQ(load({constantSlabGrid(), constantTemperatureGrid(3000.0f)}, "\"string temperaturename\" \"heat\"", missing)
                .mediumGrids[0]
                .kind,
            MediumGridKind::Density);
  ASSERT_EQ(missing.messages.size(), 1u);
  EXPECT_NE(missing.messages[0].find("has no grid named 'heat' (its grids: 'density', 'temperature'): the medium "
                                     "does not emit"),
            std::string::npos)
      << missing.messages[0];
}

template <typename T>
std::string patched(std::string file, size_t at, T value) {
  std::memcpy(file.data() + at, &value, sizeof(T));
  return file;
}

// Files that are not what they claim: one line each, at the directive, naming what is wrong.
TEST(NanoVdbMedia, HostileFilesAreRefusedInOneLine) {
  TempFolder folder;
  const std::string good = nanoVdbFile({varyingGrid()});
  const size_t grid = firstGridOffset("density"), root = grid + 672 + 64;
  TestNanoVdbGrid vectors = varyingGrid();
  vectors.valueType = 6;
  TestNanoVdbGrid levelSet = varyingGrid();
  levelSet.gridClass = 1;
  // Where voxel (-3, 2, 7)'s value is stored.
  const float firstValue = varyingGrid().values[0];
  const size_t firstValueAt = good.find(std::string(reinterpret_cast<const char*>(&firstValue), sizeof(float)), grid);
  std::string corruptZip = nanoVdbFile({varyingGrid()}, true);
  corruptZip[grid + 20] = char(corruptZip[grid + 20] ^ 0x5a);
  const struct {
    std::string file, expected, reference = "smoke.nvdb";
  } cases[] = {
      {good, "absent.nvdb", "absent.nvdb"},
      {good, "outside", "../smoke.nvdb"},
      {"ply\nformat ascii 1.0\nend_header\n", "is not a NanoVDB file"},
      {good.substr(0, 10), "ends inside a segment header: the file is truncated"},
      {good.substr(0, 100), "ends inside a grid description: the file is truncated"},
      {good.substr(0, good.size() - 100), "beyond the file's end: the file is truncated"},
      {patched(good, 16 + 8, uint64_t(1) << 40), "beyond the file's end"},
      {patched(good, 16, uint64_t(1) << 40), "states 1099511627776 bytes, more than the largest input accepted"},
      {patched(good, 16, uint64_t(1000)), "states 1000 bytes but stores"},
      {patched(good, 8, uint32_t(29) << 21), "is a NanoVDB 29.0.0 file; version 32 files are read"},
      {patched(good, 14, uint16_t(2)), "is Blosc-compressed, which is not read"},
      {nanoVdbFile({vectors}), "grid 'density' holds Vec3f values; only float grids are read"},
      {nanoVdbFile({levelSet}), "grid 'density' is a level set, not a fog volume"},
      {patched(good, 16 + 176, 'x'), "has no grid named 'density' (its grids: 'xensity')"},
      {patched(good, root + 12, int32_t(1) << 30), "has voxels beyond 2^24 from its origin"},
      {patched(good, root + 12, int32_t(1) << 21), "has a bounding box of 2097156 voxels a side, more than 2^20"},
      {patched(good, root + 64 + 8, int64_t(12345)), "has a child offset that names no upper node"},
      {patched(good, grid + 672 + 24, uint64_t(1) << 50), "has its root beyond its bytes"},
      {patched(good, grid + 672 + 32, uint32_t(1) << 30), "states 1073741824 leaves beyond its bytes"},
      {patched(good, grid + 296 + 88, std::nan("")), "has a non-finite index-to-world map"},
      {patched(good, firstValueAt, -1.0f), "has a negative or non-finite value (-1.0"},
      {corruptZip, "does not decompress"},
      {patched(nanoVdbFile({varyingGrid()}, true), 16, uint64_t(1) << 32), "compressed bytes can hold"},
  };
  for (const auto& c : cases) {
    const std::string message = loadError(folder, c.file, c.reference);
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.expected << ": " << message;
    EXPECT_NE(message.find("main.pbrt:"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// Files damaged at random where their sizes and offsets are (headers, descriptions, GridData, the tree's and the
// root's fields, node headers), in both codecs, are read or refused with a LoadError, never anything else; the
// sanitizer builds check that no byte outside them is read.
TEST(NanoVdbMedia, DamagedFilesAreReadOrRefused) {
  TempFolder folder;
  std::mt19937_64 random(11);
  for (bool zip : {false, true}) {
    const std::string original = nanoVdbFile({varyingGrid(), constantSlabGrid()}, zip);
    for (int trial = 0; trial < 150; ++trial) {
      std::string damaged = original;
      for (int edit = 0, edits = 1 + int(random() % 6); edit < edits; ++edit) {
        const size_t at = random() % std::min<size_t>(damaged.size(), 2048);
        if (random() % 3 == 0 && at + 8 <= damaged.size()) {
          const uint64_t v = random() >> (random() % 64);
          std::memcpy(damaged.data() + at, &v, sizeof(v));
        } else if (random() % 8 == 0) {
          damaged.resize(at + 1);
        } else {
          damaged[at] = char(random());
        }
      }
      const std::string path = folder.write("damaged.nvdb", damaged);
      try {
        const NanoVdbFile file(path);
        for (const NanoVdbGridEntry& grid : file.grids()) {
          std::vector<float> values;
          appendNanoVdbDenseGrid(file.gridBytes(grid), path, grid.name, 16, values);
        }
      } catch (const LoadError&) {
      }
    }
  }
}

}  // namespace
}  // namespace candela::test
