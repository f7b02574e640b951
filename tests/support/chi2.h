#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"

namespace candela::test {

// Pearson's chi-square goodness-of-fit test of a sampling routine against its density, following pbrt-v4
// (bsdfs_test.cpp) and Mitsuba 3 (chi2.py): samples are binned on a grid over the unit square, the expected
// count of every cell is the density integrated over it (adaptive Simpson), cells expecting fewer than 5
// samples are pooled, and the statistic's p-value is compared with a significance level corrected for the
// number of tests run (Sidak).
struct Chi2Options {
  int binsX = 40;
  int binsY = 80;
  long long sampleCount = 1'000'000;
  double significance = 0.01;
  int testCount = 1;  // how many chi-square tests the caller runs in total, for the Sidak correction
};

struct Chi2Result {
  bool passed = false;
  double pValue = 0.0;
  double integral = 0.0;  // of the density over the square: 1 for a normalised, non-delta density
  std::string message;
};

// `sample` draws one point of the unit square from two uniform numbers (and a third for lobe choice), or
// nothing when sampling fails; `density` is its density with respect to area on the square.
using SquareSampler = std::function<std::optional<Vec2>(double u1, double u2, double u3)>;
using SquareDensity = std::function<double(double x, double y)>;
Chi2Result chi2TestSquare(const SquareSampler& sample, const SquareDensity& density, const Chi2Options& options);

// The same for directions on the unit sphere, binned over (cos-free) spherical angles theta in [0, pi] and
// phi in [0, 2 pi); `pdf` is with respect to solid angle.
using DirectionSampler = std::function<std::optional<Vec3>(double u1, double u2, double u3)>;
using DirectionPdf = std::function<double(Vec3 direction)>;
Chi2Result chi2TestSphere(const DirectionSampler& sample, const DirectionPdf& pdf, const Chi2Options& options);

// Pearson's statistic of counts in discrete cells (lights, for example) against their expected counts: the cells
// expecting fewer than 5 are pooled into one, which counts as a cell when it expects 5 or more. The p-value is
// for cells - 1 degrees of freedom.
struct DiscreteChi2 {
  double statistic = 0.0;
  int cells = 0;
  double pooledExpected = 0.0, pooledObserved = 0.0;
  double pValue = 1.0;
};
DiscreteChi2 chi2Discrete(const std::vector<double>& observed, const std::vector<double>& expected);

// Regularised upper incomplete gamma function Q(a, x); the chi-square survival function is Q(k/2, x/2).
double upperIncompleteGammaQ(double a, double x);

}  // namespace candela::test
