// Grid media in the kernel: the trilinear lookup, the majorant grid, ratio tracking's transmittance and delta
// tracking's distances, each against answers computed another way (pbrt-v4's formulas, closed-form integrals of
// the piecewise-linear density along a ray).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "kernel/media/grid_tracking.h"
#include "media/media_grids.h"
#include "support/chi2.h"

namespace candela::test {
namespace {

float uniform(uint32_t i, uint32_t stream) { return bitsToUnitFloat(pcg4d({i, stream, 5u, 0x2545f491u}).x); }

// Samples at voxel centres, interpolated linearly between them and towards 0 beyond the outer ones.
TEST(MediumGrid, TrilinearLookupAsPbrtSampledGrid) {
  std::vector<MediumGrid> grids;
  std::vector<float> values;
  const Medium m = addDensityGrid(grids, values, {1, 1, 1}, {0, 0, 0}, 2, 1, 1, {2.0f, 4.0f}, {0, 0, 0}, {1, 1, 1});
  auto density = [&](float x) { return gridMediumAt(m, grids[0], values.data(), {x, 0.5f, 0.5f}).sigmaA.x; };
  EXPECT_FLOAT_EQ(density(0.25f), 2.0f);  // the first sample's centre
  EXPECT_FLOAT_EQ(density(0.5f), 3.0f);   // midway
  EXPECT_FLOAT_EQ(density(0.75f), 4.0f);
  EXPECT_FLOAT_EQ(density(0.0f), 1.0f);  // half a voxel beyond a centre: half the sample
  EXPECT_FLOAT_EQ(density(1.0f), 2.0f);
  // Off the samples' plane in y (one sample): the weight falls towards the empty neighbour.
  EXPECT_FLOAT_EQ(gridMediumAt(m, grids[0], values.data(), {0.25f, 0.25f, 0.5f}).sigmaA.x, 1.5f);
}

// How many of `pointsPerVoxel` random points in each majorant voxel have a channel of sigma_t above the voxel's
// majorant.
size_t majorantViolations(const Medium& m, const MediumGrid& grid, const std::vector<float>& values,
                          uint32_t pointsPerVoxel) {
  size_t violations = 0;
  uint32_t n = 0;
  for (uint32_t z = 0; z < grid.mz; ++z)
    for (uint32_t y = 0; y < grid.my; ++y)
      for (uint32_t x = 0; x < grid.mx; ++x)
        for (uint32_t i = 0; i < pointsPerVoxel; ++i, ++n) {
          const Vec3 unit{(float(x) + uniform(n, 1)) / float(grid.mx), (float(y) + uniform(n, 2)) / float(grid.my),
                          (float(z) + uniform(n, 3)) / float(grid.mz)};
          const Vec3 p = grid.p0 + (grid.p1 - grid.p0) * unit;
          const MediumPoint point = gridMediumAt(m, grid, values.data(), p);
          if (maxComponent(point.sigmaA + point.sigmaS) > gridMajorant(grid, values.data(), x, y, z)) ++violations;
        }
  return violations;
}

// Every voxel of the majorant grid bounds sigma_t wherever a lookup inside it lands, for a grid of a resolution
// that does not divide the majorant grid's; a majorant grid lowered by 10% is caught.
TEST(MediumGrid, MajorantGridBoundsEveryVoxel) {
  const uint32_t nx = 9, ny = 7, nz = 5;
  std::vector<float> density(nx * ny * nz);
  for (uint32_t i = 0; i < density.size(); ++i) density[i] = 3.0f * uniform(i, 7) * uniform(i, 8);
  std::vector<MediumGrid> grids;
  std::vector<float> values;
  const Medium m = addDensityGrid(grids, values, {0.5f, 1.0f, 2.0f}, {1.0f, 0.25f, 0.0f}, nx, ny, nz, density,
                                  {-1, 0, 2}, {3, 1, 2.5f});
  ASSERT_EQ(grids[0].mx * grids[0].my * grids[0].mz,
            kMajorantGridResolution * kMajorantGridResolution * kMajorantGridResolution);
  EXPECT_EQ(majorantViolations(m, grids[0], values, 16), 0u);
  for (uint32_t i = 0; i < grids[0].mx * grids[0].my * grids[0].mz; ++i) values[grids[0].majorants + i] *= 0.9f;
  EXPECT_GT(majorantViolations(m, grids[0], values, 16), 0u);
}

// The mean and standard error of `runs` estimates per channel.
struct ChannelMeans {
  Vec3 mean, error;
};

template <class Estimate>
ChannelMeans channelMeans(uint32_t runs, const Estimate& estimate) {
  double sum[3] = {}, squares[3] = {};
  for (uint32_t i = 0; i < runs; ++i) {
    const Vec3 v = estimate(i);
    const float c[3] = {v.x, v.y, v.z};
    for (int k = 0; k < 3; ++k) {
      sum[k] += c[k];
      squares[k] += double(c[k]) * c[k];
    }
  }
  auto mean = [&](int k) { return sum[k] / runs; };
  auto error = [&](int k) { return std::sqrt(std::max(0.0, squares[k] / runs - mean(k) * mean(k)) / runs); };
  return {{float(mean(0)), float(mean(1)), float(mean(2))}, {float(error(0)), float(error(1)), float(error(2))}};
}

// Whether every channel's mean lies within z standard errors of `expected`.
bool within(const ChannelMeans& m, Vec3 expected, float z) {
  return std::fabs(m.mean.x - expected.x) <= z * m.error.x + 1e-6f &&
         std::fabs(m.mean.y - expected.y) <= z * m.error.y + 1e-6f &&
         std::fabs(m.mean.z - expected.z) <= z * m.error.z + 1e-6f;
}

std::string describe(const ChannelMeans& m, Vec3 expected) {
  return "mean " + std::to_string(m.mean.x) + " " + std::to_string(m.mean.y) + " " + std::to_string(m.mean.z) + " +- " +
         std::to_string(m.error.x) + " " + std::to_string(m.error.y) + " " + std::to_string(m.error.z) + ", expected " +
         std::to_string(expected.x) + " " + std::to_string(expected.y) + " " + std::to_string(expected.z);
}

// A density varying along x only, nx samples over the unit cube, read along the line y = z = 0.5 (where the other
// axes' one sample has weight 1): piecewise linear between the samples' centres, falling to half the outer
// samples at the faces. Its integral from x = 0 to x, in closed form.
double densityIntegral(const std::vector<float>& d, double x) {
  const size_t n = d.size();
  std::vector<double> xs{0.0}, ys{0.5 * d[0]};
  for (size_t k = 0; k < n; ++k) {
    xs.push_back((double(k) + 0.5) / double(n));
    ys.push_back(d[k]);
  }
  xs.push_back(1.0);
  ys.push_back(0.5 * d[n - 1]);
  double sum = 0.0;
  for (size_t k = 0; k + 1 < xs.size() && xs[k] < x; ++k) {
    const double b = std::min(x, xs[k + 1]);
    const double yb = ys[k] + (ys[k + 1] - ys[k]) * (b - xs[k]) / (xs[k + 1] - xs[k]);
    sum += 0.5 * (ys[k] + yb) * (b - xs[k]);
  }
  return sum;
}

const std::vector<float> kRamp = {0.2f, 1.5f, 3.0f, 0.0f, 0.7f, 2.2f, 4.0f, 1.0f};

// Ratio tracking's transmittance through a density that varies along the ray, each channel differently (sigma_t
// 1, 1.25, 2), averages to exp(-sigma_t x the integral of the density). With the majorant grid halved the same
// estimate is biased and rejected.
TEST(GridTracking, RatioTrackingTransmittanceIsUnbiased) {
  std::vector<MediumGrid> grids;
  std::vector<float> values;
  const Vec3 sigmaA{0.5f, 1.0f, 2.0f}, sigmaS{0.5f, 0.25f, 0.0f};
  const Medium m =
      addDensityGrid(grids, values, sigmaA, sigmaS, uint32_t(kRamp.size()), 1, 1, kRamp, {0, 0, 0}, {1, 1, 1});
  const double tau = densityIntegral(kRamp, 1.0);
  const Vec3 sigmaT = sigmaA + sigmaS;
  const Vec3 expected{float(std::exp(-sigmaT.x * tau)), float(std::exp(-sigmaT.y * tau)),
                      float(std::exp(-sigmaT.z * tau))};
  // Rays start at different points behind the box, so that each seeds its own numbers.
  auto estimate = [&](uint32_t i) {
    const Ray ray{{-1.0f - float(i) * 1e-6f, 0.5f, 0.5f}, {1, 0, 0}, 0.0f, kInf};
    return gridMediumTransmittance(m, grids[0], values.data(), ray, kInf);
  };
  const ChannelMeans unbiased = channelMeans(200'000, estimate);
  EXPECT_TRUE(within(unbiased, expected, 5.0f)) << describe(unbiased, expected);
  for (uint32_t i = 0; i < grids[0].mx * grids[0].my * grids[0].mz; ++i) values[grids[0].majorants + i] *= 0.5f;
  const ChannelMeans tooSmall = channelMeans(200'000, estimate);
  EXPECT_FALSE(within(tooSmall, expected, 5.0f)) << describe(tooSmall, expected);
}

// The same along a diagonal ray through a grid that varies on all three axes under a transform (the DDA steps
// on every axis): the integral is taken by the midpoint rule over the lookups, with an error far below the test's.
TEST(GridTracking, RatioTrackingAlongADiagonalThroughATransformedGrid) {
  const uint32_t nx = 5, ny = 4, nz = 3;
  std::vector<float> density(nx * ny * nz);
  for (uint32_t i = 0; i < density.size(); ++i) density[i] = 2.0f * uniform(i, 11);
  std::vector<MediumGrid> grids;
  std::vector<float> values;
  const Medium m =
      addDensityGrid(grids, values, {0.4f, 0.8f, 1.2f}, {0.6f, 0.0f, 0.3f}, nx, ny, nz, density, {0, 0, 0}, {2, 1, 1});
  // The medium's space is the world moved by (1, -0.5, 2) and halved: world = 2 x medium + (1, -0.5, 2).
  grids[0].mediumFromWorld.m[0] = grids[0].mediumFromWorld.m[5] = grids[0].mediumFromWorld.m[10] = 0.5f;
  grids[0].mediumFromWorld.m[3] = -0.5f;
  grids[0].mediumFromWorld.m[7] = 0.25f;
  grids[0].mediumFromWorld.m[11] = -1.0f;
  const Vec3 origin{0.0f, -1.0f, 1.5f}, target{5.0f, 1.5f, 4.5f};
  const Vec3 direction = normalize(target - origin);
  const float length = 8.0f;
  Vec3 tau{};
  constexpr int kSteps = 100'000;
  for (int i = 0; i < kSteps; ++i) {
    const MediumPoint p =
        gridMediumAt(m, grids[0], values.data(), origin + direction * ((float(i) + 0.5f) * length / kSteps));
    tau += (p.sigmaA + p.sigmaS) * (length / kSteps);
  }
  ASSERT_GT(tau.x, 0.3f);  // the ray crosses the box
  const Vec3 expected{std::exp(-tau.x), std::exp(-tau.y), std::exp(-tau.z)};
  const ChannelMeans means = channelMeans(200'000, [&](uint32_t i) {
    const Vec3 o = origin - direction * (float(i) * 1e-6f);
    return gridMediumTransmittance(m, grids[0], values.data(), Ray{o, direction, 0.0f, kInf}, length);
  });
  EXPECT_TRUE(within(means, expected, 5.0f)) << describe(means, expected);
}

// Delta tracking in a grey medium along kRamp: the distance of the first real collision follows the CDF
// 1 - exp(-sigma_t x the density's integral), tested by chi-square over 40 bins of the box and one bin for rays
// that pass; every weight is the albedo (collisions) or 1 (passes), as in classic delta tracking (up to the
// rounding of the null collisions' weights, each 1 to a few ulps). The same test
// rejects the distribution of a density 10% higher.
double distanceChi2PValue(float densityScale) {
  std::vector<MediumGrid> grids;
  std::vector<float> values;
  const Vec3 sigmaA{0.3f, 0.3f, 0.3f}, sigmaS{0.7f, 0.7f, 0.7f};
  const Medium m =
      addDensityGrid(grids, values, sigmaA, sigmaS, uint32_t(kRamp.size()), 1, 1, kRamp, {0, 0, 0}, {1, 1, 1});
  constexpr int kBins = 40;
  constexpr uint32_t kRuns = 200'000;
  std::vector<double> observed(kBins + 1, 0.0);
  for (uint32_t i = 0; i < kRuns; ++i) {
    const Ray ray{{-0.5f, 0.5f, 0.5f}, {1, 0, 0}, 0.0f, kInf};
    const MediumStep step =
        sampleGridMediumDistance(m, grids[0], values.data(), ray, 2.0f, uniform(i, 21), uniform(i, 22));
    if (step.scattered) {
      EXPECT_NEAR(step.weight.x, 0.7f, 1e-3f);
      const int bin = std::clamp(int((step.t - 0.5f) * kBins), 0, kBins - 1);
      observed[size_t(bin)] += 1.0;
    } else {
      EXPECT_NEAR(step.weight.x, 1.0f, 1e-3f);
      observed[kBins] += 1.0;
    }
  }
  auto survive = [&](double x) { return std::exp(-1.0 * densityScale * densityIntegral(kRamp, x)); };
  double chi2 = 0.0;
  int cells = 0;
  for (int b = 0; b <= kBins; ++b) {
    const double p = b < kBins ? survive(double(b) / kBins) - survive(double(b + 1) / kBins) : survive(1.0);
    const double expected = p * kRuns;
    if (expected < 5.0) continue;
    chi2 += (observed[size_t(b)] - expected) * (observed[size_t(b)] - expected) / expected;
    ++cells;
  }
  return upperIncompleteGammaQ(0.5 * (cells - 1), 0.5 * chi2);
}

TEST(GridTracking, DeltaTrackingDistancesFollowTheDensity) {
  EXPECT_GT(distanceChi2PValue(1.0f), 0.001);
  EXPECT_LT(distanceChi2PValue(1.1f), 1e-6);
}

// Delta tracking's weights per channel where the channels' sigma_t differ (spectral MIS at every tentative
// collision): passing the box averages to each channel's transmittance, and a real collision's weight over
// sigma_s(t) to the integral of the transmittance, as the homogeneous medium's (media_sampling_test.cpp).
TEST(GridTracking, DeltaTrackingIsUnbiasedPerChannel) {
  std::vector<MediumGrid> grids;
  std::vector<float> values;
  const Vec3 sigmaA{0.1f, 0.6f, 1.5f}, sigmaS{0.4f, 1.0f, 0.5f};
  const Medium m =
      addDensityGrid(grids, values, sigmaA, sigmaS, uint32_t(kRamp.size()), 1, 1, kRamp, {0, 0, 0}, {1, 1, 1});
  const Vec3 sigmaT = sigmaA + sigmaS;
  const Ray ray{{0.0f, 0.5f, 0.5f}, {1, 0, 0}, 0.0f, kInf};
  constexpr uint32_t kRuns = 400'000;
  std::vector<MediumStep> steps(kRuns);
  for (uint32_t i = 0; i < kRuns; ++i)
    steps[i] = sampleGridMediumDistance(m, grids[0], values.data(), ray, 1.0f, uniform(i, 31), uniform(i, 32));
  const double tau = densityIntegral(kRamp, 1.0);
  const Vec3 transmittance{float(std::exp(-sigmaT.x * tau)), float(std::exp(-sigmaT.y * tau)),
                           float(std::exp(-sigmaT.z * tau))};
  const ChannelMeans pass =
      channelMeans(kRuns, [&](uint32_t i) { return steps[i].scattered ? Vec3{} : steps[i].weight; });
  EXPECT_TRUE(within(pass, transmittance, 5.0f)) << describe(pass, transmittance);
  // A collision's weight averages T(t) sigma_s(t) integrated against whatever it multiplies; over the constant
  // sigmaS (sigma_s(t) = sigmaS x density(t)) it estimates the integral of T(t) density(t), which is
  // (1 - T(1)) / sigma_t per channel.
  const ChannelMeans collide = channelMeans(kRuns, [&](uint32_t i) {
    return steps[i].scattered
               ? Vec3{steps[i].weight.x / sigmaS.x, steps[i].weight.y / sigmaS.y, steps[i].weight.z / sigmaS.z}
               : Vec3{};
  });
  const Vec3 integral{(1.0f - transmittance.x) / sigmaT.x, (1.0f - transmittance.y) / sigmaT.y,
                      (1.0f - transmittance.z) / sigmaT.z};
  EXPECT_TRUE(within(collide, integral, 5.0f)) << describe(collide, integral);
}

}  // namespace
}  // namespace candela::test
