#include "render_comparison.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace candela::test {

BlockComparison compareBlocks(const PixelStatistics& a, const PixelStatistics& b, uint32_t blockSize, uint32_t batches,
                              double alpha) {
  const uint32_t width = a.mean.width, height = a.mean.height;
  if (b.mean.width != width || b.mean.height != height || width % blockSize != 0 || height % blockSize != 0)
    throw std::invalid_argument("compareBlocks needs two renders of one size, a multiple of the block size");
  BlockComparison result;
  result.tests = size_t(width / blockSize) * (height / blockSize) * 3;
  const double threshold = studentTTwoSidedQuantile(sidak(alpha, double(result.tests)), double(batches - 1));
  const double pixels = double(blockSize) * blockSize;
  double worstT = -1.0;
  for (uint32_t by = 0; by < height; by += blockSize)
    for (uint32_t bx = 0; bx < width; bx += blockSize)
      for (int c = 0; c < 3; ++c) {
        double meanA = 0, meanB = 0, varA = 0, varB = 0;
        for (uint32_t y = by; y < by + blockSize; ++y)
          for (uint32_t x = bx; x < bx + blockSize; ++x) {
            meanA += a.mean.at(x, y)[c];
            meanB += b.mean.at(x, y)[c];
            varA += a.varianceOfMean.at(x, y)[c];
            varB += b.varianceOfMean.at(x, y)[c];
          }
        meanA /= pixels;
        meanB /= pixels;
        const double sigma = std::sqrt((varA + varB) / (pixels * pixels));
        const double deviation = std::fabs(meanA - meanB);
        // Noiseless blocks (no light reaches them) must agree up to float rounding.
        const double t = sigma > 0.0 ? deviation / sigma : (deviation < 1e-6 ? 0.0 : INFINITY);
        if (t > threshold) ++result.rejected;
        if (t > worstT) {
          worstT = t;
          std::ostringstream message;
          message << "block at (" << bx << ", " << by << ") channel " << c << ": " << meanA << " vs " << meanB
                  << ", t = " << t << " (threshold " << threshold << ")";
          result.worst = message.str();
        }
      }
  return result;
}

void expectRendersAgree(const PixelStatistics& a, const PixelStatistics& b, uint32_t blockSize, uint32_t batches,
                        double alpha) {
  BlockComparison blocks = compareBlocks(a, b, blockSize, batches, alpha);
  EXPECT_EQ(blocks.rejected, 0u) << blocks.rejected << " of " << blocks.tests << " rejected; worst " << blocks.worst;
  Image difference(a.mean.width, a.mean.height);
  for (size_t i = 0; i < difference.pixels.size(); ++i) difference.pixels[i] = a.mean.pixels[i] - b.mean.pixels[i];
  ImageMean d = imageMean(difference);
  EXPECT_LT(std::fabs(d.mean), twoSidedNormalQuantile(alpha) * d.standardError)
      << "mean difference " << d.mean << " +- " << d.standardError;
}

}  // namespace candela::test
