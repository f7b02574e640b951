#pragma once
// Images as separate float planes per channel, the layout the CPU filters' row loops vectorise over.
#include <algorithm>
#include <memory>
#include <vector>

#include "image/image.h"

namespace candela {

// Planes of one size in one allocation, each starting at another offset within a 4 KiB page. Large planes allocated one
// by one all start at the same page offset, and a loop that reads the same pixel of many of them then keeps evicting
// its own data from the few L1 cache sets those addresses share.
// The planes start uninitialised: the filters write every pixel before they read it.
class PlaneStack {
 public:
  PlaneStack(size_t count, size_t pixels)
      : stride_((pixels + kPageFloats - 1) / kPageFloats * kPageFloats + kStaggerFloats),
        data_(new float[count * stride_]) {}
  float* operator[](size_t plane) { return data_.get() + plane * stride_; }
  const float* operator[](size_t plane) const { return data_.get() + plane * stride_; }

 private:
  static constexpr size_t kPageFloats = 1024;
  static constexpr size_t kStaggerFloats = 64;  // 256 bytes: 16 planes, 16 offsets
  size_t stride_;
  std::unique_ptr<float[]> data_;
};

// The red, green and blue planes of an image.
struct RgbPlanes {
  float *r, *g, *b;
  void set(size_t i, Vec3 c) const {
    r[i] = c.x;
    g[i] = c.y;
    b[i] = c.z;
  }
  Vec3 get(size_t i) const { return {r[i], g[i], b[i]}; }
};

// Per-row sums of weighted colour and of the weights.
struct RowSums {
  std::vector<float> r, g, b, weight;
  explicit RowSums(uint32_t width) : r(width), g(width), b(width), weight(width) {}
  void clear() {
    std::fill(r.begin(), r.end(), 0.0f);
    std::fill(g.begin(), g.end(), 0.0f);
    std::fill(b.begin(), b.end(), 0.0f);
    std::fill(weight.begin(), weight.end(), 0.0f);
  }
};

}  // namespace candela
