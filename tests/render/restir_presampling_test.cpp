// ReSTIR DI's presampled light candidates (kernel/restir/restir_presampling.h): the lights a tile presamples follow
// the density that the candidates' resampling weights and the BSDF candidate's MIS weight divide by, and that density
// is normalised.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "kernel/restir/restir_presampling.h"
#include "scene/flat_scene.h"
#include "support/chi2.h"
#include "support/many_small_lights.h"

namespace candela::test {
namespace {

// Presampled lights for regions of the many-light floor: Pearson's chi-square test of how often each light is picked
// against presampledLightPdf (times the triangle's area: the choice of the light), lights expecting fewer than 5
// picks pooled; the stored density is the one presampledLightPdf gives, and the choices' probabilities sum to 1.
TEST(RestirPresampling, PresampledLightsFollowTheirDensity) {
  const FlatScene flat = FlatScene::build(makeManySmallLights(300, 5));
  const SceneView view = flat.hostView();
  ASSERT_EQ(view.lightCount, 600u);
  const LightSampleContext regions[] = {{{0, 0, 0}, {0, 0, 0}, 0.0f},
                                        {{-4, 0, 3}, {0, 0, 0}, 1.5f},
                                        {{6, 1, -2}, {0, 0, 0}, 5.0f}};
  const int kSamples = 400000;
  for (LightSamplerKind kind : {LightSamplerKind::Bvh, LightSamplerKind::Power})
    for (const LightSampleContext& region : regions) {
      std::vector<double> expected(view.lightCount), observed(view.lightCount, 0.0);
      double sum = 0.0;
      for (uint32_t i = 0; i < view.lightCount; ++i) {
        const double choice = double(presampledLightPdf(view, kind, region, i)) * view.lights[i].area;
        sum += choice;
        expected[i] = choice * kSamples;
      }
      EXPECT_NEAR(sum, 1.0, 1e-4);
      std::mt19937 rng(7);
      std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
      for (int s = 0; s < kSamples; ++s) {
        const float u = uniform(rng);
        const PresampledLight p = presampleLight(view, kind, region, u, {uniform(rng), uniform(rng)});
        ASSERT_LT(p.light, view.lightCount);
        ASSERT_FLOAT_EQ(p.pdf, presampledLightPdf(view, kind, region, p.light));
        ASSERT_GE(p.barycentrics.x, 0.0f);
        ASSERT_GE(p.barycentrics.y, 0.0f);
        ASSERT_LE(p.barycentrics.x + p.barycentrics.y, 1.0f);
        observed[p.light] += 1.0;
      }
      const DiscreteChi2 chi2 = chi2Discrete(observed, expected);
      ASSERT_GT(chi2.cells, 100);
      EXPECT_GT(chi2.pValue, 1.0 - std::pow(1.0 - 0.01, 1.0 / 6.0))
          << "chi2 " << chi2.statistic << " over " << chi2.cells << " cells";
    }
}

// A tile's region holds every point its pixels light through ReSTIR, and nothing where none does.
TEST(RestirPresampling, TileRegionHoldsItsPixelsPoints) {
  RenderSettings settings;
  settings.width = 19;  // tiles of 8, 8 and 3 columns
  settings.height = 10;
  std::vector<PrimarySurface> surfaces(size_t(settings.width) * settings.height);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> coordinate(-50.0f, 50.0f);
  for (size_t i = 0; i < surfaces.size(); ++i) {
    if (i % 7 == 3) continue;  // not lit by ReSTIR
    surfaces[i].normal = {0, 1, 0};
    surfaces[i].position = {coordinate(rng), coordinate(rng), coordinate(rng)};
  }
  RestirView restir;
  restir.surfaces = surfaces.data();
  for (uint32_t y = 0; y < settings.height; ++y)
    for (uint32_t x = 0; x < settings.width; ++x) {
      const PrimarySurface& s = surfaces[y * settings.width + x];
      if (!s.lit()) continue;
      const LightSampleContext region = restirTileRegion(settings, restir, restirTileOf(settings, x, y));
      EXPECT_LE(length(s.position - region.p), region.radius) << x << ", " << y;
    }
  EXPECT_EQ(restirTilePixels(settings, 2), 3u * 8u);
  EXPECT_EQ(restirTilePixels(settings, 5), 3u * 2u);
  EXPECT_EQ(restirIndexInTile(settings, 18, 9), 1u * 3u + 2u);
  std::fill(surfaces.begin(), surfaces.end(), PrimarySurface{});
  EXPECT_LT(restirTileRegion(settings, restir, 0).radius, 0.0f);
}

}  // namespace
}  // namespace candela::test
