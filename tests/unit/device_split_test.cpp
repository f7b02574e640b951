// How the devices of one process share a render() call (backends/multi/device_split.h).
#include "backends/multi/device_split.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace candela {
namespace {

uint32_t sum(const std::vector<uint32_t>& parts) { return std::accumulate(parts.begin(), parts.end(), 0u); }

TEST(SplitProportionally, EqualWeightsGiveEqualPartsTheRemainderToTheFirst) {
  EXPECT_EQ(splitProportionally(10, {1, 1}, 0), (std::vector<uint32_t>{5, 5}));
  EXPECT_EQ(splitProportionally(11, {1, 1}, 0), (std::vector<uint32_t>{6, 5}));
  EXPECT_EQ(splitProportionally(1080, {1, 1, 1, 1, 1, 1, 1}, 1),
            (std::vector<uint32_t>{155, 155, 154, 154, 154, 154, 154}));
}

TEST(SplitProportionally, PartsFollowTheWeightsAndAlwaysSumToTheTotal) {
  EXPECT_EQ(splitProportionally(4, {1, 3}, 1), (std::vector<uint32_t>{1, 3}));
  EXPECT_EQ(splitProportionally(100, {0.2, 0.3, 0.5}, 0), (std::vector<uint32_t>{20, 30, 50}));
  for (uint32_t total : {0u, 1u, 2u, 7u, 719u, 1080u, 4096u})
    for (const std::vector<double>& w : {std::vector<double>{1}, {0.1, 0.9}, {3, 1, 1e-9}, {0.333, 0.333, 0.334}})
      EXPECT_EQ(sum(splitProportionally(total, w, 1)), total) << total;
}

TEST(SplitProportionally, EveryPartGetsTheMinimumWhereTheTotalAllows) {
  EXPECT_EQ(splitProportionally(1080, {1.0, 1e-12}, 1), (std::vector<uint32_t>{1079, 1}));
  EXPECT_EQ(splitProportionally(3, {100, 1, 1}, 1), (std::vector<uint32_t>{1, 1, 1}));
  // Not enough for all: proportional alone.
  EXPECT_EQ(splitProportionally(1, {1, 1, 1}, 1), (std::vector<uint32_t>{1, 0, 0}));
}

TEST(SplitProportionally, UnusableWeightsCountAsTheSmallestUsableOne) {
  EXPECT_EQ(splitProportionally(9, {2, 1, 0}, 0), (std::vector<uint32_t>{5, 2, 2}));
  EXPECT_EQ(splitProportionally(9, {2, NAN, 1}, 0), (std::vector<uint32_t>{5, 2, 2}));
  EXPECT_EQ(splitProportionally(9, {-1, INFINITY, 0}, 0), (std::vector<uint32_t>{3, 3, 3}));
  EXPECT_TRUE(splitProportionally(9, {}, 0).empty());
}

// Contiguous, disjoint, covering: every (row, sample index) of the call is rendered by exactly one device.
void expectCovers(const std::vector<DeviceShare>& shares, uint32_t samplesPerPixel, uint32_t height) {
  std::vector<int> covered(size_t(samplesPerPixel) * height, 0);
  for (const DeviceShare& s : shares)
    for (uint32_t row = s.firstRow; row < s.firstRow + s.rows; ++row)
      for (uint32_t sample = s.firstSample; sample < s.firstSample + s.samples; ++sample) {
        ASSERT_LT(row, height);
        ASSERT_LT(sample, samplesPerPixel);
        ++covered[size_t(row) * samplesPerPixel + sample];
      }
  for (int c : covered) ASSERT_EQ(c, 1);
}

// planShares(samplesPerPixel, height, weights) gives `expected`, share for share, and covers the call.
void expectPlan(uint32_t samplesPerPixel, uint32_t height, const std::vector<double>& weights,
                const std::vector<DeviceShare>& expected) {
  const std::vector<DeviceShare> shares = planShares(samplesPerPixel, height, weights);
  ASSERT_EQ(shares.size(), expected.size());
  for (size_t d = 0; d < shares.size(); ++d) {
    EXPECT_EQ(shares[d].firstRow, expected[d].firstRow) << "device " << d;
    EXPECT_EQ(shares[d].rows, expected[d].rows) << "device " << d;
    EXPECT_EQ(shares[d].firstSample, expected[d].firstSample) << "device " << d;
    EXPECT_EQ(shares[d].samples, expected[d].samples) << "device " << d;
  }
  expectCovers(shares, samplesPerPixel, height);
}

TEST(PlanShares, ACallOfAtLeastOneSamplePerDeviceSplitsTheSampleIndices) {
  expectPlan(16, 720, {0.25, 0.75},
             {{.firstRow = 0, .rows = 720, .firstSample = 0, .samples = 4},
              {.firstRow = 0, .rows = 720, .firstSample = 4, .samples = 12}});
  // Two samples on two devices: one each, whatever the weights.
  const std::vector<DeviceShare> two = planShares(2, 8, {0.99, 0.01});
  EXPECT_EQ(two[0].samples, 1u);
  EXPECT_EQ(two[1].samples, 1u);
}

TEST(PlanShares, AFrameOfFewerSamplesThanDevicesSplitsTheRowsIntoBands) {
  expectPlan(1, 1080, {0.5, 0.5},
             {{.firstRow = 0, .rows = 540, .firstSample = 0, .samples = 1},
              {.firstRow = 540, .rows = 540, .firstSample = 0, .samples = 1}});
  expectCovers(planShares(3, 97, {0.1, 0.2, 0.3, 0.4}), 3, 97);
}

TEST(PlanShares, AnImageOfFewerRowsThanDevicesLeavesSomeIdle) {
  const std::vector<DeviceShare> shares = planShares(1, 2, {1, 1, 1});
  expectCovers(shares, 1, 2);
  EXPECT_TRUE(shares[2].empty());
}

TEST(DeviceBalance, StartsEqualAndLearnsTheSpeedsHalfwayPerCall) {
  DeviceBalance balance(2);
  EXPECT_EQ(balance.weights(), (std::vector<double>{0.5, 0.5}));
  // Equal bands, the second device three times as fast: halfway from 1/2 to 1/4 and 3/4.
  balance.record(planShares(1, 100, balance.weights()), 10, {3.0, 1.0});
  EXPECT_DOUBLE_EQ(balance.weights()[0], 0.375);
  EXPECT_DOUBLE_EQ(balance.weights()[1], 0.625);
}

TEST(DeviceBalance, DevicesWithoutWorkOrTimeKeepTheirWeight) {
  DeviceBalance balance(3);
  std::vector<DeviceShare> shares = planShares(1, 100, balance.weights());
  shares[2].rows = 0;
  balance.record(shares, 10, {1.0, 2.0, 5.0});
  EXPECT_DOUBLE_EQ(balance.weights()[2], 1.0 / 3.0);
  balance.record(planShares(1, 100, balance.weights()), 10, {0.0, NAN, -1.0});
  EXPECT_DOUBLE_EQ(balance.weights()[0] + balance.weights()[1] + balance.weights()[2], 1.0);
  EXPECT_GT(balance.weights()[0], balance.weights()[1]);
}

// A frame whose rows cost unevenly (sky above, geometry below) on devices of unequal speed: rebalancing from the
// last frame's times brings the devices' times within a few percent of each other.
TEST(DeviceBalance, BandsOfUnevenCostConvergeToEqualTimes) {
  constexpr uint32_t kHeight = 1080;
  auto rowCost = [](uint32_t row) { return row < kHeight / 3 ? 0.2 : 1.0 + double(row) / kHeight; };
  const std::vector<double> speed = {1.0, 1.6, 0.7};
  DeviceBalance balance(speed.size());
  std::vector<double> ms;
  for (int frame = 0; frame < 30; ++frame) {
    const std::vector<DeviceShare> shares = planShares(1, kHeight, balance.weights());
    ms.assign(shares.size(), 0.0);
    for (size_t d = 0; d < shares.size(); ++d)
      for (uint32_t row = shares[d].firstRow; row < shares[d].firstRow + shares[d].rows; ++row)
        ms[d] += rowCost(row) / speed[d];
    balance.record(shares, 1920, ms);
  }
  const double slowest = *std::max_element(ms.begin(), ms.end()), fastest = *std::min_element(ms.begin(), ms.end());
  EXPECT_LT(slowest / fastest, 1.03) << ms[0] << " " << ms[1] << " " << ms[2];
}

}  // namespace
}  // namespace candela
