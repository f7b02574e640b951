#include "scene/subsurface_albedo.h"

#include <algorithm>
#include <cmath>

namespace candela {

float singleScatteringAlbedo(float albedo, float g) {
  const double a = std::clamp(double(albedo), 0.0, 1.0);
  const double s = 4.20863 * a - std::sqrt(9.59217 + 41.6808 * a + 17.7126 * a * a) + 4.09712;
  const double s2 = s * s;
  // Above 0.999999 the walk would take millions of steps to lose what little it absorbs.
  return float(std::clamp((1.0 - s2) / (1.0 - double(g) * s2), 0.0, 0.999999));
}

Medium subsurfaceMediumFromReflectance(Vec3 reflectance, Vec3 meanFreePath, float g) {
  auto channel = [&](float r, float mfp, float& sigmaA, float& sigmaS) {
    const float sigmaT = 1.0f / mfp;
    sigmaS = singleScatteringAlbedo(r, g) * sigmaT;
    sigmaA = sigmaT - sigmaS;
  };
  Medium m;
  channel(reflectance.x, meanFreePath.x, m.sigmaA.x, m.sigmaS.x);
  channel(reflectance.y, meanFreePath.y, m.sigmaA.y, m.sigmaS.y);
  channel(reflectance.z, meanFreePath.z, m.sigmaA.z, m.sigmaS.z);
  m.g = g;
  return m;
}

}  // namespace candela
