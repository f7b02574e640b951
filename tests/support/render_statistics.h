#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "image/image.h"

namespace candela::test {

// Per-pixel mean and the variance of that mean, estimated from independent batches of samples.
struct PixelStatistics {
  Image mean;
  Image varianceOfMean;
  uint64_t invalidSamples = 0;
};

// Renders `batches` batches of `samplesPerBatch` samples each on a backend whose scene, camera and settings
// are set, and returns per-pixel statistics over the batch means.
PixelStatistics renderBatches(Backend& backend, uint32_t batches, uint32_t samplesPerBatch);

// renderBatches of a loaded scene through its own camera on the CPU backend, at size x size pixels, with the
// independent sampler and paths of at most `maxDepth` bounces.
PixelStatistics renderOnCpu(const Scene& scene, uint32_t size, uint32_t batches, uint32_t samplesPerBatch,
                            uint32_t maxDepth = RenderSettings{}.maxDepth);

// Mean over all pixels and channels, and its standard error assuming independent pixels.
struct ImageMean {
  double mean = 0.0;
  double standardError = 0.0;
};
ImageMean imageMean(const Image& image);
// Mean over all pixels and channels of a batched render, with its standard error from the pixels' own
// variances of the mean (pixels independent). Unlike imageMean(stats.mean), right also where pixels differ
// in expectation.
ImageMean imageMean(const PixelStatistics& stats);

// The z value beyond which a two-sided normal test rejects at `alpha` (inverse of erfc).
double twoSidedNormalQuantile(double alpha);

// The t value beyond which a two-sided Student-t test with `dof` degrees of freedom rejects at `alpha`.
double studentTTwoSidedQuantile(double alpha, double dof);

// Sidak-corrected per-test significance for `tests` tests at overall significance `alpha`.
double sidak(double alpha, double tests);

// Per-pixel Student-t test of every channel's mean against a known value, Sidak-corrected over all pixel
// channels at overall significance `alpha`. Returns the number of rejected pixel channels; `worst` receives a
// description of the largest deviation.
size_t countRejectedPixels(const PixelStatistics& stats, Vec3 expected, uint32_t batches, double alpha,
                           std::string& worst);

}  // namespace candela::test
