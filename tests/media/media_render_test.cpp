// Whole renders through participating media on the CPU backend, against answers known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "backends/cpu/cpu_backend.h"
#include "media/media_render.h"
#include "media/media_scenes.h"
#include "scene/builtin_scenes.h"

namespace candela::test {
namespace {

constexpr uint32_t kBatches = kMediaBatches;
constexpr double kAlpha = 0.01;

PixelStatistics render(const Scene& scene, uint32_t size, SamplerKind sampler = SamplerKind::Independent) {
  return renderMediaScene(scene, size, 11, sampler);
}

Vec3 expTransmittance(Vec3 sigmaT, float d) {
  return {std::exp(-sigmaT.x * d), std::exp(-sigmaT.y * d), std::exp(-sigmaT.z * d)};
}

size_t rejected(const PixelStatistics& stats, Vec3 expected) {
  std::string worst;
  return countRejectedPixels(stats, expected, kBatches, kAlpha, worst);
}

// A purely absorbing slab, each channel absorbing differently: every pixel is exp(-sigma_a d) per channel, and
// the test rejects the transmittance of a slab 10% thicker.
TEST(MediaRender, AbsorbingSlabTransmitsExpMinusSigmaTimesDepth) {
  Medium m;
  m.sigmaA = {0.5f, 1.0f, 2.0f};
  m.sigmaS = {0, 0, 0};
  for (SamplerKind sampler : {SamplerKind::Independent, SamplerKind::Sobol}) {
    SCOPED_TRACE(sampler == SamplerKind::Sobol ? "sobol" : "independent");
    const PixelStatistics stats = render(makeMediumSlab(m, 1.0f), 16, sampler);
    std::string worst;
    EXPECT_EQ(countRejectedPixels(stats, expTransmittance(m.sigmaA, 1.0f), kBatches, kAlpha, worst), 0u) << worst;
    EXPECT_EQ(stats.invalidSamples, 0u);
    EXPECT_GT(rejected(stats, expTransmittance(m.sigmaA, 1.1f)), 0u);
  }
}

// The image mean over all channels, which must be within 4 standard errors of `expected` (pixels independent).
void expectImageMean(const PixelStatistics& stats, double expected) {
  const ImageMean m = imageMean(stats);
  EXPECT_LT(std::fabs(m.mean - expected), 4.0 * m.standardError) << m.mean << " +- " << m.standardError;
}

// Inside a black enclosure that emits 1, a medium that scatters everything it stops (albedo 1) keeps the
// radiance at 1 everywhere: next-event estimation through the medium, phase sampling and their MIS weights must
// add up. A grey medium is tested pixel by pixel. Where the channels' sigma_t differ, a path's throughput per
// channel is a product of the spectral MIS weights (up to 3 each), whose rare large values leave batch means far
// from normal: that medium is tested on the image mean, where the central limit theorem holds over all pixels.
TEST(MediaRender, FurnaceOfAlbedoOneIsOneEverywhere) {
  Medium grey;
  grey.sigmaA = {0, 0, 0};
  grey.sigmaS = {1.5f, 1.5f, 1.5f};
  grey.g = 0.6f;
  const PixelStatistics stats = render(makeMediumFurnace(grey), 16);
  std::string worst;
  EXPECT_EQ(countRejectedPixels(stats, {1, 1, 1}, kBatches, kAlpha, worst), 0u) << worst;
  EXPECT_EQ(stats.invalidSamples, 0u);
  expectImageMean(stats, 1.0);

  Medium chromatic = grey;
  chromatic.sigmaS = {1.5f, 0.5f, 3.0f};
  const PixelStatistics chromaticStats = render(makeMediumFurnace(chromatic), 16);
  expectImageMean(chromaticStats, 1.0);
  EXPECT_EQ(chromaticStats.invalidSamples, 0u);
}

TEST(MediaRender, EmittingFurnaceIsOneEverywhere) {
  Medium emitting;
  emitting.sigmaA = {1.0f, 2.0f, 0.5f};
  emitting.sigmaS = {0.5f, 0.5f, 1.0f};
  emitting.emission = {1, 1, 1};
  emitting.g = -0.3f;
  const PixelStatistics stats = render(makeMediumFurnace(emitting), 16);
  std::string worst;
  EXPECT_EQ(countRejectedPixels(stats, {1, 1, 1}, kBatches, kAlpha, worst), 0u) << worst;
  Medium dark = emitting;
  dark.emission = {0, 0, 0};
  EXPECT_GT(rejected(render(makeMediumFurnace(dark), 16), {1, 1, 1}), 0u);
}

// An interface sphere inside a closed emissive sphere changes nothing, in a scene without media (where it is a
// cut-out) and inside a furnace's medium (where rays cross it, into the same medium).
TEST(MediaRender, InterfaceMaterialIsInvisible) {
  auto withInterfaceSphere = [](Scene scene, MediumInterface media) {
    scene.materials.push_back(interfaceMaterial());
    scene.meshes.push_back(makeUvSphere(0.4f, 24, 12, uint32_t(scene.materials.size() - 1), false));
    Affine3x4 placed;
    placed.m[11] = 0.3f;
    scene.instances.push_back({uint32_t(scene.meshes.size() - 1), placed, media});
    return scene;
  };
  const PixelStatistics noMedia = render(withInterfaceSphere(makeClosedEmissiveSphere(0.5f, 0.5f), {}), 16);
  std::string worst;
  EXPECT_EQ(countRejectedPixels(noMedia, {1, 1, 1}, kBatches, kAlpha, worst), 0u) << worst;
  Medium scattering;
  scattering.sigmaA = {0, 0, 0};
  scattering.sigmaS = {1, 1, 1};
  const PixelStatistics inMedium = render(withInterfaceSphere(makeMediumFurnace(scattering), {0, 0}), 16);
  EXPECT_EQ(countRejectedPixels(inMedium, {1, 1, 1}, kBatches, kAlpha, worst), 0u) << worst;
}

// Media change nothing in a scene that has none: the CPU backend renders such scenes with the path that does not
// know media, and the path that does draws the same numbers there, so a render of each is the same bit for bit.
TEST(MediaRender, ScenesWithoutMediaRenderAsBefore) {
  Scene scene = makeCornellBox();
  CpuBackend backend;
  backend.setScene(scene);
  RenderSettings settings;
  settings.width = settings.height = 24;
  backend.setSettings(settings);
  backend.setCamera(scene.camera.toCamera(1.0f));
  backend.render(4);
  const Image without = backend.readImage();

  // A medium that no instance bounds and the camera is not in turns the media path on, and is met nowhere.
  Medium unused;
  unused.sigmaS = {1, 1, 1};
  scene.media = {unused};
  backend.setScene(scene);
  backend.render(4);
  const Image with = backend.readImage();
  ASSERT_EQ(without.pixels.size(), with.pixels.size());
  for (size_t i = 0; i < with.pixels.size(); ++i) {
    ASSERT_EQ(without.pixels[i].x, with.pixels[i].x) << i;
    ASSERT_EQ(without.pixels[i].y, with.pixels[i].y) << i;
    ASSERT_EQ(without.pixels[i].z, with.pixels[i].z) << i;
  }
}

TEST(MediaRender, RestirRefusesMedia) {
  Medium m;
  CpuBackend backend;
  backend.setScene(makeMediumFurnace(m));
  RenderSettings settings;
  settings.width = settings.height = 4;
  settings.restir = RestirMode::Di;
  backend.setSettings(settings);
  EXPECT_THROW(backend.render(1), std::invalid_argument);
}

}  // namespace
}  // namespace candela::test
