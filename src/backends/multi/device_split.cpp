#include "backends/multi/device_split.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela {

namespace {

std::vector<double> usableWeights(const std::vector<double>& weights) {
  double smallest = std::numeric_limits<double>::infinity();
  for (double w : weights)
    if (std::isfinite(w) && w > 0.0) smallest = std::min(smallest, w);
  if (!std::isfinite(smallest)) smallest = 1.0;
  std::vector<double> usable(weights);
  for (double& w : usable)
    if (!std::isfinite(w) || w <= 0.0) w = smallest;
  return usable;
}

}  // namespace

std::vector<uint32_t> splitProportionally(uint32_t total, const std::vector<double>& weights, uint32_t minimum) {
  const size_t n = weights.size();
  std::vector<uint32_t> parts(n, 0);
  if (n == 0) return parts;
  const std::vector<double> w = usableWeights(weights);
  double sum = 0.0;
  for (double x : w) sum += x;
  std::vector<double> remainders(n);
  uint64_t given = 0;
  for (size_t i = 0; i < n; ++i) {
    const double ideal = double(total) * w[i] / sum;
    parts[i] = uint32_t(std::min(std::floor(ideal), double(total)));
    remainders[i] = ideal - double(parts[i]);
    given += parts[i];
  }
  // Rounding down leaves fewer than n over; the largest remainders take them.
  while (given < total) {
    size_t best = 0;
    for (size_t i = 1; i < n; ++i)
      if (remainders[i] > remainders[best]) best = i;
    ++parts[best];
    remainders[best] = -1.0;
    ++given;
  }
  while (given > total) {  // only where floating-point rounding overshot
    const size_t largest = size_t(std::max_element(parts.begin(), parts.end()) - parts.begin());
    --parts[largest];
    --given;
  }
  if (uint64_t(minimum) * n > total) return parts;
  // Parts under the minimum take from the largest part, which stays above it.
  for (size_t i = 0; i < n; ++i)
    while (parts[i] < minimum) {
      const size_t largest = size_t(std::max_element(parts.begin(), parts.end()) - parts.begin());
      --parts[largest];
      ++parts[i];
    }
  return parts;
}

std::vector<DeviceShare> planShares(uint32_t samplesPerPixel, uint32_t height, const std::vector<double>& weights) {
  std::vector<DeviceShare> shares(weights.size());
  if (shares.empty()) return shares;
  const bool splitSamples = samplesPerPixel >= shares.size();
  const std::vector<uint32_t> parts = splitProportionally(splitSamples ? samplesPerPixel : height, weights, 1);
  uint32_t start = 0;
  for (size_t i = 0; i < shares.size(); ++i) {
    DeviceShare& s = shares[i];
    if (splitSamples)
      s = {0, height, start, parts[i]};
    else
      s = {start, parts[i], 0, samplesPerPixel};
    start += parts[i];
  }
  return shares;
}

DeviceBalance::DeviceBalance(size_t devices) : weights_(devices, devices > 0 ? 1.0 / double(devices) : 0.0) {}

void DeviceBalance::record(const std::vector<DeviceShare>& shares, uint32_t width,
                           const std::vector<double>& milliseconds) {
  const size_t n = std::min({weights_.size(), shares.size(), milliseconds.size()});
  std::vector<double> speeds(n, 0.0);
  double measuredWeight = 0.0, speedSum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double ms = milliseconds[i];
    if (shares[i].empty() || !std::isfinite(ms) || ms <= 0.0) continue;
    speeds[i] = double(shares[i].pixelSamples(width)) / ms;
    measuredWeight += weights_[i];
    speedSum += speeds[i];
  }
  if (speedSum <= 0.0) return;
  // The measured devices share their current total weight by speed: the unmeasured keep theirs.
  for (size_t i = 0; i < n; ++i)
    if (speeds[i] > 0.0) weights_[i] = 0.5 * weights_[i] + 0.5 * measuredWeight * speeds[i] / speedSum;
}

}  // namespace candela
