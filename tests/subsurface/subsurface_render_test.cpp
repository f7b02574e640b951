// Subsurface scattering rendered on the CPU backend: a random walk inside a dielectric boundary that loses
// nothing returns all the light it takes in.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "backends/cpu/cpu_backend.h"
#include "media/media_scenes.h"
#include "support/render_statistics.h"

namespace candela::test {
namespace {

constexpr uint32_t kBatches = 32;
constexpr uint32_t kSamplesPerBatch = 8;

// A smooth dielectric sphere of radius 1 and index `eta` around `interior` (a subsurface medium), under an
// environment of radiance 1, seen from outside so that it fills most of the image. The sphere has no vertex
// normals: the dielectric refracts about the geometric normal, so that it reflects and transmits everything.
Scene makeSubsurfaceFurnace(const Medium& interior, float eta) {
  Scene scene;
  scene.name = "subsurface-furnace";
  Material boundary;
  boundary.type = MaterialType::Glass;
  boundary.baseColor = {1, 1, 1};
  boundary.ior = eta;
  scene.materials = {boundary};
  scene.meshes.push_back(makeUvSphere(1.0f, 48, 24, 0, /*inward=*/false));
  scene.meshes.back().normals.clear();
  scene.media = {interior};
  scene.instances.push_back({0, Affine3x4{}, {0, kNoMedium}});
  scene.environment.radiance = {1, 1, 1};
  scene.camera.eye = {0, 0, -3};
  scene.camera.target = {0, 0, 0};
  scene.camera.verticalFovDegrees = 45.0f;
  return scene;
}

PixelStatistics render(const Scene& scene, uint32_t maxDepth) {
  CpuBackend backend;
  backend.setScene(scene);
  RenderSettings settings;
  settings.sampler = SamplerKind::Independent;
  settings.width = settings.height = 16;
  settings.maxDepth = maxDepth;
  settings.seed = 5;
  backend.setSettings(settings);
  backend.setCamera(scene.camera.toCamera(1.0f));
  return renderBatches(backend, kBatches, kSamplesPerBatch);
}

// Albedo 1 inside a smooth dielectric: whatever enters leaves again, so every pixel is the environment's 1,
// whatever the Fresnel split at each crossing. The medium is dense enough (optical radius 3) that many walks take
// more collisions than the path's 16 bounces: they must not count against it. A walk that counted them, or a
// boundary that lost or made energy, fails the test.
TEST(SubsurfaceRender, FurnaceOfAlbedoOneIsOneEverywhere) {
  for (float g : {0.0f, 0.7f}) {
    SCOPED_TRACE("g " + std::to_string(g));
    Medium interior;
    interior.sigmaA = {0, 0, 0};
    interior.sigmaS = {3, 3, 3};
    interior.g = g;
    interior.subsurface = 1;
    const PixelStatistics stats = render(makeSubsurfaceFurnace(interior, 1.33f), 16);
    std::string worst;
    EXPECT_EQ(countRejectedPixels(stats, {1, 1, 1}, kBatches, 0.01, worst), 0u) << worst;
    EXPECT_EQ(stats.invalidSamples, 0u);
    const ImageMean mean = imageMean(stats);
    EXPECT_NEAR(mean.mean, 1.0, 4.0 * mean.standardError + 1e-3);
  }
}

// The same sphere with an absorbing interior is darker than the furnace, and the more so the more it absorbs:
// the walk's throughput falls with the medium's albedo.
TEST(SubsurfaceRender, AbsorptionDarkensTheWalk) {
  double previous = 1.0;
  for (float sigmaA : {0.05f, 0.5f}) {
    Medium interior;
    interior.sigmaA = {sigmaA, sigmaA, sigmaA};
    interior.sigmaS = {3, 3, 3};
    interior.subsurface = 1;
    const PixelStatistics stats = render(makeSubsurfaceFurnace(interior, 1.33f), 16);
    const ImageMean mean = imageMean(stats);
    EXPECT_LT(mean.mean, previous - 4.0 * mean.standardError) << sigmaA;
    EXPECT_EQ(stats.invalidSamples, 0u);
    previous = mean.mean;
  }
}

// A scene that reaches the backends from elsewhere than a loader (the API, a cache) is validated: a negative
// transmittance would make a lobe's choice probability negative, a subsurface flag other than 0 or 1 is no
// scene's.
TEST(SubsurfaceRender, ValidationRefusesWhatNoLoaderMakes) {
  Medium interior;
  interior.sigmaS = {1, 1, 1};
  interior.subsurface = 1;
  Scene scene = makeSubsurfaceFurnace(interior, 1.33f);
  EXPECT_NO_THROW(validateScene(scene));
  scene.media[0].subsurface = 2;
  EXPECT_THROW(validateScene(scene), std::runtime_error);
  scene.media[0].subsurface = 1;
  scene.materials[0].type = MaterialType::DiffuseTransmission;
  scene.materials[0].transmittance = {0.5f, -0.1f, 0.5f};
  EXPECT_THROW(validateScene(scene), std::runtime_error);
}

}  // namespace
}  // namespace candela::test
