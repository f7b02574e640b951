#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kernel/environment.h"
#include "scene/environment_distribution.h"
#include "support/chi2.h"

namespace candela {
namespace {

using test::Chi2Options;
using test::chi2TestSphere;

constexpr int kChi2Tests = 4;

// A small sky: a gradient from the horizon up, a bright sun, and a black band, so that the distribution has
// smooth parts, a sharp peak and holes.
std::vector<Vec3> skyTexels(uint32_t w, uint32_t h) {
  std::vector<Vec3> t(size_t(w) * h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      Vec3 c = Vec3{0.3f, 0.5f, 1.0f} * (0.2f + float(y) / float(h));
      if (x >= 40 && x < 43 && y >= 8 && y < 10) c = {200.0f, 180.0f, 150.0f};
      if (y >= 20 && y < 23) c = {0, 0, 0};
      t[size_t(y) * w + x] = c;
    }
  return t;
}

struct MapFixture {
  uint32_t width = 64, height = 32;
  std::vector<Vec3> texels;
  EnvironmentDistribution distribution;
  EnvironmentView view;

  MapFixture(float rotationDegrees, std::vector<Vec3> samplingTexels = {}) : texels(skyTexels(width, height)) {
    distribution = EnvironmentDistribution::build(samplingTexels.empty() ? texels : samplingTexels, width, height);
    view.scale = {1, 1, 1};
    view.texels = texels.data();
    view.width = width;
    view.height = height;
    view.rotationCos = std::cos(rotationDegrees * kPi / 180.0f);
    view.rotationSin = std::sin(rotationDegrees * kPi / 180.0f);
    distribution.attach(view);
  }

  test::Chi2Result chi2(const EnvironmentView& pdfView) const {
    Chi2Options options;
    options.testCount = kChi2Tests;
    return chi2TestSphere(
        [&](double u1, double u2, double) -> std::optional<Vec3> {
          EnvironmentSample s = sampleEnvironment(view, {float(u1), float(u2)});
          if (!(s.pdf > 0.0f)) return std::nullopt;
          return s.direction;
        },
        [&](Vec3 d) { return double(environmentDirectionPdf(pdfView, d)); }, options);
  }
};

TEST(EnvironmentSampling, MapSamplerMatchesItsPdf) {
  MapFixture f(0.0f);
  auto r = f.chi2(f.view);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NEAR(r.integral, 1.0, 2e-3);
}

TEST(EnvironmentSampling, RotatedMapSamplerMatchesItsPdf) {
  MapFixture f(117.0f);
  auto r = f.chi2(f.view);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NEAR(r.integral, 1.0, 2e-3);
}

// Building the distribution without the sin(theta) factor (here: from texels divided by it, which the builder
// then multiplies back to plain luminance) over-samples the poles; the test must notice.
TEST(EnvironmentSampling, Chi2RejectsADistributionWithoutSinTheta) {
  std::vector<Vec3> texels = skyTexels(64, 32);
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 64; ++x)
      texels[y * 64 + x] = texels[y * 64 + x] / std::sin(kPi * (float(y) + 0.5f) / 32.0f);
  MapFixture broken(0.0f, texels);
  MapFixture right(0.0f);
  auto r = broken.chi2(right.view);
  EXPECT_FALSE(r.passed) << r.message;
}

TEST(EnvironmentSampling, ConstantEnvironmentSamplesTheSphereUniformly) {
  EnvironmentView constant;
  constant.scale = {1, 1, 1};
  Chi2Options options;
  options.testCount = kChi2Tests;
  auto r = chi2TestSphere(
      [&](double u1, double u2, double) -> std::optional<Vec3> {
        return sampleEnvironment(constant, {float(u1), float(u2)}).direction;
      },
      [&](Vec3 d) { return double(environmentDirectionPdf(constant, d)); }, options);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_FLOAT_EQ(environmentRadiance(constant, {0, 1, 0}).x, 1.0f);
}

TEST(EnvironmentSampling, DirectionsAndMapCoordinatesRoundTrip) {
  MapFixture f(33.0f);
  for (float u : {0.01f, 0.25f, 0.5f, 0.8f, 0.99f})
    for (float v : {0.02f, 0.3f, 0.5f, 0.97f}) {
      Vec2 back = environmentUv(f.view, environmentDirection(f.view, {u, v}));
      EXPECT_NEAR(back.x, u, 1e-4f);
      EXPECT_NEAR(back.y, v, 1e-4f);
    }
}

// The middle of the map is what a camera looking down -Z sees; the top row is the zenith; rotating the map by
// +90 degrees about +Y brings its middle to -X.
TEST(EnvironmentSampling, MapOrientation) {
  MapFixture f(0.0f);
  Vec2 ahead = environmentUv(f.view, {0, 0, -1});
  EXPECT_NEAR(ahead.x, 0.5f, 1e-6f);
  EXPECT_NEAR(ahead.y, 0.5f, 1e-6f);
  EXPECT_NEAR(environmentUv(f.view, {1, 0, 0}).x, 0.75f, 1e-6f);
  EXPECT_NEAR(environmentUv(f.view, {0, 1, 0}).y, 0.0f, 1e-6f);
  MapFixture turned(90.0f);
  Vec2 left = environmentUv(turned.view, {-1, 0, 0});
  EXPECT_NEAR(left.x, 0.5f, 1e-5f);
}

// A map of one row of n texels whose row cdf has steps, flat runs (empty buckets) and a smooth stretch, as maps with
// black regions and bright suns give them: its conditionalCdf and conditionalGuide are one table of n buckets.
EnvironmentDistribution unevenRow(uint32_t n, uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Vec3> texels(n);
  for (Vec3& t : texels) {
    const float pick = unit(random);
    const float grey = pick < 0.3f ? 0.0f : (pick < 0.35f ? 1000.0f * unit(random) : unit(random));
    t = {grey, grey, grey};
  }
  return EnvironmentDistribution::build(texels, n, 1);
}

TEST(EnvironmentSampling, GuidedSearchFindsTheBucketsOfThePlainSearch) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (uint32_t n : {1u, 2u, 3u, 17u, 512u, 1024u}) {
    for (uint32_t seed = 0; seed < 4; ++seed) {
      const EnvironmentDistribution row = unevenRow(n, seed);
      const std::vector<float>& cdf = row.conditionalCdf;
      const std::vector<uint32_t>& guide = row.conditionalGuide;
      std::vector<float> us = {0.0f, std::nextafter(1.0f, 0.0f)};
      for (uint32_t g = 0; g <= n; ++g) {  // the guide cells' edges and their neighbours
        const float edge = float(g) / float(n);
        us.insert(us.end(), {edge, std::nextafter(edge, 0.0f), std::nextafter(edge, 1.0f)});
      }
      for (float c : cdf) us.insert(us.end(), {c, std::nextafter(c, 0.0f), std::nextafter(c, 1.0f)});
      for (int i = 0; i < 20000; ++i) us.push_back(unit(random));
      for (float u : us) {
        if (!(u >= 0.0f && u < 1.0f)) continue;
        ASSERT_EQ(findGuidedInterval(cdf.data(), guide.data(), int(n), u), findInterval(cdf.data(), int(n), u))
            << "n " << n << " seed " << seed << " u " << u;
      }
    }
  }
}

TEST(EnvironmentSampling, GuidedSearchWidensAWrongGuideToTheWholeTable) {
  const std::vector<float> cdf = unevenRow(64, 3).conditionalCdf;
  for (uint32_t wrong : {0u, 63u}) {
    const std::vector<uint32_t> guide(65, wrong);
    for (float u : {0.0f, 0.1f, 0.37f, 0.5f, 0.93f, 0.9999f})
      EXPECT_EQ(findGuidedInterval(cdf.data(), guide.data(), 64, u), findInterval(cdf.data(), 64, u)) << u;
  }
}

TEST(EnvironmentSampling, BlackMapIsNeverSampled) {
  std::vector<Vec3> black(64 * 32);
  EnvironmentDistribution d = EnvironmentDistribution::build(black, 64, 32);
  EXPECT_EQ(d.funcAverage, 0.0f);
  EnvironmentView view;
  view.texels = black.data();
  view.width = 64;
  view.height = 32;
  d.attach(view);
  EXPECT_EQ(sampleEnvironment(view, {0.3f, 0.6f}).pdf, 0.0f);
  EXPECT_EQ(environmentDirectionPdf(view, {0, 0, 1}), 0.0f);
}

}  // namespace
}  // namespace candela
