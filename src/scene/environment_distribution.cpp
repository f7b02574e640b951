#include "scene/environment_distribution.h"

#include <cmath>
#include <stdexcept>

namespace candela {

namespace {

// Fills cdf (n + 1 entries) from n non-negative values; returns their mean. A row without energy gets a uniform
// cdf so that every entry stays well defined, although such a row is never chosen.
double buildCdf(const float* values, uint32_t n, float* cdf) {
  double sum = 0.0;
  cdf[0] = 0.0f;
  for (uint32_t i = 0; i < n; ++i) sum += values[i];
  double running = 0.0;
  for (uint32_t i = 0; i < n; ++i) {
    running += values[i];
    cdf[i + 1] = sum > 0.0 ? float(running / sum) : float(double(i + 1) / n);
  }
  cdf[n] = 1.0f;
  return sum / n;
}

// Fills guide (n + 1 entries) for cdf (n + 1 entries): guide[g] is the bucket of g / n, guide[n] = n - 1
// (findGuidedInterval, core/sampling.h).
void buildIntervalGuide(const float* cdf, uint32_t n, uint32_t* guide) {
  uint32_t bucket = 0;
  for (uint32_t g = 0; g < n; ++g) {
    const float u = float(g) / float(n);
    while (bucket + 1 < n && cdf[bucket + 1] <= u) ++bucket;
    guide[g] = bucket;
  }
  guide[n] = n - 1;
}

}  // namespace

EnvironmentDistribution EnvironmentDistribution::build(const std::vector<Vec3>& texels, uint32_t width,
                                                       uint32_t height) {
  if (width == 0 || height == 0 || texels.size() != size_t(width) * height)
    throw std::invalid_argument("environment distribution: texel count does not match the size");
  EnvironmentDistribution d;
  d.func.resize(texels.size());
  d.conditionalCdf.resize(size_t(height) * (width + 1));
  d.marginalCdf.resize(height + 1);
  d.conditionalGuide.resize(d.conditionalCdf.size());
  d.marginalGuide.resize(d.marginalCdf.size());
  std::vector<float> rowAverages(height);
  for (uint32_t row = 0; row < height; ++row) {
    float sinTheta = std::sin(kPi * (float(row) + 0.5f) / float(height));
    for (uint32_t col = 0; col < width; ++col) {
      float l = luminance(texels[size_t(row) * width + col]);
      d.func[size_t(row) * width + col] = std::isfinite(l) && l > 0.0f ? l * sinTheta : 0.0f;
    }
    const size_t rowStart = size_t(row) * (width + 1);
    rowAverages[row] = float(buildCdf(&d.func[size_t(row) * width], width, &d.conditionalCdf[rowStart]));
    buildIntervalGuide(&d.conditionalCdf[rowStart], width, &d.conditionalGuide[rowStart]);
  }
  d.funcAverage = float(buildCdf(rowAverages.data(), height, d.marginalCdf.data()));
  buildIntervalGuide(d.marginalCdf.data(), height, d.marginalGuide.data());
  return d;
}

void EnvironmentDistribution::attach(EnvironmentView& view) const {
  view.func = func.data();
  view.conditionalCdf = conditionalCdf.data();
  view.marginalCdf = marginalCdf.data();
  view.conditionalGuide = conditionalGuide.data();
  view.marginalGuide = marginalGuide.data();
  view.funcAverage = funcAverage;
}

std::vector<Vec3> environmentTexels(const Texture& map) {
  if (map.channels < 3 || map.floats.size() != size_t(map.width) * map.height * map.channels)
    throw std::invalid_argument("environment map '" + map.name + "' is not a float RGB image");
  std::vector<Vec3> texels(size_t(map.width) * map.height);
  for (size_t i = 0; i < texels.size(); ++i) {
    const float* t = &map.floats[i * map.channels];
    texels[i] = {t[0], t[1], t[2]};
  }
  return texels;
}

}  // namespace candela
