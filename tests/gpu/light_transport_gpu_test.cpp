// CPU and GPU renders of light that goes through things must agree (see expectRendersAgree): participating media
// of every kind (the OptiX backend renders them with a megakernel of its own, device/media_programs.cu), the
// camera in a medium, emission from grids and from temperatures, subsurface random walks and diffuse transmission.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "backend_agreement.h"
#include "light_transport_scenes.h"

namespace candela {
namespace {

// The backends agree, on a scene that light reaches and without an invalid sample on either.
void expectBackendsAgree(const Scene& scene, uint32_t seed) {
  const test::AgreementRun run;
  const test::BackendStatistics s = test::renderOnBoth(scene, scene, seed, run);
  EXPECT_EQ(s.cpu.invalidSamples, 0u);
  EXPECT_EQ(s.gpu.invalidSamples, 0u);
  // Not black: two renders of a scene that no light reaches would agree whatever the media did.
  EXPECT_GT(test::imageMean(s.cpu).mean, 0.01);
  test::expectRendersAgree(s.cpu, s.gpu, run.block, run.batches, run.alpha);
}

// A forward-scattering fog sphere and a backward-scattering smoke box around a diffuse sphere, chromatic both.
TEST(GpuHomogeneousMedia, FogAndSmokeAgreeWithTheCpuBackend) {
  test::TempFolder folder;
  const Scene scene = test::makeFogRoom(folder);
  ASSERT_EQ(scene.media.size(), 2u);
  EXPECT_EQ(scene.cameraMedium, kNoMedium);
  expectBackendsAgree(scene, 211);
}

// Camera rays start in a haze and cross into the fog sphere inside it.
TEST(GpuHomogeneousMedia, CameraInAHazeAgreesWithTheCpuBackend) {
  test::TempFolder folder;
  const Scene scene = test::makeHazyRoom(folder);
  ASSERT_EQ(scene.media.size(), 2u);
  ASSERT_NE(scene.cameraMedium, kNoMedium);
  expectBackendsAgree(scene, 221);
}

// The media tests must be able to fail: a GPU render of the hazy room whose haze and fog are 10% denser is
// rejected by both parts of the comparison.
TEST(GpuHomogeneousMedia, AgreementTestDetectsADenserMedium) {
  test::TempFolder folder;
  const Scene scene = test::makeHazyRoom(folder);
  const test::AgreementRun run;
  const test::BackendStatistics s = test::renderOnBoth(scene, test::withDenserHomogeneousMedia(scene, 1.1f), 231, run);
  const test::BlockComparison blocks = test::compareBlocks(s.cpu, s.gpu, run.block, run.batches, run.alpha);
  EXPECT_GT(blocks.rejected, 0u);
  Image difference(run.size, run.size);
  for (size_t i = 0; i < difference.pixels.size(); ++i)
    difference.pixels[i] = s.cpu.mean.pixels[i] - s.gpu.mean.pixels[i];
  const test::ImageMean d = test::imageMean(difference);
  EXPECT_GT(std::fabs(d.mean), test::twoSidedNormalQuantile(run.alpha) * d.standardError);
}

// A uniformgrid of varying density with empty regions (skipped by the majorant grid's walk) that emits from its
// Lescale grid.
TEST(GpuGridMedia, UniformGridWithLescaleAgreesWithTheCpuBackend) {
  test::TempFolder folder;
  const Scene scene = test::makeUniformGridRoom(folder);
  ASSERT_EQ(scene.mediumGrids.size(), 1u);
  EXPECT_EQ(scene.mediumGrids[0].kind, MediumGridKind::Density);
  EXPECT_NE(scene.mediumGrids[0].emission, kNoGridValues);
  expectBackendsAgree(scene, 241);
}

// An rgbgrid of chromatic coefficients beside a procedural cloud.
TEST(GpuGridMedia, RgbGridAndCloudAgreeWithTheCpuBackend) {
  test::TempFolder folder;
  const Scene scene = test::makeRgbGridAndCloudRoom(folder);
  ASSERT_EQ(scene.mediumGrids.size(), 2u);
  EXPECT_NE(scene.mediumGrids[0].kind, scene.mediumGrids[1].kind);
  for (const MediumGrid& grid : scene.mediumGrids) EXPECT_NE(grid.kind, MediumGridKind::Density);
  expectBackendsAgree(scene, 251);
}

// A nanovdb medium from a .nvdb file whose temperature grid emits a blackbody (interpolated, then looked up in
// the scene's blackbody table).
TEST(GpuNanoVdbMedia, TemperatureEmissionAgreesWithTheCpuBackend) {
  test::TempFolder folder;
  const Scene scene = test::makeNanoVdbRoom(folder);
  ASSERT_EQ(scene.mediumGrids.size(), 1u);
  EXPECT_EQ(scene.mediumGrids[0].kind, MediumGridKind::Density);
  EXPECT_NE(scene.mediumGrids[0].temperature, kNoGridValues);
  expectBackendsAgree(scene, 261);
}

// Random walks inside pbrt's `subsurface` sphere (reflectance and mfp) and box (sigma_a and sigma_s, a rough
// boundary), and a `diffusetransmission` sphere.
TEST(GpuSubsurface, RandomWalksAndDiffuseTransmissionAgreeWithTheCpuBackend) {
  test::TempFolder folder;
  const Scene scene = test::makeSubsurfaceRoom(folder);
  ASSERT_EQ(scene.media.size(), 2u);
  EXPECT_EQ(scene.media[0].subsurface, 1u);
  EXPECT_EQ(scene.media[1].subsurface, 1u);
  EXPECT_TRUE(std::any_of(scene.materials.begin(), scene.materials.end(),
                          [](const Material& m) { return m.type == MaterialType::DiffuseTransmission; }));
  expectBackendsAgree(scene, 271);
}

}  // namespace
}  // namespace candela
