#include "scene/loaders/pbrt/pbrt_spectra.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace candela {

namespace {

// CIE 1931 colour matching functions as fitted by Wyman, Sloan and Shirley (2013, "Simple Analytic
// Approximations to the CIE XYZ Color Matching Functions"): within a percent of the tables, no tables to carry.
double lobe(double lambda, double mu, double sigmaBelow, double sigmaAbove) {
  double t = (lambda - mu) / (lambda < mu ? sigmaBelow : sigmaAbove);
  return std::exp(-0.5 * t * t);
}

Vec3 cieXyz(double lambda) {
  double x = 1.056 * lobe(lambda, 599.8, 37.9, 31.0) + 0.362 * lobe(lambda, 442.0, 16.0, 26.7) -
             0.065 * lobe(lambda, 501.1, 20.4, 26.2);
  double y = 0.821 * lobe(lambda, 568.8, 46.9, 40.5) + 0.286 * lobe(lambda, 530.9, 16.3, 31.1);
  double z = 1.217 * lobe(lambda, 437.0, 11.8, 36.0) + 0.681 * lobe(lambda, 459.0, 26.0, 13.8);
  return {float(x), float(y), float(z)};
}

Vec3 xyzToLinearSrgb(Vec3 c) {
  return {3.2406f * c.x - 1.5372f * c.y - 0.4986f * c.z, -0.9689f * c.x + 1.8758f * c.y + 0.0415f * c.z,
          0.0557f * c.x - 0.2040f * c.y + 1.0570f * c.z};
}

constexpr double kFirstWavelength = 360.0, kLastWavelength = 830.0;

Vec3 clampNegative(Vec3 c) { return {std::max(c.x, 0.0f), std::max(c.y, 0.0f), std::max(c.z, 0.0f)}; }

struct MetalConstants {
  const char* name;
  Vec3 eta, k;
};

// Complex indices of refraction of pbrt-v4's named metals, integrated against the sRGB primaries.
constexpr MetalConstants kMetals[] = {
    {"Ag", {0.155f, 0.117f, 0.138f}, {4.828f, 3.122f, 2.147f}},
    {"Al", {1.657f, 0.880f, 0.521f}, {9.224f, 6.270f, 4.837f}},
    {"Au", {0.143f, 0.375f, 1.442f}, {3.983f, 2.386f, 1.603f}},
    {"Cu", {0.200f, 0.924f, 1.102f}, {3.913f, 2.453f, 2.142f}},
    {"CuZn", {0.444f, 0.527f, 1.094f}, {3.695f, 2.765f, 1.829f}},
    {"MgO", {1.732f, 1.736f, 1.750f}, {0.0f, 0.0f, 0.0f}},
    {"TiO2", {2.745f, 2.874f, 3.125f}, {0.0f, 0.0f, 0.0f}},
};

constexpr std::pair<const char*, float> kGlasses[] = {
    {"glass-BK7", 1.5168f}, {"glass-BAF10", 1.6700f}, {"glass-FK51A", 1.4866f}, {"glass-LASF9", 1.8503f},
    {"glass-F5", 1.6034f},  {"glass-F10", 1.7283f},   {"glass-F11", 1.7847f},
};

// Correlated colour temperatures of the CIE standard illuminants, which stand in for their spectra.
constexpr std::pair<const char*, float> kIlluminantTemperatures[] = {
    {"stdillum-A", 2856.0f},   {"stdillum-D50", 5003.0f}, {"stdillum-F1", 6430.0f}, {"stdillum-F2", 4230.0f},
    {"stdillum-F3", 3450.0f},  {"stdillum-F4", 2940.0f},  {"stdillum-F5", 6350.0f}, {"stdillum-F6", 4150.0f},
    {"stdillum-F7", 6500.0f},  {"stdillum-F8", 5000.0f},  {"stdillum-F9", 4150.0f}, {"stdillum-F10", 5000.0f},
    {"stdillum-F11", 4000.0f}, {"stdillum-F12", 3000.0f},
};

}  // namespace

Vec3 blackbodyRgb(float kelvin) {
  if (!(kelvin > 0.0f)) return {0, 0, 0};
  constexpr double c2 = 1.4387769e7;  // second radiation constant in nm K
  Vec3 xyz{0, 0, 0};
  for (double lambda = kFirstWavelength; lambda <= kLastWavelength; lambda += 1.0) {
    double planck = 1.0 / (std::pow(lambda * 1e-3, 5.0) * (std::exp(c2 / (lambda * double(kelvin))) - 1.0));
    if (!std::isfinite(planck)) continue;
    xyz += cieXyz(lambda) * float(planck);
  }
  if (!(xyz.y > 0.0f) || !isFinite(xyz)) return {0, 0, 0};
  return clampNegative(xyzToLinearSrgb(xyz / xyz.y));
}

Vec3 peakNormalisedBlackbodyRgb(double kelvin) { return peakNormalisedBlackbodyRgbs({kelvin})[0]; }

std::vector<Vec3> peakNormalisedBlackbodyRgbs(const std::vector<double>& kelvins) {
  std::vector<double> wavelengths;
  std::vector<Vec3> matches;
  double ySum = 0.0;
  for (double lambda = kFirstWavelength; lambda <= kLastWavelength; lambda += 1.0) {
    wavelengths.push_back(lambda);
    matches.push_back(cieXyz(lambda));
    ySum += matches.back().y;
  }
  constexpr double c2 = 1.4387769e7;            // second radiation constant in nm K
  constexpr double wien = 2.8977721e6;          // Wien's displacement constant in nm K
  const double atPeak = std::expm1(c2 / wien);  // Planck's denominator there, less the wavelength's power
  std::vector<Vec3> colours;
  colours.reserve(kelvins.size());
  for (double kelvin : kelvins) {
    if (!(kelvin > 0.0) || !std::isfinite(kelvin)) {
      colours.push_back({0, 0, 0});
      continue;
    }
    const double peak = wien / kelvin;  // the peak wavelength
    Vec3 xyz{0, 0, 0};
    for (size_t i = 0; i < wavelengths.size(); ++i) {
      const double r = peak / wavelengths[i];
      const double ratio = r * r * r * r * r * atPeak / std::expm1(c2 / (wavelengths[i] * kelvin));
      if (std::isfinite(ratio)) xyz += matches[i] * float(ratio);
    }
    colours.push_back(clampNegative(xyzToLinearSrgb(xyz / float(ySum))));
  }
  return colours;
}

Vec3 sampledSpectrumRgb(const std::vector<double>& pairs) {
  std::vector<std::pair<double, double>> samples;
  for (size_t i = 0; i + 1 < pairs.size(); i += 2)
    if (std::isfinite(pairs[i]) && std::isfinite(pairs[i + 1])) samples.emplace_back(pairs[i], pairs[i + 1]);
  if (samples.empty()) return {0, 0, 0};
  std::sort(samples.begin(), samples.end());
  auto valueAt = [&](double lambda) {
    if (lambda <= samples.front().first) return samples.front().second;
    if (lambda >= samples.back().first) return samples.back().second;
    auto upper = std::lower_bound(samples.begin(), samples.end(), std::make_pair(lambda, -HUGE_VAL));
    auto lower = upper - 1;
    double span = upper->first - lower->first;
    double t = span > 0 ? (lambda - lower->first) / span : 0.0;
    return lower->second + t * (upper->second - lower->second);
  };
  Vec3 weighted{0, 0, 0}, total{0, 0, 0};
  for (double lambda = kFirstWavelength; lambda <= kLastWavelength; lambda += 1.0) {
    Vec3 rgbMatch = xyzToLinearSrgb(cieXyz(lambda));
    weighted += rgbMatch * float(valueAt(lambda));
    total += rgbMatch;
  }
  return clampNegative({weighted.x / total.x, weighted.y / total.y, weighted.z / total.z});
}

std::optional<Vec3> namedSpectrumRgb(const std::string& name) {
  if (name == "stdillum-D65") return Vec3{1, 1, 1};  // sRGB's white point
  for (const auto& [illuminant, kelvin] : kIlluminantTemperatures)
    if (name == illuminant) return blackbodyRgb(kelvin);
  for (const auto& [glass, ior] : kGlasses)
    if (name == glass) return Vec3{ior, ior, ior};
  for (const MetalConstants& metal : kMetals) {
    std::string prefix = std::string("metal-") + metal.name;
    if (name == prefix + "-eta") return metal.eta;
    if (name == prefix + "-k") return metal.k;
  }
  return std::nullopt;
}

bool isNamedIlluminant(const std::string& name) { return name.rfind("stdillum-", 0) == 0; }

Vec3 conductorReflectance(Vec3 eta, Vec3 k) {
  auto channel = [](float n, float kk) {
    float num = (n - 1) * (n - 1) + kk * kk, den = (n + 1) * (n + 1) + kk * kk;
    return den > 0.0f ? clampf(num / den, 0.0f, 1.0f) : 1.0f;
  };
  return {channel(eta.x, k.x), channel(eta.y, k.y), channel(eta.z, k.z)};
}

}  // namespace candela
