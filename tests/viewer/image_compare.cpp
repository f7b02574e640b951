// image_compare: compares two 8-bit images (.png) for scripts that check the viewer on a GPU machine.
//   image_compare exact A.png B.png [--crop W H] [--tolerance STEPS]
//     the largest per-channel difference in 8-bit steps; exit 0 when it is at most STEPS (default 0)
//   image_compare agree A.png B.png [--crop W H] [--block N] [--alpha A]
//     compareIndependentRenders (image_agreement.h) on two renders of one scene with different seeds; exit 0 when
//     they agree at family-wise false-rejection rate A
// --crop W H compares the top-left W x H pixels of both (a window capture holds the image left of the panel).
// Exit 2 on bad arguments or unreadable files, with one line saying why.
#include <stb/stb_image.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "image_agreement.h"

namespace {

struct Rgb8 {
  int width = 0, height = 0;
  std::vector<double> values;  // width * height * 3, row by row from the top
};

Rgb8 readCropped(const std::string& path, int cropWidth, int cropHeight) {
  int width = 0, height = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &width, &height, &channels, 3);
  if (!data) throw std::runtime_error("cannot read '" + path + "': " + stbi_failure_reason());
  Rgb8 image;
  image.width = cropWidth > 0 ? cropWidth : width;
  image.height = cropHeight > 0 ? cropHeight : height;
  if (image.width > width || image.height > height) {
    stbi_image_free(data);
    throw std::runtime_error("'" + path + "' is " + std::to_string(width) + " x " + std::to_string(height) +
                             ", smaller than the crop");
  }
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width * 3; ++x) image.values.push_back(data[(size_t(y) * width) * 3 + size_t(x)]);
  stbi_image_free(data);
  return image;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Compares two 8-bit images"};
  app.require_subcommand(1);
  std::string first, second;
  std::vector<int> crop;
  double tolerance = 0.0, alpha = 0.01;
  int block = 8;
  auto common = [&](CLI::App* cmd) {
    cmd->add_option("first", first, "An image (.png)")->required();
    cmd->add_option("second", second, "Another image of at least the same size")->required();
    cmd->add_option("--crop", crop, "Compare the top-left W x H pixels")->expected(2);
  };
  CLI::App* exact = app.add_subcommand("exact", "Largest per-channel difference in 8-bit steps");
  common(exact);
  exact->add_option("--tolerance", tolerance, "Largest difference that passes")->capture_default_str();
  CLI::App* agree = app.add_subcommand("agree", "Do two renders with different seeds show the same picture?");
  common(agree);
  agree->add_option("--block", block, "Block size in pixels")->check(CLI::Range(1, 1024))->capture_default_str();
  agree->add_option("--alpha", alpha, "Family-wise false-rejection rate")
      ->check(CLI::Range(1e-12, 0.5))
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  try {
    const int cropWidth = crop.empty() ? 0 : crop[0], cropHeight = crop.empty() ? 0 : crop[1];
    const Rgb8 a = readCropped(first, cropWidth, cropHeight), b = readCropped(second, cropWidth, cropHeight);
    if (a.width != b.width || a.height != b.height)
      throw std::runtime_error("the images differ in size: " + std::to_string(a.width) + " x " +
                               std::to_string(a.height) + " and " + std::to_string(b.width) + " x " +
                               std::to_string(b.height));
    if (*exact) {
      double worst = 0.0;
      size_t differing = 0;
      for (size_t i = 0; i < a.values.size(); i += 3) {
        double pixelWorst = 0.0;
        for (size_t c = 0; c < 3; ++c) pixelWorst = std::max(pixelWorst, std::fabs(a.values[i + c] - b.values[i + c]));
        worst = std::max(worst, pixelWorst);
        differing += pixelWorst > 0.0 ? 1 : 0;
      }
      std::printf("exact: %d x %d pixels, %zu differ, largest difference %.0f steps (tolerance %.0f)\n", a.width,
                  a.height, differing, worst, tolerance);
      return worst <= tolerance ? 0 : 1;
    }
    const candela::test::AgreementReport report =
        candela::test::compareIndependentRenders(a.values, b.values, a.width, a.height, 3, block, alpha);
    std::printf("agree: %s; worst statistic %.3f at %s, threshold %.3f over %d tests (alpha %g)\n",
                report.agree ? "yes" : "no", report.worstStatistic, report.worstBlock.c_str(), report.threshold,
                report.tests, alpha);
    return report.agree ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "image_compare: %s\n", e.what());
    return 2;
  }
}
