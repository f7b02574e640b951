#pragma once
// Agreement of two independent renders of one scene, each summarised by per-pixel batch statistics.
#include <cstdint>
#include <string>

#include "support/render_statistics.h"

namespace candela::test {

struct BlockComparison {
  size_t tests = 0;
  size_t rejected = 0;
  std::string worst;  // the largest deviation found
};

// Two-sample t-test per square block of `blockSize` x `blockSize` pixels and per channel, Sidak-corrected over
// all blocks and channels at overall significance `alpha`.
//
// Why blocks: a single pixel's batch means (a few samples each) are skewed near the light, so a per-pixel
// t-test is miscalibrated; a block's batch mean averages blockSize^2 pixels and is close to normal. Pixels
// draw independent random numbers, so the variance of a block's mean is the sum of its pixels' variances over
// the square of the pixel count. The t quantile uses batches - 1 degrees of freedom, the fewest that either
// variance estimate has, which keeps the test conservative.
BlockComparison compareBlocks(const PixelStatistics& a, const PixelStatistics& b, uint32_t blockSize, uint32_t batches,
                              double alpha);

// Expects independent renders (different seeds) of one scene to agree: no block rejected by compareBlocks,
// and the mean per-pixel difference within a two-sided z-test at `alpha` (pixels are independent).
void expectRendersAgree(const PixelStatistics& a, const PixelStatistics& b, uint32_t blockSize, uint32_t batches,
                        double alpha);

}  // namespace candela::test
