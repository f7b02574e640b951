#include "image/filters/bilateral.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace candela {

Image bilateralFilter(const Image& input, const BilateralParams& params) {
  if (params.radius < 0 || params.radius > kMaxBilateralRadius)
    throw std::invalid_argument("bilateral radius must lie in [0, " + std::to_string(kMaxBilateralRadius) + "]");
  if (!(params.spatialSigma > 0.0f) || !(params.rangeSigma > 0.0f))
    throw std::invalid_argument("bilateral sigmas must be positive");

  const float spatialScale = 1.0f / (2.0f * params.spatialSigma * params.spatialSigma);
  const float rangeScale = 1.0f / (2.0f * params.rangeSigma * params.rangeSigma);
  const int r = params.radius, w = int(input.width), h = int(input.height);
  Image output(input.width, input.height);
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < w; ++x) {
        const Vec3 centre = input.at(uint32_t(x), uint32_t(y));
        Vec3 sum{};
        float weightSum = 0.0f;
        for (int dy = -r; dy <= r; ++dy) {
          if (y + dy < 0 || y + dy >= h) continue;
          for (int dx = -r; dx <= r; ++dx) {
            if (x + dx < 0 || x + dx >= w) continue;
            const Vec3 c = input.at(uint32_t(x + dx), uint32_t(y + dy));
            const Vec3 d = c - centre;
            const float weight = std::exp(-float(dx * dx + dy * dy) * spatialScale - dot(d, d) * rangeScale);
            sum += c * weight;
            weightSum += weight;
          }
        }
        output.at(uint32_t(x), uint32_t(y)) = sum / weightSum;
      }
  });
  return output;
}

}  // namespace candela
