#include "image_agreement.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace candela::test {

AgreementReport compareIndependentRenders(const std::vector<double>& a, const std::vector<double>& b, int width,
                                          int height, int channels, int blockSize, double alpha) {
  if (a.size() != b.size() || a.size() != size_t(width) * height * channels)
    throw std::invalid_argument("images of different sizes");
  AgreementReport report;
  const int blocksX = (width + blockSize - 1) / blockSize, blocksY = (height + blockSize - 1) / blockSize;
  report.tests = blocksX * blocksY * channels;
  const double perTest = 1.0 - std::pow(1.0 - alpha, 1.0 / report.tests);
  report.threshold = std::sqrt(2.0 * std::log(2.0 / perTest));
  for (int by = 0; by < blocksY; ++by)
    for (int bx = 0; bx < blocksX; ++bx)
      for (int c = 0; c < channels; ++c) {
        double sum = 0.0, squares = 0.0;
        for (int y = by * blockSize; y < std::min(height, (by + 1) * blockSize); ++y)
          for (int x = bx * blockSize; x < std::min(width, (bx + 1) * blockSize); ++x) {
            size_t i = (size_t(y) * width + x) * channels + c;
            double d = a[i] - b[i];
            sum += d;
            squares += d * d;
          }
        double statistic = squares > 0.0 ? std::fabs(sum) / std::sqrt(squares) : 0.0;
        if (statistic > report.worstStatistic) {
          report.worstStatistic = statistic;
          report.worstBlock =
              "block (" + std::to_string(bx) + ", " + std::to_string(by) + ") channel " + std::to_string(c);
        }
      }
  report.agree = report.worstStatistic < report.threshold;
  return report;
}

}  // namespace candela::test
