#pragma once
#include <vector>

#include "kernel/environment.h"
#include "scene/scene.h"

namespace candela {

// The piecewise-constant 2D distribution kernel/environment.h samples an equirectangular map with: density over
// (u, v) proportional to luminance * sin(theta) of each texel, so that directions are drawn in proportion to
// the light they carry (the sin(theta) undoes the stretching of the map towards the poles).
struct EnvironmentDistribution {
  std::vector<float> func;            // width * height
  std::vector<float> conditionalCdf;  // height rows of width + 1 entries, each from 0 to 1
  std::vector<float> marginalCdf;     // height + 1 entries, from 0 to 1
  // Guide tables of the cdfs, entry for entry (findGuidedInterval, core/sampling.h)
  std::vector<uint32_t> conditionalGuide;
  std::vector<uint32_t> marginalGuide;
  float funcAverage = 0.0f;  // 0 when the map is black

  // `texels`: width * height linear RGB values, top row first.
  static EnvironmentDistribution build(const std::vector<Vec3>& texels, uint32_t width, uint32_t height);

  // Points `view`'s sampling tables (and funcAverage) at this distribution's.
  void attach(EnvironmentView& view) const;
};

// The RGB texels of an environment map (first three channels of a float texture).
std::vector<Vec3> environmentTexels(const Texture& map);

}  // namespace candela
