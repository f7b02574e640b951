// The Cornell box on the OptiX backend: valid samples, determinism, accumulation across launches, and
// agreement with the CPU backend.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "gpu_render.h"
#include "render_comparison.h"
#include "support/render_statistics.h"

namespace candela {
namespace {

constexpr uint32_t kSize = 64;
constexpr double kAlpha = 0.01;

struct Render {
  Image image;
  FrameStats stats;
};

// `launches` launches of `samplesPerLaunch` samples each.
Render renderGpu(uint32_t seed, uint32_t launches, uint32_t samplesPerLaunch) {
  auto backend = test::makeBackend<OptixBackend>(makeCornellBox(), test::squareImage(kSize, seed));
  Render r;
  for (uint32_t i = 0; i < launches; ++i) {
    FrameStats f = backend->render(samplesPerLaunch);
    r.stats.rays += f.rays;
    r.stats.invalidSamples += f.invalidSamples;
  }
  EXPECT_EQ(backend->accumulatedSamples(), launches * samplesPerLaunch);
  r.image = backend->readImage();
  return r;
}

TEST(GpuCornellBox, NoNaNsNoInvalidSamples) {
  Render r = renderGpu(1, 64, 1);
  EXPECT_EQ(r.stats.invalidSamples, 0u);
  for (Vec3 p : r.image.pixels) ASSERT_TRUE(isFinite(p) && p.x >= 0.0f && p.y >= 0.0f && p.z >= 0.0f);
  // Every sample traces at least its camera ray, and most of them bounce.
  EXPECT_GT(r.stats.rays, uint64_t(kSize * kSize * 64) * 2);
  EXPECT_GT(test::imageMean(r.image).mean, 0.05) << "the box must be lit";
}

TEST(GpuCornellBox, SameSeedGivesTheSameImageBitForBit) {
  Render a = renderGpu(3, 8, 1), b = renderGpu(3, 8, 1);
  ASSERT_EQ(a.image.pixels.size(), b.image.pixels.size());
  EXPECT_EQ(std::memcmp(a.image.pixels.data(), b.image.pixels.data(), a.image.pixels.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(a.stats.rays, b.stats.rays);
}

// One launch of 32 samples per pixel and 32 launches of one draw the same sample indices, hence the same
// random numbers and paths: the same rays, and sums that differ at most by float rounding (today the order
// of the additions is the same too, so the images are identical; 1e-6 relative leaves room for rounding only).
TEST(GpuCornellBox, OneLaunchOfManySamplesEqualsManyLaunchesOfOne) {
  Render one = renderGpu(5, 1, 32), many = renderGpu(5, 32, 1);
  EXPECT_EQ(one.stats.rays, many.stats.rays);
  for (size_t i = 0; i < one.image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      float a = one.image.pixels[i][c], b = many.image.pixels[i][c];
      ASSERT_LE(std::fabs(a - b), 1e-6f * std::fmax(std::fabs(a), std::fabs(b))) << "pixel " << i;
    }
}

// With different seeds, several launches and one launch are independent estimates of the same image.
TEST(GpuCornellBox, LaunchSplitDoesNotChangeTheImageStatistically) {
  Render one = renderGpu(6, 1, 64), many = renderGpu(7, 16, 4);
  Image difference(kSize, kSize);
  for (size_t i = 0; i < difference.pixels.size(); ++i)
    difference.pixels[i] = one.image.pixels[i] - many.image.pixels[i];
  test::ImageMean d = test::imageMean(difference);
  EXPECT_GT(d.standardError, 0.0);
  EXPECT_LT(std::fabs(d.mean), test::twoSidedNormalQuantile(kAlpha) * d.standardError)
      << d.mean << " +- " << d.standardError;
}

constexpr uint32_t kBatches = 32;
constexpr uint32_t kSamplesPerBatch = 32;
constexpr uint32_t kBlock = 4;

template <class BackendType>
test::PixelStatistics batchStatistics(const Scene& scene, uint32_t seed, uint32_t maxDepth) {
  RenderSettings settings = test::squareImage(kSize, seed);
  settings.maxDepth = maxDepth;
  return test::batchStatistics<BackendType>(scene, settings, kBatches, kSamplesPerBatch);
}

void expectAgreement(const test::PixelStatistics& cpu, const test::PixelStatistics& gpu) {
  test::expectRendersAgree(cpu, gpu, kBlock, kBatches, kAlpha);
}

TEST(GpuCornellBox, AgreesWithTheCpuBackend) {
  test::PixelStatistics cpu = batchStatistics<CpuBackend>(makeCornellBox(), 21, 8);
  test::PixelStatistics gpu = batchStatistics<OptixBackend>(makeCornellBox(), 22, 8);
  EXPECT_EQ(cpu.invalidSamples, 0u);
  EXPECT_EQ(gpu.invalidSamples, 0u);
  expectAgreement(cpu, gpu);
}

// Two meshes, three instances (one mesh instanced twice with scale and translation): IAS instance ids must
// map to the right InstanceRecord for the GPU image to match.
TEST(GpuCornellSpheres, AgreesWithTheCpuBackend) {
  test::PixelStatistics cpu = batchStatistics<CpuBackend>(makeCornellSpheres(), 31, 8);
  test::PixelStatistics gpu = batchStatistics<OptixBackend>(makeCornellSpheres(), 32, 8);
  expectAgreement(cpu, gpu);
}

// The agreement test must be able to fail: a GPU render that stops after 3 bounces (about a tenth of the
// light in this box arrives after more) is rejected by both parts.
TEST(GpuCornellBox, AgreementTestDetectsMissingBounces) {
  test::PixelStatistics cpu = batchStatistics<CpuBackend>(makeCornellBox(), 21, 8);
  test::PixelStatistics gpu = batchStatistics<OptixBackend>(makeCornellBox(), 22, 3);
  test::BlockComparison blocks = test::compareBlocks(cpu, gpu, kBlock, kBatches, kAlpha);
  EXPECT_GT(blocks.rejected, 0u);
  Image difference(kSize, kSize);
  for (size_t i = 0; i < difference.pixels.size(); ++i) difference.pixels[i] = cpu.mean.pixels[i] - gpu.mean.pixels[i];
  test::ImageMean d = test::imageMean(difference);
  EXPECT_GT(std::fabs(d.mean), test::twoSidedNormalQuantile(kAlpha) * d.standardError);
}

}  // namespace
}  // namespace candela
