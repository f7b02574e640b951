#include "support/render_statistics.h"

#include <cmath>
#include <sstream>

#include "backends/cpu/cpu_backend.h"

namespace candela::test {

PixelStatistics renderBatches(Backend& backend, uint32_t batches, uint32_t samplesPerBatch) {
  std::vector<Image> batchMeans;
  Image previous;
  uint64_t invalid = 0;
  for (uint32_t b = 0; b < batches; ++b) {
    invalid += backend.render(samplesPerBatch).invalidSamples;
    Image running = backend.readImage();
    // The backend reports the running mean; recover this batch's own mean from the running sums.
    Image batch(running.width, running.height);
    for (size_t i = 0; i < batch.pixels.size(); ++i) {
      Vec3 sumNow = running.pixels[i] * float(b + 1);
      Vec3 sumBefore = b == 0 ? Vec3{} : previous.pixels[i] * float(b);
      batch.pixels[i] = sumNow - sumBefore;
    }
    batchMeans.push_back(std::move(batch));
    previous = std::move(running);
  }
  PixelStatistics stats;
  stats.invalidSamples = invalid;
  stats.mean = previous;
  stats.varianceOfMean = Image(previous.width, previous.height);
  for (size_t i = 0; i < previous.pixels.size(); ++i) {
    Vec3 m = previous.pixels[i];
    Vec3 squares{};
    for (const Image& batch : batchMeans) {
      Vec3 d = batch.pixels[i] - m;
      squares += d * d;
    }
    // Sample variance of the batch means, divided by the batch count: the variance of the overall mean.
    stats.varianceOfMean.pixels[i] = squares / float((batches - 1) * batches);
  }
  return stats;
}

PixelStatistics renderOnCpu(const Scene& scene, uint32_t size, uint32_t batches, uint32_t samplesPerBatch,
                            uint32_t maxDepth) {
  CpuBackend backend;
  backend.setScene(scene);
  RenderSettings settings;
  settings.width = settings.height = size;
  settings.maxDepth = maxDepth;
  settings.sampler = SamplerKind::Independent;
  backend.setSettings(settings);
  backend.setCamera(scene.camera.toCamera(1.0f));
  return renderBatches(backend, batches, samplesPerBatch);
}

ImageMean imageMean(const Image& image) {
  // Channels of one pixel share their random numbers, so the pixel (not the channel) is the independent unit.
  double sum = 0.0, sumSquares = 0.0;
  size_t n = image.pixels.size();
  for (Vec3 p : image.pixels) {
    double v = (double(p.x) + p.y + p.z) / 3.0;
    sum += v;
    sumSquares += v * v;
  }
  ImageMean m;
  m.mean = sum / double(n);
  double variance = (sumSquares - double(n) * m.mean * m.mean) / double(n - 1);
  m.standardError = std::sqrt(std::max(variance, 0.0) / double(n));
  return m;
}

ImageMean imageMean(const PixelStatistics& stats) {
  double sum = 0.0, variance = 0.0;
  const size_t n = stats.mean.pixels.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3 p = stats.mean.pixels[i], v = stats.varianceOfMean.pixels[i];
    sum += (double(p.x) + p.y + p.z) / 3.0;
    // The channels of a pixel are correlated: the mean of their standard deviations bounds their average's.
    const double sd = (std::sqrt(double(v.x)) + std::sqrt(double(v.y)) + std::sqrt(double(v.z))) / 3.0;
    variance += sd * sd;
  }
  ImageMean m;
  m.mean = sum / double(n);
  m.standardError = std::sqrt(variance) / double(n);
  return m;
}

double twoSidedNormalQuantile(double alpha) {
  // Bisection on erfc(z / sqrt 2) = alpha; monotone, so this converges to full precision.
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 200; ++i) {
    double mid = 0.5 * (lo + hi);
    if (std::erfc(mid / std::sqrt(2.0)) > alpha)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

namespace {

// Continued fraction of the regularised incomplete beta function (Numerical Recipes, betacf).
double betaContinuedFraction(double a, double b, double x) {
  constexpr double tiny = 1e-300;
  double qab = a + b, qap = a + 1.0, qam = a - 1.0, c = 1.0, d = 1.0 - qab * x / qap;
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m < 10000; ++m) {
    int m2 = 2 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < 1e-15) break;
  }
  return h;
}

double regularizedIncompleteBeta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  double front =
      std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log(1.0 - x));
  if (x < (a + 1.0) / (a + b + 2.0)) return front * betaContinuedFraction(a, b, x) / a;
  return 1.0 - front * betaContinuedFraction(b, a, 1.0 - x) / b;
}

}  // namespace

double studentTTwoSidedQuantile(double alpha, double dof) {
  // P(|T| > t) = I_{dof / (dof + t^2)}(dof / 2, 1 / 2), decreasing in t.
  double lo = 0.0, hi = 1e6;
  for (int i = 0; i < 200; ++i) {
    double mid = 0.5 * (lo + hi);
    if (regularizedIncompleteBeta(0.5 * dof, 0.5, dof / (dof + mid * mid)) > alpha)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

double sidak(double alpha, double tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

}  // namespace candela::test

namespace candela::test {

size_t countRejectedPixels(const PixelStatistics& stats, Vec3 expected, uint32_t batches, double alpha,
                           std::string& worst) {
  double channels = double(stats.mean.pixels.size()) * 3.0;
  double threshold = studentTTwoSidedQuantile(sidak(alpha, channels), double(batches - 1));
  size_t rejected = 0;
  double worstT = 0.0;
  for (uint32_t y = 0; y < stats.mean.height; ++y)
    for (uint32_t x = 0; x < stats.mean.width; ++x)
      for (int c = 0; c < 3; ++c) {
        double deviation = double(stats.mean.at(x, y)[c]) - double(expected[c]);
        double sigma = std::sqrt(double(stats.varianceOfMean.at(x, y)[c]));
        // A noiseless pixel must be exact up to float rounding.
        double t = sigma > 0.0 ? std::fabs(deviation) / sigma : (std::fabs(deviation) < 1e-5 ? 0.0 : kInf);
        if (t > threshold) ++rejected;
        if (t > worstT) {
          worstT = t;
          std::ostringstream msg;
          msg << "pixel (" << x << ", " << y << ") channel " << c << ": mean " << stats.mean.at(x, y)[c]
              << ", expected " << expected[c] << ", t = " << t << " (threshold " << threshold << ")";
          worst = msg.str();
        }
      }
  return rejected;
}

}  // namespace candela::test
