#pragma once
// The progressive film: per-pixel sums of the path samples (kernel/film_accumulation.h adds samples to them).
#include <cstddef>
#include <cstdint>

#include "core/math.h"
#include "kernel/film_channels.h"

namespace candela {

// Pointers to a film's per-pixel sums, one per channel of kernel/film_channels.h, in host or device memory; those
// of the channels with AOVs only are null while the AOVs are off. A pixel's mean is its sum over its sample count
// (`samples`, the samples accepted): samples dropped as invalid count nowhere, so they neither darken the pixel nor
// shift its AOVs. Besides the AOVs (kernel/aovs.h) and the emission (PathResult::emitted) the channels hold the
// denoisers' guides: the sums of the squared luminance of the samples' radiance, and the sum of the luminance and
// the count of the samples of odd index (the half the Sobol sampler scrambles apart from the even one).
struct FilmView {
#define CANDELA_FILM_VIEW_POINTER(Type, name, ...) Type* name = nullptr;
  CANDELA_FILM_CHANNELS(CANDELA_FILM_VIEW_POINTER)
#undef CANDELA_FILM_VIEW_POINTER
};

// A pixel's sum over `samples` samples as a mean; zero where no sample was accepted.
CANDELA_FN Vec3 filmMean(Vec3 sum, uint32_t samples) { return samples > 0 ? sum / float(samples) : Vec3{}; }
CANDELA_FN float filmMean(float sum, uint32_t samples) { return samples > 0 ? sum / float(samples) : 0.0f; }

// A pixel's mean luminance has this variance where it is not known (fewer than two samples).
constexpr float kUnknownVariance = -1.0f;

// Standard errors by which meanLuminanceVariance overstates the variance: a few samples can agree by chance, and
// the a-trous filter must not take such a pixel for a converged one (atrous_kernel.h, blendWithRaw). 5 made the
// Cornell box's 4-sample relMSE 4.6x lower than raw, against 3.0x for 0 (docs/denoising.md).
constexpr float kVarianceStandardErrors = 5.0f;

// The factor by which meanLuminanceVariance overstates the sample variance over the count: 1 +
// kVarianceStandardErrors relative standard errors of a sample variance of n normal samples (sqrt(2 / (n - 1))).
CANDELA_FN float varianceOverstatement(uint32_t samples) {
  return 1.0f + kVarianceStandardErrors * sqrtf(2.0f / (float(samples) - 1.0f));
}

// An upper estimate of the variance of a pixel's mean luminance, from the sum of its samples' radiance, the sum of
// their squared luminance and their count: the sample variance over the count, times varianceOverstatement.
// Saturated sums (kernel/film_accumulation.h) give a large finite value. For stratified samples (the Sobol
// sampler) the sample variance overstates the variance of the mean further; halvesVariance measures by how much.
CANDELA_FN float meanLuminanceVariance(Vec3 radianceSum, float luminanceSquaresSum, uint32_t samples) {
  if (samples < 2) return kUnknownVariance;
  const float n = float(samples), mean = luminance(radianceSum) / n;
  const float spread = luminanceSquaresSum / n - mean * mean;
  const float variance = (spread > 0.0f ? spread : 0.0f) / (n - 1.0f);
  const float bound = variance * varianceOverstatement(samples);
  return bound < 3.0e38f ? bound : 3.0e38f;
}

// The variance of a pixel's mean luminance from the difference of the means of its two halves of samples (even and
// odd index), which the Sobol sampler scrambles independently, so that they are independent estimates of the pixel.
// With halves of n_e and n_o samples, E[(m_e - m_o)^2] = s_e^2 + s_o^2 (their means' variances), and the pixel's
// mean has variance (n_e^2 s_e^2 + n_o^2 s_o^2) / n^2, which for s^2 proportional to 1 / n is
// E[(m_e - m_o)^2] n_e n_o / n^2: unbiased whether or not the samples are stratified, where the sample variance
// over the count assumes independent samples. One degree of freedom, so the filter only pools it over
// neighbourhoods (atrous_kernel.h, stratifiedVariance); times varianceOverstatement, on the scale of
// meanLuminanceVariance, so that the two compare. kUnknownVariance while a half has no sample.
CANDELA_FN float halvesVariance(Vec3 radianceSum, float oddLuminanceSum, uint32_t samples, uint32_t oddSamples) {
  if (oddSamples == 0 || oddSamples >= samples) return kUnknownVariance;
  const float n = float(samples), no = float(oddSamples), ne = n - no;
  const float d = (luminance(radianceSum) - oddLuminanceSum) / ne - oddLuminanceSum / no;
  const float variance = d * d * (ne / n) * (no / n) * varianceOverstatement(samples);
  return variance < 3.0e38f ? variance : 3.0e38f;
}

// The mean at pixel i of a film's sums, or of an image of means where there are no sample counts (null): the
// filters read both.
CANDELA_FN Vec3 meanAt(const Vec3* values, const uint32_t* samples, size_t i) {
  return samples ? filmMean(values[i], samples[i]) : values[i];
}
CANDELA_FN float meanAt(const float* values, const uint32_t* samples, size_t i) {
  return samples ? filmMean(values[i], samples[i]) : values[i];
}

}  // namespace candela
