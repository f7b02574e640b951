#pragma once
// How a render() call is shared between the devices of one process (optix/multi_gpu_backend.h), and how the
// shares follow the devices' speeds: pure functions, so that they are tested without a GPU.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace candela {

// What one device renders of one render() call: in every pixel of the rows [firstRow, firstRow + rows), the
// call's sample indices [firstSample, firstSample + samples), counted from the call's first one.
struct DeviceShare {
  uint32_t firstRow = 0, rows = 0;
  uint32_t firstSample = 0, samples = 0;

  bool empty() const { return rows == 0 || samples == 0; }
  uint64_t pixelSamples(uint32_t width) const { return uint64_t(width) * rows * samples; }
};

// `total` split into one part per weight, in proportion to the weights (largest remainders, ties to the earlier
// part), every part at least `minimum` where `total` allows it for all. Non-positive or non-finite weights count
// as the smallest positive one; all of them so: equal parts.
std::vector<uint32_t> splitProportionally(uint32_t total, const std::vector<double>& weights, uint32_t minimum);

// The shares of one call of `samplesPerPixel` over an image of `height` rows on devices of relative speeds
// `weights`. A call of at least one sample per device splits its sample indices (every device renders every
// row: progressive renders); a smaller one, the interactive frame of one sample, splits the rows into bands,
// top to bottom in device order. Either way each device gets a part in proportion to its weight and, where
// there is enough, at least one sample or row, so that its speed is measured again.
std::vector<DeviceShare> planShares(uint32_t samplesPerPixel, uint32_t height, const std::vector<double>& weights);

// The devices' relative speeds, learnt call after call from the pixel samples each rendered and the time it
// took; equal until measured. Half of each update comes from the new measurement: a band of rows that is
// cheap in one frame and dear in the next (sky, then geometry) moves the split halfway, not back and forth.
class DeviceBalance {
 public:
  explicit DeviceBalance(size_t devices);
  const std::vector<double>& weights() const { return weights_; }
  // The shares of the last call over an image `width` pixels wide, and each device's time for its share in
  // milliseconds. Devices without work or without a positive time keep their weight.
  void record(const std::vector<DeviceShare>& shares, uint32_t width, const std::vector<double>& milliseconds);

 private:
  std::vector<double> weights_;  // they sum to 1
};

}  // namespace candela
