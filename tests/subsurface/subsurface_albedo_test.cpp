// The albedo inversion of subsurface materials given as a reflectance and a mean free path: the single-scattering
// albedo it returns makes a half-space reflect the reflectance asked for.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "core/sampling.h"
#include "kernel/media/henyey_greenstein.h"
#include "scene/subsurface_albedo.h"

namespace candela::test {
namespace {

// The total diffuse reflectance of the half-space z < 0 of sigma_t 1 and single-scattering albedo `alpha`, lit
// cosine-distributed through an index-matched boundary: the fraction of `walks` random walks (free flights drawn
// exactly, directions from the kernel's Henyey-Greenstein sampling) that come back out, each weighed by alpha per
// collision, until that weight falls below 1e-4 (a bias below 1e-4). Deterministic: walk i draws from
// randomUniform(i, step, dimension, seed).
double halfSpaceReflectance(float alpha, float g, uint32_t walks, uint32_t seed) {
  double reflected = 0.0;
  for (uint32_t i = 0; i < walks; ++i) {
    Vec3 wi = sampleCosineHemisphere({randomUniform(i, 0, 0, seed), randomUniform(i, 0, 1, seed)});
    Vec3 d = -wi;  // into the medium
    double z = 0.0, weight = 1.0;
    for (uint32_t step = 1; weight > 1e-4; ++step) {
      z += d.z * -std::log(1.0 - double(randomUniform(i, step, 0, seed)));
      if (z >= 0.0) {
        reflected += weight;
        break;
      }
      weight *= alpha;
      d = sampleHenyeyGreenstein(-d, g, {randomUniform(i, step, 1, seed), randomUniform(i, step, 2, seed)}).wi;
    }
  }
  return reflected / walks;
}

// The fit is good to about 0.005 (d'Eon's); 40000 walks add a standard error below 0.0025. Up to a reflectance of
// 0.9: brighter ones take walks of thousands of collisions, too slow for the test.
TEST(SubsurfaceAlbedo, InversionRoundTripsThroughAHalfSpace) {
  constexpr uint32_t kWalks = 40000;
  constexpr double kTolerance = 0.012;
  for (float g : {0.0f, 0.5f, -0.3f})
    for (float albedo : {0.05f, 0.2f, 0.5f, 0.7f, 0.9f}) {
      const float alpha = singleScatteringAlbedo(albedo, g);
      const double measured = halfSpaceReflectance(alpha, g, kWalks, 5);
      EXPECT_NEAR(measured, albedo, kTolerance) << "g " << g << " albedo " << albedo << " alpha " << alpha;
    }
}

TEST(SubsurfaceAlbedo, EndsOfTheRange) {
  EXPECT_NEAR(singleScatteringAlbedo(0.0f, 0.0f), 0.0f, 1e-5f);
  EXPECT_LT(singleScatteringAlbedo(1.0f, 0.0f), 1.0f);  // a walk must lose something, or never end
  EXPECT_GT(singleScatteringAlbedo(1.0f, 0.0f), 0.9999f);
  EXPECT_EQ(singleScatteringAlbedo(-1.0f, 0.0f), singleScatteringAlbedo(0.0f, 0.0f));  // out of range: clamped
  EXPECT_EQ(singleScatteringAlbedo(2.0f, 0.0f), singleScatteringAlbedo(1.0f, 0.0f));
  for (float a = 0.0f; a < 1.0f; a += 0.05f)  // monotonic: more reflectance needs more scattering
    EXPECT_LT(singleScatteringAlbedo(a, 0.3f), singleScatteringAlbedo(a + 0.05f, 0.3f) + 1e-7f) << a;
}

TEST(SubsurfaceAlbedo, MediumFromReflectanceHasTheMeanFreePath) {
  const Medium m = subsurfaceMediumFromReflectance({0.8f, 0.5f, 0.2f}, {1.0f, 0.5f, 0.25f}, 0.2f);
  const Vec3 sigmaT = mediumSigmaT(m);
  EXPECT_NEAR(sigmaT.x, 1.0f, 1e-5f);
  EXPECT_NEAR(sigmaT.y, 2.0f, 1e-5f);
  EXPECT_NEAR(sigmaT.z, 4.0f, 1e-5f);
  EXPECT_NEAR(m.sigmaS.y / sigmaT.y, singleScatteringAlbedo(0.5f, 0.2f), 1e-6f);
  EXPECT_GE(m.sigmaA.x, 0.0f);
  EXPECT_EQ(m.g, 0.2f);
}

}  // namespace
}  // namespace candela::test
