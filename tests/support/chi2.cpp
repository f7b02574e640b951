#include "support/chi2.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/rng.h"

namespace candela::test {

namespace {

double simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm, double fb,
               double whole, double eps, int depth) {
  double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  double flm = f(lm), frm = f(rm);
  double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm), right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  double delta = left + right - whole;
  if (depth <= 0 || std::fabs(delta) <= 15.0 * eps) return left + right + delta / 15.0;
  return simpson(f, a, m, fa, flm, fm, left, eps / 2, depth - 1) +
         simpson(f, m, b, fm, frm, fb, right, eps / 2, depth - 1);
}

double adaptiveSimpson(const std::function<double(double)>& f, double a, double b, double eps) {
  double fa = f(a), fb = f(b), fm = f(0.5 * (a + b));
  return simpson(f, a, b, fa, fm, fb, (b - a) / 6.0 * (fa + 4.0 * fm + fb), eps, 12);
}

double adaptiveSimpson2D(const SquareDensity& f, double x0, double y0, double x1, double y1) {
  return adaptiveSimpson([&](double y) { return adaptiveSimpson([&](double x) { return f(x, y); }, x0, x1, 1e-8); }, y0,
                         y1, 1e-8);
}

// Continued fraction for Q(a, x) (Numerical Recipes, gcf), valid for x >= a + 1.
double gammaQContinuedFraction(double a, double x) {
  constexpr double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

// Series for P(a, x) (Numerical Recipes, gser), valid for x < a + 1.
double gammaPSeries(double a, double x) {
  double sum = 1.0 / a, term = sum;
  for (int n = 1; n < 10000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::fabs(term) < std::fabs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

}  // namespace

double upperIncompleteGammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  return x < a + 1.0 ? 1.0 - gammaPSeries(a, x) : gammaQContinuedFraction(a, x);
}

Chi2Result chi2TestSquare(const SquareSampler& sample, const SquareDensity& density, const Chi2Options& options) {
  const int nx = options.binsX, ny = options.binsY;
  std::vector<double> observed(size_t(nx) * ny, 0.0), expected(size_t(nx) * ny, 0.0);
  long long failures = 0;
  for (long long i = 0; i < options.sampleCount; ++i) {
    uint32_t index = uint32_t(i);
    double u1 = randomUniform(index, 0, 0, 0xC0FFEEu), u2 = randomUniform(index, 0, 1, 0xC0FFEEu),
           u3 = randomUniform(index, 0, 2, 0xC0FFEEu);
    std::optional<Vec2> p = sample(u1, u2, u3);
    if (!p) {
      ++failures;
      continue;
    }
    int bx = std::clamp(int(double(p->x) * nx), 0, nx - 1), by = std::clamp(int(double(p->y) * ny), 0, ny - 1);
    observed[size_t(by) * nx + bx] += 1.0;
  }
  Chi2Result result;
  for (int by = 0; by < ny; ++by)
    for (int bx = 0; bx < nx; ++bx) {
      double integral =
          adaptiveSimpson2D(density, double(bx) / nx, double(by) / ny, double(bx + 1) / nx, double(by + 1) / ny);
      result.integral += integral;
      expected[size_t(by) * nx + bx] = integral * double(options.sampleCount);
    }

  // Pool cells with small expectations, from the smallest up, so the statistic's distribution holds.
  std::vector<size_t> order(expected.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
  double pooledObserved = 0.0, pooledExpected = 0.0, chi2 = 0.0;
  int dof = 0;
  for (size_t i : order) {
    if (expected[i] == 0.0) {
      if (observed[i] > double(options.sampleCount) * 1e-5) {
        std::ostringstream msg;
        msg << "cell " << i << " has " << observed[i] << " samples where the density integrates to 0";
        result.message = msg.str();
        return result;
      }
      continue;
    }
    if (expected[i] < 5.0 || (pooledExpected > 0.0 && pooledExpected < 5.0)) {
      pooledObserved += observed[i];
      pooledExpected += expected[i];
      if (pooledExpected >= 5.0) {
        chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++dof;
        pooledObserved = pooledExpected = 0.0;
      }
      continue;
    }
    chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++dof;
  }
  if (pooledExpected > 0.0) {
    chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
    ++dof;
  }
  dof -= 1;
  result.pValue = dof > 0 ? upperIncompleteGammaQ(0.5 * dof, 0.5 * chi2) : 1.0;
  double alpha = 1.0 - std::pow(1.0 - options.significance, 1.0 / options.testCount);
  result.passed = result.pValue >= alpha;
  std::ostringstream msg;
  msg << "chi2 = " << chi2 << " with " << dof << " degrees of freedom, p = " << result.pValue << " (reject below "
      << alpha << "), density integral = " << result.integral << ", failed samples = " << failures;
  result.message = msg.str();
  return result;
}

Chi2Result chi2TestSphere(const DirectionSampler& sample, const DirectionPdf& pdf, const Chi2Options& options) {
  auto toSquare = [&](double u1, double u2, double u3) -> std::optional<Vec2> {
    std::optional<Vec3> d = sample(u1, u2, u3);
    if (!d) return std::nullopt;
    double theta = std::acos(std::clamp(double(d->z), -1.0, 1.0));
    double phi = std::atan2(double(d->y), double(d->x));
    if (phi < 0.0) phi += 2.0 * kPi;
    return Vec2{float(theta / kPi), float(phi / (2.0 * kPi))};
  };
  auto squareDensity = [&](double x, double y) {
    double theta = x * kPi, phi = y * 2.0 * kPi;
    double st = std::sin(theta);
    Vec3 d{float(st * std::cos(phi)), float(st * std::sin(phi)), float(std::cos(theta))};
    return pdf(d) * st * 2.0 * kPi * kPi;  // Jacobian of (x, y) -> direction
  };
  return chi2TestSquare(toSquare, squareDensity, options);
}

DiscreteChi2 chi2Discrete(const std::vector<double>& observed, const std::vector<double>& expected) {
  DiscreteChi2 r;
  for (size_t i = 0; i < expected.size(); ++i) {
    if (expected[i] < 5.0) {
      r.pooledExpected += expected[i];
      r.pooledObserved += observed[i];
      continue;
    }
    r.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++r.cells;
  }
  if (r.pooledExpected >= 5.0) {
    r.statistic += (r.pooledObserved - r.pooledExpected) * (r.pooledObserved - r.pooledExpected) / r.pooledExpected;
    ++r.cells;
  }
  r.pValue = r.cells > 1 ? upperIncompleteGammaQ(0.5 * (r.cells - 1), 0.5 * r.statistic) : 1.0;
  return r;
}

}  // namespace candela::test
