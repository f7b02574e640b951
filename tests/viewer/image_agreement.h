#pragma once
#include <string>
#include <vector>

namespace candela::test {

// Do two renders of the same scene with different seeds show the same picture?
//
// For independent, identically distributed images A and B, each pixel difference d = A - B is symmetric about
// zero, whatever the distribution of the renderer's noise (fireflies included) and whatever per-pixel mapping
// (tone mapping, 8-bit rounding) was applied to both. Given the magnitudes |d|, the signs are then fair coin
// flips, so over one block of pixels and one channel S = sum(d) / sqrt(sum(d^2)) satisfies
// P(|S| >= t) <= 2 exp(-t^2 / 2) (Hoeffding). The images agree when no block and channel exceeds the threshold
// that makes the family-wise false-rejection rate `alpha` (Sidak over all blocks and channels).
struct AgreementReport {
  bool agree = true;
  double worstStatistic = 0.0;
  double threshold = 0.0;
  int tests = 0;
  std::string worstBlock;  // "block (x, y) channel c", for messages
};

// `a` and `b` hold width * height * channels values, row by row.
AgreementReport compareIndependentRenders(const std::vector<double>& a, const std::vector<double>& b, int width,
                                          int height, int channels, int blockSize, double alpha);

}  // namespace candela::test
